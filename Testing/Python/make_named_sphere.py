"""Writes the sphere-in-box mesh as a CFD reader gives it, for the distributed tests of boundaries
chosen by name, and the serial result of its front half moving (pvbatch, one process): a
multiblock (.vtm) of the volume (`internalMesh`, without the marker) and its patches, the sphere
in two halves `wingA` (faces with x < 0) and `wingB` (the others), which share the nodes of
their seam, and `box`, each a polydata on points of its own.

usage: pvbatch make_named_sphere.py PLUGIN SOURCE.vtu TARGET.vtm HALF_REFERENCE.vtu
"""
import os
import sys

from vtkmodules.vtkFiltersGeometry import vtkDataSetSurfaceFilter
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader
from vtkmodules.vtkParallelCore import vtkMultiProcessController

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from reader_blocks import deform_by_name, write_binary, write_reader_blocks  # noqa: E402

plugin, source, target, half_reference = sys.argv[1:5]
assert vtkMultiProcessController.GetGlobalController().GetNumberOfProcesses() == 1
reader = vtkXMLUnstructuredGridReader()
reader.SetFileName(source)
reader.Update()
mesh = reader.GetOutput()
assert mesh.GetNumberOfPoints() == 3200, mesh.GetNumberOfPoints()
surface = vtkDataSetSurfaceFilter()
surface.SetInputData(mesh)
surface.Update()
faces = surface.GetOutput()
marker = faces.GetPointData().GetArray("BoundaryMarker")


def corners(cell):
    ids = faces.GetCell(cell).GetPointIds()
    return [ids.GetId(k) for k in range(ids.GetNumberOfIds())]


patches = {"wingA": [], "wingB": [], "box": []}
for c in range(faces.GetNumberOfCells()):
    ids = corners(c)
    if all(marker.GetTuple1(i) == 2 for i in ids):
        centre = sum(faces.GetPoint(i)[0] for i in ids) / len(ids)
        patches["wingA" if centre < 0.0 else "wingB"].append(ids)
    else:
        patches["box"].append(ids)
volume = mesh.NewInstance()
volume.DeepCopy(mesh)
volume.GetPointData().RemoveArray("BoundaryMarker")
write_reader_blocks(volume, faces.GetPoints(), patches, target)

# The serial result of wingA moving alone (wingB static): its seam nodes move (moving over
# static, wherever the two halves' blocks are).
deformed = deform_by_name(plugin, target, ["wingA"], RotationAngles=[10.0, 20.0, 30.0],
                          Translation=[0.2, -0.1, 0.05])
write_binary(deformed.GetBlock(0), half_reference)
print("named sphere: wingA %d, wingB %d, box %d faces" % tuple(
    len(patches[name]) for name in ("wingA", "wingB", "box")))
