#!/usr/bin/env bash
# Installs every Debian package Catena needs to build, test and benchmark.
# Idempotent: packages already present are skipped by apt; safe to run again.
# Runs as root on a fresh Debian 12 machine (uses sudo when not root and sudo exists).
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config git clang-format
  clang libclang-rt-14-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  libudunits2-dev udunits-bin
  libcli11-dev nlohmann-json3-dev libfmt-dev libboost-dev
  libcairo2-dev libdxflib-dev libtomlplusplus-dev
  chromium
  calculix-ccx
  pybind11-dev python3-dev python3-pytest python3-numpy python3-pandas python3-distributed
  python3-matplotlib
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null 2>&1 && SUDO="sudo" || {
    [ "${#missing[@]}" -eq 0 ] || {
      echo "setup: run as root (missing: ${missing[*]})" >&2
      exit 1
    }
  }
fi

if [ "${#missing[@]}" -eq 0 ]; then
  echo "setup: all ${#packages[@]} Debian packages already installed" >&2
else
  echo "setup: installing ${missing[*]}" >&2
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq --no-install-recommends "${packages[@]}" >/dev/null
  echo "setup: Debian packages done" >&2
fi

# The report's charting library (embedded into every report at build time) and the
# headless-browser test driver come from the npm registry, with the machine's own Node.js and
# npm, pinned by web/package-lock.json. Skipped when web/node_modules matches the lock file.
cd "$(dirname "$0")/../web"
command -v npm >/dev/null 2>&1 || {
  echo "setup: npm (with Node.js) is needed for the report's chart library; install Node.js" >&2
  exit 1
}
if [ -f node_modules/.package-lock.json ] && cmp -s package-lock.json .installed-lock.json; then
  echo "setup: npm packages already installed" >&2
else
  npm ci --no-audit --no-fund --loglevel=error >&2
  cp package-lock.json .installed-lock.json
  echo "setup: npm packages done" >&2
fi
