"""Meshes for the failure tests, made with VTK in the test (no file is shipped for them)."""
import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import (VTK_QUADRATIC_TRIANGLE, vtkCellArray, vtkImageData,
                                            vtkUnstructuredGrid)
from vtkmodules.vtkFiltersGeneral import vtkDataSetTriangleFilter
from vtkmodules.vtkIOLegacy import vtkUnstructuredGridReader
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader, vtkXMLUnstructuredGridWriter


def read(path):
    """The unstructured grid in `path` (.vtu or legacy .vtk)."""
    reader = vtkUnstructuredGridReader() if path.endswith(".vtk") else vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def write(mesh, path):
    writer = vtkXMLUnstructuredGridWriter()
    writer.SetInputData(mesh)
    writer.SetFileName(path)
    writer.SetDataModeToBinary()
    if not writer.Write() or writer.GetErrorCode():
        raise RuntimeError("could not write " + path)


def set_marker(mesh, values, name="BoundaryMarker"):
    array = numpy_to_vtk(np.ascontiguousarray(values, dtype=np.int32), deep=1)
    array.SetName(name)
    mesh.GetPointData().AddArray(array)


def cube_in_box(n, path):
    """Tetrahedra of an n^3 grid of the unit cube: the outer faces static (1), the nodes of the
    centre cube [0.4, 0.6]^3 moving (2). Returns (points, cells)."""
    image = vtkImageData()
    image.SetDimensions(n, n, n)
    image.SetSpacing(1.0 / (n - 1), 1.0 / (n - 1), 1.0 / (n - 1))
    tetrahedra = vtkDataSetTriangleFilter()
    tetrahedra.SetInputData(image)
    tetrahedra.Update()
    mesh = vtkUnstructuredGrid()
    mesh.ShallowCopy(tetrahedra.GetOutput())
    p = vtk_to_numpy(mesh.GetPoints().GetData()).astype(np.float64)
    marker = np.zeros(len(p), dtype=np.int32)
    marker[np.any((p < 1e-9) | (p > 1.0 - 1e-9), axis=1)] = 1
    marker[np.all(np.abs(p - 0.5) < 0.1, axis=1)] = 2
    set_marker(mesh, marker)
    write(mesh, path)
    return mesh.GetNumberOfPoints(), mesh.GetNumberOfCells()


def as_quadratic_triangles(source_path, path):
    """The triangle mesh of `source_path` with a node in the middle of every edge, as
    VTK_QUADRATIC_TRIANGLE cells (which SizeSkew does not cover). A middle node is marked as the
    two ends of its edge when they agree, 0 otherwise."""
    mesh = read(source_path)
    points = vtk_to_numpy(mesh.GetPoints().GetData()).astype(np.float64)
    marker = vtk_to_numpy(mesh.GetPointData().GetArray("BoundaryMarker"))
    new_points, new_marker = list(points), list(marker)
    middle = {}
    cells = vtkCellArray()
    for c in range(mesh.GetNumberOfCells()):
        ids = [mesh.GetCell(c).GetPointId(k) for k in range(3)]
        nodes = list(ids)
        for a, b in ((ids[0], ids[1]), (ids[1], ids[2]), (ids[2], ids[0])):
            key = (min(a, b), max(a, b))
            if key not in middle:
                middle[key] = len(new_points)
                new_points.append(0.5 * (points[a] + points[b]))
                new_marker.append(marker[a] if marker[a] == marker[b] else 0)
            nodes.append(middle[key])
        cells.InsertNextCell(6, nodes)
    quadratic = vtkUnstructuredGrid()
    vtk_points = vtkPoints()
    vtk_points.SetData(numpy_to_vtk(np.array(new_points), deep=1))
    quadratic.SetPoints(vtk_points)
    quadratic.SetCells(VTK_QUADRATIC_TRIANGLE, cells)
    set_marker(quadratic, np.array(new_marker))
    write(quadratic, path)
    return quadratic.GetNumberOfPoints()


def with_marker(source_path, path, change):
    """`source_path` with its BoundaryMarker replaced by change(marker, points)."""
    mesh = read(source_path)
    marker = vtk_to_numpy(mesh.GetPointData().GetArray("BoundaryMarker")).copy()
    points = vtk_to_numpy(mesh.GetPoints().GetData()).copy()
    set_marker(mesh, change(marker, points))
    write(mesh, path)


def with_displacement(source_path, path, change):
    """`source_path` with its Displacement replaced by change(displacement, marker)."""
    mesh = read(source_path)
    marker = vtk_to_numpy(mesh.GetPointData().GetArray("BoundaryMarker")).copy()
    displacement = vtk_to_numpy(mesh.GetPointData().GetArray("Displacement")).copy()
    array = numpy_to_vtk(np.ascontiguousarray(change(displacement, marker)), deep=1)
    array.SetName("Displacement")
    mesh.GetPointData().AddArray(array)
    write(mesh, path)


def with_nan_point(source_path, path):
    mesh = read(source_path)
    points = mesh.GetPoints()
    x = list(points.GetPoint(5))
    points.SetPoint(5, float("nan"), x[1], x[2])
    write(mesh, path)
