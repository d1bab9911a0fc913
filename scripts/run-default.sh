#!/usr/bin/env bash
# The main job on the default case: the rotating circle of Data/ (radius 1 in a square of side
# 10), rotated by 90 degrees with DGMF (u1, DGMF2). Writes build/rotating_circle_90.vtu and prints
# the quality summary (mean and minimum SizeSkew, inverted cells).
set -euo pipefail
SOURCE_DIR="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD_DIR="${BUILD_DIR:-$SOURCE_DIR/build}"
bash "$SOURCE_DIR/scripts/build.sh" >/dev/null
"$BUILD_DIR/bin/dgmf-deform" "$SOURCE_DIR/Data/rotating_circle.vtu" \
  "$BUILD_DIR/rotating_circle_90.vtu" --rotate 0 0 90
