#!/usr/bin/env bash
# Builds the VTK-free core and its tests with AddressSanitizer and UndefinedBehaviorSanitizer
# (no VTK, no ParaView) in build-sanitize/, and runs them. Called by scripts/run-tests.sh.
set -euo pipefail
SOURCE_DIR="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD_DIR="${SANITIZE_BUILD_DIR:-$SOURCE_DIR/build-sanitize}"
if [ ! -f "$BUILD_DIR/CMakeCache.txt" ]; then
  cmake -S "$SOURCE_DIR" -B "$BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DDGMF_CORE_ONLY=ON -DDGMF_ENABLE_SANITIZERS=ON >/dev/null
fi
cmake --build "$BUILD_DIR" -j 2
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
ctest --test-dir "$BUILD_DIR" --output-on-failure -j 2
