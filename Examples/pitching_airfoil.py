"""A pitching airfoil with the DGMF plugin: a motion law, the animation, the export.

    build/bin/dgmf-pvpython Examples/pitching_airfoil.py Data/pitching_airfoil.vtu OUT_DIR \
        [FRAMES_PER_PERIOD] [PERIODS]

The NACA 0012 of Data/pitching_airfoil.vtu pitches about its quarter chord,
theta(t) = 20 sin(2 pi t) degrees (one period per unit of time), with the quality guard on. The
filter reports the time steps (its Time Range and Number Of Time Steps), so ParaView's animation
plays the motion; each frame maps from the input mesh with the Delaunay graph built once. The
script

1. plays every time step and records the quality of each frame (SizeSkewMinimum,
   InvertedCellCount and MotionTime from the filter's field data);
2. saves the whole series with ParaView's Save Data (OUT_DIR/pitch.pvd and OUT_DIR/pitch/);
3. renders four frames (OUT_DIR/frame_NNNN.png, kept) into one picture strip
   (OUT_DIR/pitch_strip.png) and plots the minimum
   quality over the cycle (OUT_DIR/pitch_quality.png; OUT_DIR/pitch_quality.csv has the numbers).

It prints one line per frame and exits with 1 if a frame has an inverted cell. Copy it and change
the law: RotationLaw "Harmonic" or "Ramp" with RotationLawParameters (mean, amplitude, frequency,
phase) or (start angle, end angle, start time, end time); TranslationLaw likewise along the
Translation's direction; or connect a CSV table of a trajectory as the filter's Trajectory input.
The plugin is found from DGMF_PLUGIN (dgmf-pvpython sets it). Rendering needs an X display: the
script runs itself again under xvfb-run when there is none (dgmf_display.py).
"""
import csv
import os
import sys

from paraview import servermanager
from paraview.simple import *  # noqa: F401,F403 (ParaView's scripting style)

from dgmf_display import ensure_display

ensure_display("pitching_airfoil.py")
input_path, out_dir = sys.argv[1], sys.argv[2]
frames_per_period = int(sys.argv[3]) if len(sys.argv) > 3 else 50
periods = int(sys.argv[4]) if len(sys.argv) > 4 else 1
os.makedirs(out_dir, exist_ok=True)
LoadPlugin(os.environ["DGMF_PLUGIN"], remote=False, ns=globals())

# The law: 20 degrees of amplitude about the quarter chord, one period per unit of time.
mesh = XMLUnstructuredGridReader(FileName=[input_path])
deform = DGMFDeform(Input=mesh)  # noqa: F821 (defined by LoadPlugin)
deform.BoundaryMarkerArray = ["POINTS", "BoundaryMarker"]
deform.RotationCenter = [0.25, 0.0, 0.0]
deform.RotationAxis = [0.0, 0.0, 1.0]
deform.RotationLaw = "Harmonic"
deform.RotationLawParameters = [0.0, 20.0, 1.0, 0.0]  # mean, amplitude, frequency, phase
deform.TimeRange = [0.0, float(periods)]
deform.NumberOfTimeSteps = frames_per_period * periods + 1
deform.SubSteps = 0  # automatic sub-steps ...
deform.RepairThreshold = 0.2  # ... and the quality guard
deform.UpdatePipelineInformation()
times = list(deform.TimestepValues)

# 1. The animation: the scene follows the filter's time steps.
scene = GetAnimationScene()
scene.UpdateAnimationUsingDataTimeSteps()
view = GetActiveViewOrCreate("RenderView")
view.ViewSize = [480, 400]
display = Show(deform, view)
display.SetRepresentationType("Surface With Edges")
ColorBy(display, ("CELLS", "SizeSkew"))
GetColorTransferFunction("SizeSkew").RescaleTransferFunction(0.0, 1.0)
Render(view)  # the first render places the camera: zoom on the airfoil after it
view.CameraPosition = [0.5, 0.0, 3.0]
view.CameraFocalPoint = [0.5, 0.0, 0.0]
view.CameraViewUp = [0.0, 1.0, 0.0]
view.CameraParallelProjection = 1
view.CameraParallelScale = 0.6
view.OrientationAxesVisibility = 0

rows, strip, worst = [], [], 0
snapshots = {k * frames_per_period // 4 for k in range(4)}  # about 0, 1/4, 1/2, 3/4 period
for k, t in enumerate(times):
    scene.AnimationTime = t
    field_data = servermanager.Fetch(deform).GetFieldData()
    value = lambda name: field_data.GetArray(name).GetTuple1(0)  # noqa: E731
    row = (value("MotionTime"), value("SizeSkewMinimum"), int(value("InvertedCellCount")))
    rows.append(row)
    worst = max(worst, row[2])
    print("frame %3d: t = %.4f, SizeSkew minimum %.4f, inverted cells %d" % ((k,) + row))
    if k in snapshots:
        path = os.path.join(out_dir, "frame_%04d.png" % k)
        Render(view)
        SaveScreenshot(path, view)
        strip.append((path, t))

# 2. The series, every time step (ParaView's Save Data with Write Time Steps).
SaveData(os.path.join(out_dir, "pitch.pvd"), proxy=deform, WriteTimeSteps=1)

# 3. The quality over the cycle, and the picture strip.
with open(os.path.join(out_dir, "pitch_quality.csv"), "w", newline="") as handle:
    writer = csv.writer(handle)
    writer.writerow(["time", "SizeSkewMinimum", "InvertedCellCount"])
    writer.writerows(rows)
import matplotlib  # noqa: E402 (after ParaView: a display-free backend)
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import math  # noqa: E402

figure, axes = plt.subplots(figsize=(6, 3.2))
axes.plot([r[0] for r in rows], [r[1] for r in rows], label="minimum SizeSkew of the frame")
axes.axhline(0.2, color="red", linewidth=0.8, label="guard threshold 0.2")
axes.set_xlabel("time (periods)")
axes.set_ylabel("quality")
axes.set_ylim(0.0, 1.0)
axes.legend(loc="lower left", fontsize=8)
angle = axes.twinx()
angle.plot([r[0] for r in rows], [20 * math.sin(2 * math.pi * r[0]) for r in rows], ":",
           color="grey")
angle.set_ylabel("pitch angle (degrees, dotted)")
angle.set_ylim(-40, 40)
figure.tight_layout()
figure.savefig(os.path.join(out_dir, "pitch_quality.png"), dpi=100)
images = [plt.imread(path) for path, _ in strip]
figure, panels = plt.subplots(1, len(images), figsize=(3 * len(images), 2.6))
for panel, image, (_, t) in zip(panels, images, strip):
    panel.imshow(image)
    panel.set_title("t = %.2f: %.1f degrees" % (t, 20 * math.sin(2 * math.pi * t)), fontsize=9)
    panel.axis("off")
figure.tight_layout()
figure.savefig(os.path.join(out_dir, "pitch_strip.png"), dpi=100)

print("%d frames, the lowest SizeSkew minimum %.4f, inverted cells in %d frames" % (
    len(rows), min(r[1] for r in rows), sum(1 for r in rows if r[2] > 0)))
print("wrote %s (series), pitch_strip.png and pitch_quality.png in %s" % (
    os.path.join(out_dir, "pitch.pvd"), out_dir))
if worst > 0:
    sys.exit(1)
