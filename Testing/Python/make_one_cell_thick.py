"""The one-cell-thick mesh of the distributed test and its serial result (pvbatch, one process):
the rotating circle extruded by 0.1 along z into one layer of wedges, written as a reader's
multiblock (.vtm): `internalMesh`, and the patches `circle` (the moving body), `outer` (the
square), `front` and `back` (the two planes), each a polydata on points of its own. The serial
run deforms it as 2D (one cell thick, detected) with the circle turned by 30 degrees, and writes
the volume.

usage: pvbatch make_one_cell_thick.py PLUGIN CIRCLE.vtu MESH.vtm REFERENCE.vtu
"""
import os
import sys

from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import VTK_WEDGE, vtkUnstructuredGrid
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader
from vtkmodules.vtkParallelCore import vtkMultiProcessController

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from reader_blocks import deform_by_name, write_binary, write_reader_blocks  # noqa: E402

plugin, source, mesh_path, reference_path = sys.argv[1:5]
assert vtkMultiProcessController.GetGlobalController().GetNumberOfProcesses() == 1
reader = vtkXMLUnstructuredGridReader()
reader.SetFileName(source)
reader.Update()
circle = reader.GetOutput()
n = circle.GetNumberOfPoints()
assert n == 822, n
points = vtkPoints()
points.SetDataTypeToDouble()
for layer in (0.0, 0.1):
    for i in range(n):
        x, y, _ = circle.GetPoint(i)
        points.InsertNextPoint(x, y, layer)
volume = vtkUnstructuredGrid()
volume.SetPoints(points)
edges = {}
patches = {"front": [], "back": [], "circle": [], "outer": []}
for c in range(circle.GetNumberOfCells()):
    ids = [circle.GetCell(c).GetPointId(k) for k in range(3)]
    volume.InsertNextCell(VTK_WEDGE, 6, ids + [i + n for i in ids])
    patches["front"].append(ids)
    patches["back"].append([i + n for i in ids])
    for k in range(3):
        a, b = ids[k], ids[(k + 1) % 3]
        edges[(min(a, b), max(a, b))] = edges.get((min(a, b), max(a, b)), 0) + 1
for (a, b), count in edges.items():
    if count == 1:
        name = "circle" if sum(c * c for c in circle.GetPoint(a)) < 4.0 else "outer"
        patches[name].append([a, b, b + n, a + n])
write_reader_blocks(volume, points, patches, mesh_path)

output = deform_by_name(plugin, mesh_path, ["circle"], RotationAngles=[0.0, 0.0, 30.0])
deformed = output.GetBlock(0)
moved = sum(deformed.GetPoint(i) != volume.GetPoint(i) for i in range(2 * n))
inverted = output.GetFieldData().GetArray("InvertedCellCount").GetTuple1(0)
write_binary(deformed, reference_path)
print("one-cell-thick reference: %d of %d nodes moved, %d inverted" % (moved, 2 * n, inverted))
