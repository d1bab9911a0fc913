#!/usr/bin/env bash
# Builds the meshes of OpenFOAM's wingMotion tutorials (Debian's openfoam-examples) with
# OpenFOAM's own tools, as the tutorials' Allrun scripts do, into the directory $1 (the build
# tree), once: later runs find them there (the marker file .complete) and return at once.
#
#   $1/wingMotion_snappyHexMesh   blockMesh + snappyHexMesh (3D, 196,018 points, symmetry planes)
#   $1/wingMotion2D_simpleFoam    extrudeMesh + createPatch (one cell thick, empty front/back),
#                                 with 0/ from 0.orig, ready for simpleFoam
#   $1/baseline.<case>.checkMesh  checkMesh on the undeformed meshes (run on copies)
#
# The dictionaries are the tutorials' own: snappyHexMesh takes about 20 s on 2 cores.
set -euo pipefail
OUT="$1"
TUTORIAL=/usr/share/doc/openfoam-examples/examples/incompressible/pimpleFoam/RAS/wingMotion
export WM_PROJECT_DIR="${WM_PROJECT_DIR:-/usr/share/openfoam}"
if [ -f "$OUT/.complete" ]; then
  echo "tutorial meshes already built in $OUT"
  exit 0
fi
if [ ! -d "$TUTORIAL" ] || ! command -v snappyHexMesh > /dev/null; then
  echo "OpenFOAM or its tutorials are missing: apt-get install openfoam openfoam-examples" >&2
  exit 1
fi
rm -rf "$OUT"
mkdir -p "$OUT"
cd "$OUT"
cp -r "$TUTORIAL/wingMotion_snappyHexMesh" "$TUTORIAL/wingMotion2D_simpleFoam" .
chmod -R u+w .
find . -name '*.gz' -exec gunzip {} +

(cd wingMotion_snappyHexMesh && blockMesh > log.blockMesh && snappyHexMesh -overwrite > log.snappyHexMesh)
(cd wingMotion2D_simpleFoam && extrudeMesh > log.extrudeMesh && createPatch -overwrite > log.createPatch \
  && cp -r 0.orig 0)
for c in wingMotion_snappyHexMesh wingMotion2D_simpleFoam; do
  rm -rf "$c/constant/polyMesh/sets" "$c"/log.*
  touch "$c/case.foam"
  # checkMesh writes sets into the case it checks: check a copy.
  rm -rf check.tmp && cp -r "$c" check.tmp
  (cd check.tmp && checkMesh -constant > "../baseline.$c.checkMesh" 2>&1)
  rm -rf check.tmp
done
touch .complete
echo "tutorial meshes built in $OUT"
