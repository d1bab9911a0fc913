#!/usr/bin/env bash
# Installs what is missing, builds, and runs the whole test suite with ctest: the main build
# (core, VTK filter, plugin, pvpython and GUI tests), then the core again under AddressSanitizer
# and UndefinedBehaviorSanitizer, then the core built by Clang with the portable scalar code
# (the same bits as the main build).
set -euo pipefail
SOURCE_DIR="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD_DIR="${BUILD_DIR:-$SOURCE_DIR/build}"
bash "$SOURCE_DIR/scripts/build.sh"
ctest --test-dir "$BUILD_DIR" --output-on-failure -j 2
bash "$SOURCE_DIR/scripts/run-sanitizer-tests.sh"
bash "$SOURCE_DIR/scripts/run-portability-tests.sh"
