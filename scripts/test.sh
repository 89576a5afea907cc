#!/usr/bin/env bash
# Builds Catena with warnings as errors, runs every test, proves that an installed Catena can be
# used by another CMake project, then builds and runs the tests again under ASan + UBSan, and
# fuzzes the input paths for about three minutes (scripts/fuzz.sh).
# Assumes scripts/setup.sh has run. Run from anywhere; works in the repository root.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc 2>/dev/null || echo 2)

echo "== formatting (clang-format, .clang-format)" >&2
git ls-files -z '*.cpp' '*.hpp' '*.ipp' '*.h' | xargs -0 clang-format --dry-run --Werror

echo "== build (warnings as errors) and test" >&2
cmake --preset ci >/dev/null
cmake --build --preset ci -j "$jobs"
ctest --preset ci -j "$jobs"

echo "== install and build a consumer project with find_package(catena)" >&2
prefix=$(mktemp -d)
trap 'rm -rf "$prefix"' EXIT
cmake --install build/ci --prefix "$prefix/install" >/dev/null
cmake -S tests/consumer -B "$prefix/build" -G Ninja -DCMAKE_PREFIX_PATH="$prefix/install" >/dev/null
cmake --build "$prefix/build" >/dev/null
"$prefix/build/consumer"

echo "== build and test under AddressSanitizer + UndefinedBehaviorSanitizer" >&2
cmake --preset asan >/dev/null
cmake --build --preset asan -j "$jobs"
ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 ctest --preset asan -j "$jobs" --label-exclude 'browser|python|slow'

echo "== fuzz: libFuzzer harnesses under ASan + UBSan for a bounded time (tests/fuzz)" >&2
cmake --preset fuzz >/dev/null
cmake --build --preset fuzz -j "$jobs"
bash scripts/fuzz.sh 150  # runs the seed corpus and the saved findings first
