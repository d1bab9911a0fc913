"""The serial reference of the distributed test's extracted rigid motion (pvbatch, one process):
writes the sphere-in-box mesh with a displacement on its moving nodes that is a rotation about z
plus a shape deformation (so that how the nodes are weighted changes the fitted motion), and the
mesh DGMF Deform gives with RigidMotionMode Extracted.

usage: pvbatch make_extracted_reference.py PLUGIN SOURCE.vtu MESH.vtu REFERENCE.vtu
"""
import sys

from paraview import simple
from vtkmodules.vtkParallelCore import vtkMultiProcessController

plugin, source, mesh_path, reference_path = sys.argv[1:5]
assert vtkMultiProcessController.GetGlobalController().GetNumberOfProcesses() == 1
simple.LoadPlugin(plugin, remote=False, ns=globals())
reader = simple.XMLUnstructuredGridReader(FileName=[source])
mesh = simple.Calculator(Input=reader, ResultArrayName="Displacement", Function=(
    "(BoundaryMarker==2)*((-0.2*coordsY+0.05*coordsX*coordsX)*iHat + 0.2*coordsX*jHat"
    " + 0.1*coordsZ*coordsZ*kHat)"))
simple.SaveData(mesh_path, proxy=mesh, DataMode="Binary")
deform = DGMFDeform(Input=mesh)  # noqa: F821 (defined by LoadPlugin)
deform.BoundaryMarkerArray = ["POINTS", "BoundaryMarker"]
deform.DisplacementArray = ["POINTS", "Displacement"]
deform.RigidMotionMode = "Extracted"
simple.SaveData(reference_path, proxy=deform, DataMode="Binary")
deform.UpdatePipeline()
angle = deform.GetClientSideObject().GetOutputDataObject(0).GetFieldData().GetArray(
    "FittedRotationAngle").GetTuple1(0)
print("extracted reference: fitted rotation %.6f degrees" % angle)
