#!/usr/bin/env bash
# Remakes the GUI screenshots in this folder: the ParaView GUI under Xvfb with the DGMF Deform
# panel and the rotating circle coloured by SizeSkew. Needs a build (scripts/build.sh) and
# ImageMagick (apt-get install imagemagick x11-apps). Not part of the tests.
set -euo pipefail
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
ROOT="$(cd "$HERE/../.." && pwd)"
BUILD="${BUILD_DIR:-$ROOT/build}"
export DGMF_PLUGIN="$BUILD/lib/dgmf-plugins/DGMFPlugin/DGMFPlugin.so"
export DGMF_DATA="$ROOT/Data/rotating_circle.vtu"
DISPLAY_NUMBER=:77
# A fresh home: no welcome dialog, default layout.
export HOME="$(mktemp -d)"
mkdir -p "$HOME/.config/ParaView"
printf '[General]\nGeneralSettings.ShowWelcomeDialog=false\n' > "$HOME/.config/ParaView/ParaView5.11.0.ini"
Xvfb $DISPLAY_NUMBER -screen 0 1400x900x24 -noreset >/dev/null 2>&1 &
XVFB=$!
trap 'kill $XVFB 2>/dev/null || true' EXIT
sleep 2
DISPLAY=$DISPLAY_NUMBER LD_PRELOAD="$BUILD/lib/libdgmf_expat_fix.so" \
  paraview --script="$HERE/gui_panel.py" >/dev/null 2>&1 &
PARAVIEW=$!
sleep "${WAIT_SECONDS:-15}"
# Fill the screen (no window manager runs: xdotool resizes the main window itself).
for WINDOW in $(DISPLAY=$DISPLAY_NUMBER xdotool search --onlyvisible --name "ParaView"); do
  DISPLAY=$DISPLAY_NUMBER xdotool windowmove "$WINDOW" 0 0 windowsize "$WINDOW" 1400 900 || true
done
sleep 5
DISPLAY=$DISPLAY_NUMBER import -window root "$HERE/paraview_dgmf_deform.png"
kill $PARAVIEW 2>/dev/null || true
echo "wrote $HERE/paraview_dgmf_deform.png"
