"""Writes the sphere-in-box mesh with its lowest box face marked 3 (slip), but for the face's edges
(they stay static), the whole mesh turned by 37 degrees about (1, 2, 0.5) so that the slip plane
is tilted and carries the rotation's round-off: the input of the distributed slip test and of its
serial reference.

usage: make_slip_mesh.py SOURCE.vtu TARGET.vtu
"""
import sys

from vtkmodules.vtkCommonTransforms import vtkTransform
from vtkmodules.vtkFiltersGeneral import vtkTransformFilter
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader, vtkXMLUnstructuredGridWriter

reader = vtkXMLUnstructuredGridReader()
reader.SetFileName(sys.argv[1])
reader.Update()
mesh = reader.GetOutput()
assert mesh.GetNumberOfPoints() == 3200, mesh.GetNumberOfPoints()
marker = mesh.GetPointData().GetArray("BoundaryMarker")
x0, x1, y0, y1, z0, _ = mesh.GetBounds()
slip = 0
for i in range(mesh.GetNumberOfPoints()):
    x, y, z = mesh.GetPoint(i)
    if z == z0 and x0 < x < x1 and y0 < y < y1:
        assert marker.GetTuple1(i) == 1, (i, marker.GetTuple1(i))
        marker.SetTuple1(i, 3)
        slip += 1
assert slip > 20, slip
turn = vtkTransform()
turn.RotateWXYZ(37.0, 1.0, 2.0, 0.5)
turned = vtkTransformFilter()
turned.SetTransform(turn)
turned.SetInputData(mesh)
turned.Update()
mesh = turned.GetOutput()
writer = vtkXMLUnstructuredGridWriter()
writer.SetInputData(mesh)
writer.SetFileName(sys.argv[2])
writer.SetDataModeToBinary()  # inline: read with and without the expat work-around
assert writer.Write() == 1
print("slip mesh: %d slip nodes of %d" % (slip, mesh.GetNumberOfPoints()))
