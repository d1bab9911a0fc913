#!/usr/bin/env bash
# Regenerate the meshes committed in Data/ (deterministic: same bytes on every run).
# Usage: Data/generators/generate_all.sh [PVPYTHON]   (default: pvpython on PATH)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
data="$(dirname "$here")"
pvpython="${1:-pvpython}"
for case in rotating_circle rotating_rectangle twisted_bar sphere_in_box two_circles; do
  "$pvpython" "$here/$case.py" "$data/$case.vtu"
done
"$pvpython" "$here/thin_slab.py" "$data/thin_slab.vtu" --size-min 0.08 --size-max 2 --dist-max 5
"$pvpython" "$here/pitching_airfoil.py" "$data/pitching_airfoil.vtu"
