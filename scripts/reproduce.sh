#!/usr/bin/env bash
# Reproduces the paper's test cases (Section 3) and writes Documentation/results/:
# CSV files, plots, quality pictures and tables.md (see Documentation/results/README.md).
#   scripts/reproduce.sh [--skip-wing] [--skip-idw] [--wing-full]
#     --skip-wing  leave out the 3D wing-body case (mesh generation and fold)
#     --skip-idw   leave out IDW on the wing-body (about 1.5 minutes)
#     --wing-full  also the full wing-body model (both wings, no symmetry plane; its mesh takes
#                  about 10 more minutes the first time, then is cached)
# Environment: BUILD_DIR (default build/), XDG_CACHE_HOME (the wing-body mesh is cached in
# ${XDG_CACHE_HOME:-$HOME/.cache}/dgmf/), DISPLAY (else a private Xvfb server is started).
# Builds first (scripts/build.sh). On 2 cores: about 10 minutes the first time (4 of them for the
# wing-body mesh), about 5 minutes once the mesh is cached.
set -euo pipefail
SOURCE_DIR="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD_DIR="${BUILD_DIR:-$SOURCE_DIR/build}"
RESULTS="$SOURCE_DIR/Documentation/results"
CACHE="${XDG_CACHE_HOME:-$HOME/.cache}/dgmf"
REPRO="$SOURCE_DIR/Reproduction"
skip_wing=0
wing_full=0
skip_idw=()
for arg in "$@"; do
  case "$arg" in
    --skip-wing) skip_wing=1 ;;
    --skip-idw) skip_idw=(--skip-idw) ;;
    --wing-full) wing_full=1 ;;
    *) echo "usage: $0 [--skip-wing] [--skip-idw] [--wing-full]" >&2; exit 2 ;;
  esac
done

bash "$SOURCE_DIR/scripts/build.sh"
PLUGIN="$BUILD_DIR/lib/dgmf-plugins/DGMFPlugin/DGMFPlugin.so"
EXPAT_FIX="$BUILD_DIR/lib/libdgmf_expat_fix.so"
for file in "$PLUGIN" "$EXPAT_FIX"; do
  [ -f "$file" ] || { echo "missing $file: did the build succeed?" >&2; exit 1; }
done
mkdir -p "$RESULTS" "$CACHE"

# Debian's ParaView renders through GLX even offscreen: give it an X server (-noreset: a pvpython
# connecting while Xvfb resets after its last client fails; Documentation/paraview_environment.md).
if [ -z "${DISPLAY:-}" ]; then
  display_file="$(mktemp)"
  Xvfb -displayfd 3 -screen 0 1280x1024x24 -noreset -nolisten tcp 3>"$display_file" 2>/dev/null &
  xvfb_pid=$!
  trap 'kill "$xvfb_pid" 2>/dev/null || true; rm -f "$display_file"' EXIT
  for _ in $(seq 50); do [ -s "$display_file" ] && break; sleep 0.1; done
  [ -s "$display_file" ] || { echo "Xvfb did not start" >&2; exit 1; }
  export DISPLAY=":$(head -n 1 "$display_file")"
fi

pv() {  # pvpython with the expat work-around and the plugin of this build
  env LD_PRELOAD="$EXPAT_FIX" DGMF_PLUGIN="$PLUGIN" PYTHONDONTWRITEBYTECODE=1 \
    pvpython --force-offscreen-rendering "$@"
}

log="$RESULTS/run.md"
step() {  # step NAME COMMAND...: run, time, and record the time in run.md
  local name="$1" start end
  shift
  echo "== $name"
  start=$(date +%s)
  "$@"
  end=$(date +%s)
  echo "| $name | $((end - start)) |" >>"$log"
}

total_start=$(date +%s)
{
  echo "# Last run of scripts/reproduce.sh"
  echo
  echo "Generated; times vary from run to run. $(date -u +%Y-%m-%d),"
  echo "$(nproc) cores ($(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)),"
  changes=""
  git -C "$SOURCE_DIR" diff --quiet HEAD -- Filters Plugin Tools 2>/dev/null ||
    changes=" with local changes to the C++ code"
  echo "commit $(git -C "$SOURCE_DIR" rev-parse --short HEAD 2>/dev/null || echo unknown)$changes."
  echo
  echo "| step | seconds |"
  echo "|---|---|"
} >"$log"

if [ "$skip_wing" = 0 ]; then
  step "wing-body mesh (cached in $CACHE)" pv "$SOURCE_DIR/Data/generators/wing_body.py" \
    "$CACHE/wing_body.vtu"
fi
if [ "$skip_wing" = 0 ] && [ "$wing_full" = 1 ]; then
  step "full wing-body mesh (cached)" pv "$SOURCE_DIR/Data/generators/wing_body.py" --full \
    "$CACHE/wing_body_full.vtu"
fi
step "finer twisted-bar mesh (diagnosis)" pv "$SOURCE_DIR/Data/generators/twisted_bar.py" \
  "$CACHE/twisted_bar_size_max_1.vtu" --size-max 1
step "Fig. 4-6: rotating rectangle" pv "$REPRO/rotating_rectangle.py" --output "$RESULTS"
step "Fig. 8-9: rotating circle" pv "$REPRO/rotating_circle.py" --output "$RESULTS"
step "Fig. 12-14, Table 2: twisted bar" pv "$REPRO/twisted_bar.py" --output "$RESULTS" \
  --fine-mesh "$CACHE/twisted_bar_size_max_1.vtu"
if [ "$skip_wing" = 0 ]; then
  step "Figs. 15-16: wing fold" pv "$REPRO/wing_fold.py" --output "$RESULTS" \
    --mesh "$CACHE/wing_body.vtu" "${skip_idw[@]}"
fi
if [ "$skip_wing" = 0 ] && [ "$wing_full" = 1 ]; then
  step "wing fold, full model" pv "$REPRO/wing_fold.py" --output "$RESULTS" \
    --mesh "$CACHE/wing_body_full.vtu" --prefix wing_fold_full --skip-idw
fi
step "plots" pv "$REPRO/plots.py" --results "$RESULTS"
step "tables" pv "$REPRO/tables.py" --results "$RESULTS"
total=$(($(date +%s) - total_start))
echo "| total (after the build) | $total |" >>"$log"
echo "done in $total s: $RESULTS"
