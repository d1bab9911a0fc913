"""Writes the sphere-in-box mesh as a CFD reader gives it, for the distributed test of boundaries
chosen by name: a multiblock (.vtm) of the volume (`internalMesh`, without the marker) and its
two patches, `wing` (the faces on the sphere, marker 2) and `box` (the others), each a polydata
on points of its own.

usage: make_named_sphere.py SOURCE.vtu TARGET.vtm
"""
import sys

import os

from vtkmodules.vtkFiltersGeometry import vtkDataSetSurfaceFilter
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from reader_blocks import write_reader_blocks  # noqa: E402

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
volume = mesh.NewInstance()
volume.DeepCopy(mesh)
volume.GetPointData().RemoveArray("BoundaryMarker")

def corners(cell):
    ids = faces.GetCell(cell).GetPointIds()
    return [ids.GetId(k) for k in range(ids.GetNumberOfIds())]


write_reader_blocks(volume, faces.GetPoints(),
                    {name: [corners(c) for c in cells] for name, cells in patches.items()},
                    sys.argv[2])
print("named sphere: wing %d faces, box %d faces" % (len(patches["wing"]), len(patches["box"])))
