#!/usr/bin/env bash
# Builds the VTK-free core and its tests with Clang and the portable scalar fallback of
# dgmf/Simd.h forced on (build-portable/), runs them, and checks that this build computes the same
# bits as the main build (GCC, vector types): dgmf-core-fingerprint hashes every core result.
# Called by scripts/run-tests.sh after the main build.
set -euo pipefail
SOURCE_DIR="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
MAIN_BUILD_DIR="${BUILD_DIR:-$SOURCE_DIR/build}"
BUILD_DIR="${PORTABLE_BUILD_DIR:-$SOURCE_DIR/build-portable}"
REFERENCE="$MAIN_BUILD_DIR/bin/dgmf-core-fingerprint"
if [ ! -x "$REFERENCE" ]; then
  echo "run-portability-tests: $REFERENCE is missing: build the main build first" >&2
  exit 1
fi
if [ ! -f "$BUILD_DIR/CMakeCache.txt" ]; then
  CC=clang CXX=clang++ cmake -S "$SOURCE_DIR" -B "$BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE=Release \
    -DDGMF_CORE_ONLY=ON -DDGMF_FORCE_SCALAR_SIMD=ON -DDGMF_REFERENCE_FINGERPRINT="$REFERENCE" >/dev/null
fi
cmake --build "$BUILD_DIR" -j 2
ctest --test-dir "$BUILD_DIR" --output-on-failure -j 2
