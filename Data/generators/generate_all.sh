#!/usr/bin/env bash
# Regenerate the four meshes committed in Data/ (deterministic: same bytes on every run).
# Usage: Data/generators/generate_all.sh [PVPYTHON]   (default: pvpython on PATH)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
data="$(dirname "$here")"
pvpython="${1:-pvpython}"
for case in rotating_circle rotating_rectangle twisted_bar sphere_in_box two_circles; do
  "$pvpython" "$here/$case.py" "$data/$case.vtu"
done
