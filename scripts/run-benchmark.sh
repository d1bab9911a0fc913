#!/usr/bin/env bash
# The paper's Table 3 on this machine: builds (Release), runs Benchmarks/dgmf-benchmark on the
# four mesh sizes with DGM, DGMF, DGRBF (and IDW on the two smallest) on 1 and 2 threads, and
# writes Documentation/benchmark/benchmark.csv and Documentation/benchmark/README.md; then the
# large-motion options on the thin slab (Documentation/benchmark/large_motion.md).
# Takes about 20 minutes on 2 cores; run it on a quiet machine.
#   SIZES=0,1 METHODS=dgmf bash scripts/run-benchmark.sh   # a subset
set -euo pipefail
SOURCE_DIR="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD_DIR="${BUILD_DIR:-$SOURCE_DIR/build}"
OUT="$SOURCE_DIR/Documentation/benchmark"
bash "$SOURCE_DIR/scripts/build.sh" >/dev/null
mkdir -p "$OUT"
"$BUILD_DIR/bin/dgmf-benchmark" --sizes "${SIZES:-0,1,2,3}" --methods "${METHODS:-dgm,dgmf,dgrbf,idw}" \
  --threads 1,2 --repeats "${REPEATS:-3}" --idw-max-size 1 --csv "$OUT/benchmark.csv" 2> >(grep -v WARN >&2)
{
  echo "date: $(date -u +%Y-%m-%d)"
  lscpu | grep -E "Model name|^CPU\(s\)|MHz|L2 cache|L3 cache"
  grep MemTotal /proc/meminfo
  echo "compiler: $(c++ --version | head -1)"
  echo "VTK (ParaView): $(pvpython --version 2>/dev/null | head -1)"
  # The cost of new memory, which varies from day to day on virtual machines (speed.md).
  /usr/bin/python3 "$SOURCE_DIR/scripts/page-fault-probe.py"
  echo "transparent huge pages: $(cat /sys/kernel/mm/transparent_hugepage/enabled 2>/dev/null)"
} > "$OUT/machine.txt"
# Node numbering (issue 18): the largest mesh, DGMF, numbered three ways.
"$BUILD_DIR/bin/dgmf-benchmark" --sizes "${NUMBERING_SIZES:-3}" --methods dgmf --threads 1,2 \
  --repeats "${REPEATS:-3}" --numberings layered,hilbert,random --csv "$OUT/numbering.csv" \
  2> >(grep -v WARN >&2)
# Composite input and the whole command (issue 18): the two largest meshes, DGMF.
"$BUILD_DIR/bin/dgmf-benchmark" --sizes "${COMPOSITE_SIZES:-2,3}" --methods dgmf --threads 1,2 \
  --repeats "${REPEATS:-3}" --inputs grid,multiblock --quality 0 --csv "$OUT/composite.csv" \
  --command "$BUILD_DIR/bin/dgmf-deform" --command-csv "$OUT/command.csv" 2> >(grep -v WARN >&2)
# Motion in time (issue 19): frames per second of a periodic motion on the 826,080-node mesh.
"$BUILD_DIR/bin/dgmf-benchmark" --sizes 2 --methods dgmf --threads 1,2 --repeats 1 --quality 0 \
  --frames 51 --frames-csv "$OUT/motion.csv" --csv /dev/null 2> >(grep -v WARN >&2)
# A real mesh (issue 18): the wing-body of Reproduction/, when scripts/reproduce.sh cached it.
WING="${XDG_CACHE_HOME:-$HOME/.cache}/dgmf/wing_body.vtu"
if [ -f "$WING" ]; then
  "$BUILD_DIR/bin/dgmf-benchmark" --mesh "$WING" --threads 1,2 --repeats "${REPEATS:-3}" \
    --mesh-csv "$OUT/wing_body.csv" --csv /dev/null 2> >(grep -v WARN >&2)
fi
/usr/bin/python3 "$SOURCE_DIR/Benchmarks/write_benchmark_page.py" "$OUT/benchmark.csv" \
  "$OUT/machine.txt" "$OUT/README.md" "$OUT/numbering.csv" "$OUT/machine.txt" \
  "$OUT/composite.csv" "$OUT/command.csv" "$OUT/motion.csv" "$OUT/wing_body.csv"
echo "wrote $OUT/README.md"
# Large motions (issue 10): sub-steps and the quality guard on the thin slab (about 30 s).
/usr/bin/python3 "$SOURCE_DIR/Benchmarks/large_motion.py" "$BUILD_DIR" "$OUT/large_motion.md" \
  --repeats "${REPEATS:-5}"
# The whole command on a solver's mesh file (issue 18): gmsh, SU2, Exodus II and CGNS (about 80 s
# the first time: gmsh makes the mesh once into the cache folder).
/usr/bin/python3 "$SOURCE_DIR/Benchmarks/solver_formats.py" "$BUILD_DIR" "$OUT/solver_formats.md" \
  --repeats "${REPEATS:-3}"
