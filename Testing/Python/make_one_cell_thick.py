"""The one-cell-thick mesh of the distributed test and its serial result (pvbatch, one process):
the rotating circle extruded by 0.1 along z into one layer of wedges, written as a reader's
multiblock (.vtm): `internalMesh`, and the patches `circle` (the moving body), `outer` (the
square), `front` and `back` (the two planes), each a polydata on points of its own. The serial
run deforms it as 2D (one cell thick, detected) with the circle turned by 30 degrees, and writes
the volume.

usage: pvbatch make_one_cell_thick.py PLUGIN CIRCLE.vtu MESH.vtm REFERENCE.vtu
"""
import sys

from paraview import simple
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import (VTK_WEDGE, vtkCellArray, vtkCompositeDataSet,
                                           vtkMultiBlockDataSet, vtkPolyData, vtkUnstructuredGrid)
from vtkmodules.vtkFiltersCore import vtkCleanPolyData
from vtkmodules.vtkIOXML import (vtkXMLMultiBlockDataWriter, vtkXMLUnstructuredGridReader,
                                 vtkXMLUnstructuredGridWriter)
from vtkmodules.vtkParallelCore import vtkMultiProcessController

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
boundary = vtkMultiBlockDataSet()
for index, name in enumerate(("circle", "outer", "front", "back")):
    polys = vtkCellArray()
    for face in patches[name]:
        polys.InsertNextCell(len(face), face)
    patch = vtkPolyData()
    patch.SetPoints(points)
    patch.SetPolys(polys)
    clean = vtkCleanPolyData()  # its own points only, as the OpenFOAM reader's patches
    clean.SetInputData(patch)
    clean.PointMergingOff()
    clean.Update()
    boundary.SetBlock(index, clean.GetOutput())
    boundary.GetMetaData(index).Set(vtkCompositeDataSet.NAME(), name)
blocks = vtkMultiBlockDataSet()
blocks.SetBlock(0, volume)
blocks.GetMetaData(0).Set(vtkCompositeDataSet.NAME(), "internalMesh")
blocks.SetBlock(1, boundary)
blocks.GetMetaData(1).Set(vtkCompositeDataSet.NAME(), "boundary")
writer = vtkXMLMultiBlockDataWriter()
writer.SetInputData(blocks)
writer.SetFileName(mesh_path)
writer.SetDataModeToBinary()
assert writer.Write() == 1

simple.LoadPlugin(plugin, remote=False, ns=globals())
deform = DGMFDeform(Input=simple.XMLMultiBlockDataReader(FileName=[mesh_path]))  # noqa: F821
deform.BoundaryMarkerArray = ["POINTS", "None"]
deform.DisplacementArray = ["POINTS", "None"]
deform.MovingBoundaries = ["circle"]
deform.RotationAngles = [0.0, 0.0, 30.0]
deform.UpdatePipeline()
deformed = deform.GetClientSideObject().GetOutputDataObject(0).GetBlock(0)
moved = sum(deformed.GetPoint(i) != volume.GetPoint(i) for i in range(2 * n))
inverted = deform.GetClientSideObject().GetOutputDataObject(0).GetFieldData().GetArray(
    "InvertedCellCount").GetTuple1(0)
out = vtkXMLUnstructuredGridWriter()
out.SetInputData(deformed)
out.SetFileName(reference_path)
out.SetDataModeToBinary()
assert out.Write() == 1
print("one-cell-thick reference: %d of %d nodes moved, %d inverted" % (moved, 2 * n, inverted))
