#!/usr/bin/env bash
# Installs every Debian package Catena needs to build, test and benchmark.
# Idempotent: packages already present are skipped by apt; safe to run again.
# Runs as root on a fresh Debian 12 machine (uses sudo when not root and sudo exists).
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config git
  libgtest-dev libgmock-dev libbenchmark-dev
  libudunits2-dev udunits-bin
  libcli11-dev nlohmann-json3-dev libfmt-dev libboost-dev
  libcairo2-dev libdxflib-dev
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ "${#missing[@]}" -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages already installed" >&2
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null 2>&1 && SUDO="sudo" || {
    echo "setup: run as root (missing: ${missing[*]})" >&2
    exit 1
  }
fi

echo "setup: installing ${missing[*]}" >&2
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${packages[@]}" >/dev/null
echo "setup: done" >&2
