#!/usr/bin/env bash
# Installs what is missing, configures (once) and builds the project in Release mode.
#   BUILD_DIR  build folder (default: build/ in the source tree)
# Idempotent: with everything in place it only runs an incremental build.
set -euo pipefail
SOURCE_DIR="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD_DIR="${BUILD_DIR:-$SOURCE_DIR/build}"

bash "$SOURCE_DIR/scripts/install-deps.sh"

if [ ! -f "$BUILD_DIR/CMakeCache.txt" ]; then
  cmake -S "$SOURCE_DIR" -B "$BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE=Release
fi
cmake --build "$BUILD_DIR" -j 2
