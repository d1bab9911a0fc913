"""Animate the rotating circle from 0 to 90 degrees with the DGMF plugin and save the frames.

    build/bin/dgmf-pvpython Examples/animate_circle.py Data/rotating_circle.vtu FRAMES_DIR [FRAMES]

The plugin is found from the DGMF_PLUGIN environment variable (dgmf-pvpython sets it, and
preloads the expat work-around). Without an X display (Debian's ParaView renders through X even
offscreen), the script runs itself again under xvfb-run (dgmf_display.py), or says what to run.
Only the rotation angle changes from frame to frame, so the filter keeps its Delaunay graph and
node locations: every frame after the first is a single pass over the nodes. The script prints,
for each frame, whether the graph was reused, and the quality, then the number of frames written.
Frames are PNG files (frame_0000.png, ...); a movie can be made from them, e.g. with
ffmpeg -i FRAMES_DIR/frame_%04d.png circle.mp4.
"""
import os
import sys

from paraview import servermanager
from paraview.simple import *  # noqa: F401,F403 (ParaView's scripting style)

from dgmf_display import ensure_display

ensure_display("animate_circle.py")
input_path, frames_dir = sys.argv[1], sys.argv[2]
frames = int(sys.argv[3]) if len(sys.argv) > 3 else 19
os.makedirs(frames_dir, exist_ok=True)
LoadPlugin(os.environ["DGMF_PLUGIN"], remote=False, ns=globals())

mesh = XMLUnstructuredGridReader(FileName=[input_path])
deform = DGMFDeform(Input=mesh)  # noqa: F821 (defined by LoadPlugin)
deform.BoundaryMarkerArray = ["POINTS", "BoundaryMarker"]
view = GetActiveViewOrCreate("RenderView")
view.ViewSize = [600, 600]
display = Show(deform, view)
ColorBy(display, ("CELLS", "SizeSkew"))
GetColorTransferFunction("SizeSkew").RescaleTransferFunction(0.0, 1.0)
ResetCamera(view)

reused = saved = 0
for frame in range(frames):
    angle = 90.0 * frame / max(frames - 1, 1)
    deform.RotationAngles = [0.0, 0.0, angle]
    Render(view)
    saved += 1 if SaveScreenshot(os.path.join(frames_dir, "frame_%04d.png" % frame), view) else 0
    field_data = servermanager.Fetch(deform).GetFieldData()
    graph_reused = field_data.GetArray("GraphReused").GetTuple1(0) == 1
    reused += 1 if graph_reused else 0
    quality = field_data
    print("frame %d: %5.1f degrees, graph reused: %s, SizeSkew minimum %.4f, inverted cells %d" % (
        frame, angle, graph_reused,
        quality.GetArray("SizeSkewMinimum").GetTuple1(0),
        int(quality.GetArray("InvertedCellCount").GetTuple1(0))))
print("%d frames written to %s" % (saved, frames_dir))
print("graph reused for %d of %d frames" % (reused, frames))
