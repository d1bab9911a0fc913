"""Loaded by make_screenshots.sh inside the ParaView GUI: the rotating circle deformed by DGMF
Deform, coloured by SizeSkew, with the filter's properties panel (advanced properties shown)."""
import os

from paraview.simple import *  # noqa: F401,F403

LoadPlugin(os.environ["DGMF_PLUGIN"], remote=False, ns=globals())
mesh = XMLUnstructuredGridReader(FileName=[os.environ["DGMF_DATA"]])
deform = DGMFDeform(Input=mesh)  # noqa: F821 (defined by LoadPlugin)
deform.BoundaryMarkerArray = ["POINTS", "BoundaryMarker"]
deform.RotationAngles = [0.0, 0.0, 90.0]
Hide(mesh)
display = Show(deform)
ColorBy(display, ("CELLS", "SizeSkew"))
display.SetScalarBarVisibility(GetActiveViewOrCreate("RenderView"), True)
GetColorTransferFunction("SizeSkew").RescaleTransferFunction(0.0, 1.0)
SetActiveSource(deform)
ResetCamera()
Render()
