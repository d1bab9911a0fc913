"""Run inside the ParaView GUI (paraview --script=... --exit) under Xvfb: load the plugin, apply
DGMF Deform to the rotating circle, colour by SizeSkew and save a screenshot.

Paths come from the environment: DGMF_PLUGIN, DGMF_DATA, DGMF_SCREENSHOT. Prints "GUI OK <points>"
on success; the ctest checks that line and the screenshot.
"""
import os

from paraview.simple import *  # noqa: F401,F403

LoadPlugin(os.environ["DGMF_PLUGIN"], remote=False, ns=globals())
mesh = XMLUnstructuredGridReader(FileName=[os.environ["DGMF_DATA"]])
deform = DGMFDeform(Input=mesh)  # noqa: F821 (defined by LoadPlugin)
deform.BoundaryMarkerArray = ["POINTS", "BoundaryMarker"]
deform.RotationAngles = [0.0, 0.0, 90.0]
display = Show(deform)
ColorBy(display, ("CELLS", "SizeSkew"))
view = GetActiveViewOrCreate("RenderView")
ResetCamera()
Render()
SaveScreenshot(os.environ["DGMF_SCREENSHOT"], view, ImageResolution=[800, 600])
points = deform.GetDataInformation().GetNumberOfPoints()
assert points == 822, points
print("GUI OK %d" % points)
