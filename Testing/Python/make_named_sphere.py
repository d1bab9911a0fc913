"""Writes the sphere-in-box mesh as a CFD reader gives it, for the distributed test of boundaries
chosen by name: a multiblock (.vtm) of the volume (`internalMesh`, without the marker) and its
two patches, `wing` (the faces on the sphere, marker 2) and `box` (the others), each a polydata
on points of its own.

usage: make_named_sphere.py SOURCE.vtu TARGET.vtm
"""
import sys

from vtkmodules.vtkCommonDataModel import (vtkCellArray, vtkCompositeDataSet, vtkMultiBlockDataSet,
                                            vtkPolyData)
from vtkmodules.vtkFiltersCore import vtkCleanPolyData
from vtkmodules.vtkFiltersGeometry import vtkDataSetSurfaceFilter
from vtkmodules.vtkIOXML import vtkXMLMultiBlockDataWriter, vtkXMLUnstructuredGridReader

reader = vtkXMLUnstructuredGridReader()
reader.SetFileName(sys.argv[1])
reader.Update()
mesh = reader.GetOutput()
assert mesh.GetNumberOfPoints() == 3200, mesh.GetNumberOfPoints()
surface = vtkDataSetSurfaceFilter()
surface.SetInputData(mesh)
surface.Update()
faces = surface.GetOutput()
marker = faces.GetPointData().GetArray("BoundaryMarker")
patches = {"wing": [], "box": []}
for c in range(faces.GetNumberOfCells()):
    ids = faces.GetCell(c).GetPointIds()
    on_wing = all(marker.GetTuple1(ids.GetId(k)) == 2 for k in range(ids.GetNumberOfIds()))
    patches["wing" if on_wing else "box"].append(c)
boundary = vtkMultiBlockDataSet()
for index, name in enumerate(("wing", "box")):
    polys = vtkCellArray()
    for c in patches[name]:
        polys.InsertNextCell(faces.GetCell(c).GetPointIds())
    patch = vtkPolyData()
    patch.SetPoints(faces.GetPoints())
    patch.SetPolys(polys)
    clean = vtkCleanPolyData()  # its own points only, as the OpenFOAM reader's patches
    clean.SetInputData(patch)
    clean.PointMergingOff()
    clean.Update()
    boundary.SetBlock(index, clean.GetOutput())
    boundary.GetMetaData(index).Set(vtkCompositeDataSet.NAME(), name)
volume = mesh.NewInstance()
volume.DeepCopy(mesh)
volume.GetPointData().RemoveArray("BoundaryMarker")
blocks = vtkMultiBlockDataSet()
blocks.SetBlock(0, volume)
blocks.GetMetaData(0).Set(vtkCompositeDataSet.NAME(), "internalMesh")
blocks.SetBlock(1, boundary)
blocks.GetMetaData(1).Set(vtkCompositeDataSet.NAME(), "boundary")
writer = vtkXMLMultiBlockDataWriter()
writer.SetInputData(blocks)
writer.SetFileName(sys.argv[2])
writer.SetDataModeToBinary()
assert writer.Write() == 1
print("named sphere: wing %d faces, box %d faces" % (len(patches["wing"]), len(patches["box"])))
