"""Shared code of the DGMF test-mesh generators (run the case scripts with ``pvpython``).

A case script builds its geometry with gmsh's OpenCASCADE kernel (an outer domain with the moving
body cut out of it) and calls :func:`generate`. This module then

1. meshes the domain with gmsh, single-threaded and with fixed options, so that the result is
   deterministic, graded by a distance field: ``size_min`` on the moving body, growing linearly to
   ``size_max`` at ``dist_max`` from it;
2. converts the mesh to a ``vtkUnstructuredGrid`` holding only the volume cells (VTK_TRIANGLE in
   2D, VTK_TETRA in 3D), without the points gmsh created but no cell uses, in gmsh's node order;
3. makes every cell positively oriented (counter-clockwise triangles, tetrahedra with the 4th point
   on the side of (p1-p0)x(p2-p0)) and sets z = 0 exactly in 2D;
4. adds the point arrays ``BoundaryMarker`` (vtkIntArray: 0 interior, 1 static boundary, 2 moving
   boundary) and ``Displacement`` (vtkDoubleArray, 3 components, all zero);
5. writes the grid with ``vtkXMLUnstructuredGridWriter`` in inline binary mode (zlib), reads it
   back and checks the counts (Debian 12's libexpat can make VTK 9.2 read a file as empty).
"""

import argparse

import gmsh
import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk, numpy_to_vtkIdTypeArray, vtk_to_numpy
from vtkmodules.vtkCommonCore import VTK_DOUBLE, VTK_INT, vtkPoints
from vtkmodules.vtkCommonDataModel import (
    VTK_TETRA,
    VTK_TRIANGLE,
    vtkCellArray,
    vtkUnstructuredGrid,
)
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader, vtkXMLUnstructuredGridWriter

INTERIOR, STATIC, MOVING = 0, 1, 2
"""Values of the ``BoundaryMarker`` point array (those of ``dgmf::NodeKind``)."""

MARKER_ARRAY = "BoundaryMarker"
DISPLACEMENT_ARRAY = "Displacement"

# dimension -> gmsh element type (2: 3-node triangle, 4: 4-node tetrahedron)
_GMSH_CELL_TYPE = {2: 2, 3: 4}
_VTK_CELL_TYPE = {2: VTK_TRIANGLE, 3: VTK_TETRA}

# Options fixed so that two runs give the same mesh (and a user's gmshrc cannot change it).
_GMSH_OPTIONS = {
    "General.Terminal": 1,
    "General.Verbosity": 2,  # errors and warnings only
    "General.NumThreads": 1,
    "Mesh.MaxNumThreads1D": 1,
    "Mesh.MaxNumThreads2D": 1,
    "Mesh.MaxNumThreads3D": 1,
    "Mesh.RandomSeed": 1,
    "Geometry.OCCParallel": 0,
    "Mesh.Algorithm": 6,  # Frontal-Delaunay (2D and surfaces)
    "Mesh.Algorithm3D": 1,  # Delaunay (sequential; HXT would be multithreaded)
    "Mesh.Optimize": 1,
    "Mesh.OptimizeNetgen": 0,
    "Mesh.ElementOrder": 1,
    "Mesh.MeshSizeFromPoints": 0,  # size comes only from the background field
    "Mesh.MeshSizeFromCurvature": 0,
    "Mesh.MeshSizeExtendFromBoundary": 0,
}


def parse_args(description, size_min, size_max, dist_max):
    """Command line of a case script: an output path and the grading parameters."""
    parser = argparse.ArgumentParser(description=description,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("output", help="path of the .vtu file to write")
    parser.add_argument("--size-min", type=float, default=size_min,
                        help="element size on the moving body (default %(default)s)")
    parser.add_argument("--size-max", type=float, default=size_max,
                        help="element size far from the body (default %(default)s)")
    parser.add_argument("--dist-max", type=float, default=dist_max,
                        help="distance from the body where size-max is reached "
                             "(default %(default)s)")
    return parser.parse_args()


def generate(args, dim, build_geometry, moving_box, shared_nodes_moving=False):
    """Mesh the geometry made by ``build_geometry()``, convert it, write ``args.output``.

    ``build_geometry`` creates the domain with ``gmsh.model.occ`` (without synchronizing).
    ``moving_box`` = (xmin, ymin, zmin, xmax, ymax, zmax) encloses the moving body's boundary and no
    part of the outer boundary. Nodes on both the static and the moving boundary (where a body
    crosses a symmetry plane) are an error, or moving ones with ``shared_nodes_moving``.
    Returns the ``vtkUnstructuredGrid`` written.
    """
    gmsh.initialize([], readConfigFiles=False)
    try:
        for name, value in _GMSH_OPTIONS.items():
            gmsh.option.setNumber(name, value)
        gmsh.model.add("domain")
        build_geometry()
        gmsh.model.occ.synchronize()
        static, moving = _classify_boundary(dim, moving_box)
        _set_size_field(dim, moving, args.size_min, args.size_max, args.dist_max)
        gmsh.model.mesh.generate(dim)
        tags, coords, cells = _extract_mesh(dim)
        static_tags = _nodes_on(dim - 1, static)
        moving_tags = _nodes_on(dim - 1, moving)
    finally:
        gmsh.finalize()

    points, cells, used = _compact(tags, coords, cells, dim)
    cells = _orient(points, cells, dim)
    if shared_nodes_moving:
        static_tags = np.setdiff1d(static_tags, moving_tags)
    marker = _markers(used, static_tags, moving_tags)
    _check_markers(cells, marker, dim)
    grid = to_unstructured_grid(points, cells, marker, dim)
    write_and_check(grid, args.output)
    print_summary(args.output, grid)
    return grid


def _classify_boundary(dim, moving_box):
    """Split the domain's boundary entities into (static, moving) tag lists."""
    domain = gmsh.model.getEntities(dim)
    boundary = {tag for _, tag in gmsh.model.getBoundary(domain, combined=True, oriented=False)}
    inside = {tag for _, tag in gmsh.model.getEntitiesInBoundingBox(*moving_box, dim=dim - 1)}
    moving = sorted(boundary & inside)
    static = sorted(boundary - inside)
    assert moving and static, f"boundary split failed: static {static}, moving {moving}"
    return static, moving


def _set_size_field(dim, moving, size_min, size_max, dist_max):
    """Background size: size_min on the moving boundary, linear up to size_max at dist_max."""
    field = gmsh.model.mesh.field
    distance = field.add("Distance")
    field.setNumbers(distance, "CurvesList" if dim == 2 else "SurfacesList", moving)
    field.setNumber(distance, "NumPointsPerCurve", 400)
    threshold = field.add("Threshold")
    field.setNumber(threshold, "InField", distance)
    field.setNumber(threshold, "SizeMin", size_min)
    field.setNumber(threshold, "SizeMax", size_max)
    field.setNumber(threshold, "DistMin", 0.0)
    field.setNumber(threshold, "DistMax", dist_max)
    field.setAsBackgroundMesh(threshold)


def _extract_mesh(dim):
    """All gmsh node tags and coordinates, and the volume cells as an (n, dim+1) tag array."""
    tags, coords, _ = gmsh.model.mesh.getNodes(returnParametricCoord=False)
    types, _, nodes = gmsh.model.mesh.getElements(dim)
    wanted = _GMSH_CELL_TYPE[dim]
    assert list(types) == [wanted], f"unexpected gmsh element types {list(types)}"
    cells = np.asarray(nodes[0], dtype=np.int64).reshape(-1, dim + 1)
    return np.asarray(tags, dtype=np.int64), np.asarray(coords).reshape(-1, 3), cells


def _nodes_on(dim, entity_tags):
    """Tags of the nodes on the given entities, their bounding points and curves included."""
    found = [gmsh.model.mesh.getNodes(dim, tag, includeBoundary=True,
                                        returnParametricCoord=False)[0] for tag in entity_tags]
    return np.unique(np.concatenate(found).astype(np.int64))


def _compact(tags, coords, cells, dim):
    """Drop nodes no cell uses; renumber the rest 0..n-1 in gmsh's tag order.

    Returns (points, cells as 0-based indices, gmsh tags of the kept points).
    """
    order = np.argsort(tags)
    tags, coords = tags[order], coords[order]
    used = np.unique(cells)
    points = coords[np.searchsorted(tags, used)].copy()
    if dim == 2:
        assert np.abs(points[:, 2]).max() < 1e-12, "2D mesh is not in the plane z = 0"
        points[:, 2] = 0.0
    return points, np.searchsorted(used, cells), used


def signed_measures(points, cells, dim):
    """Signed areas (2D, counter-clockwise > 0) or volumes (3D, VTK convention > 0) of the cells."""
    p = points[cells]
    e1, e2 = p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]
    if dim == 2:
        return 0.5 * (e1[:, 0] * e2[:, 1] - e1[:, 1] * e2[:, 0])
    return np.einsum("ij,ij->i", np.cross(e1, e2), p[:, 3] - p[:, 0]) / 6.0


def _orient(points, cells, dim):
    """Swap two vertices of every negatively oriented cell; assert all cells are then positive."""
    cells = cells.copy()
    flip = signed_measures(points, cells, dim) < 0
    cells[np.ix_(flip, [1, 2])] = cells[np.ix_(flip, [2, 1])]
    assert (signed_measures(points, cells, dim) > 0).all(), "degenerate cell in the mesh"
    return cells


def _markers(used, static_tags, moving_tags):
    """BoundaryMarker values of the kept points, from the gmsh entities the nodes lie on."""
    marker = np.full(len(used), INTERIOR, dtype=np.int32)
    is_static, is_moving = np.isin(used, static_tags), np.isin(used, moving_tags)
    assert not (is_static & is_moving).any(), "a node is on both the static and moving boundary"
    marker[is_static], marker[is_moving] = STATIC, MOVING
    return marker


def _check_markers(cells, marker, dim):
    """Assert that the marked nodes are exactly the nodes of the mesh's boundary facets."""
    corners = range(dim + 1)
    facets = np.concatenate([np.delete(cells, k, axis=1) for k in corners])
    facets = np.sort(facets, axis=1)
    unique, counts = np.unique(facets, axis=0, return_counts=True)
    assert counts.max() <= 2, "non-manifold mesh"
    on_boundary = np.zeros(len(marker), dtype=bool)
    on_boundary[unique[counts == 1].ravel()] = True
    assert (on_boundary == (marker != INTERIOR)).all(), "markers differ from the mesh boundary"


def to_unstructured_grid(points, cells, marker, dim):
    """Build the vtkUnstructuredGrid with its two point arrays."""
    grid = vtkUnstructuredGrid()
    vtk_points = vtkPoints()
    vtk_points.SetData(numpy_to_vtk(points, deep=1, array_type=VTK_DOUBLE))
    grid.SetPoints(vtk_points)
    n = dim + 1
    offsets = np.arange(0, n * len(cells) + 1, n, dtype=np.int64)
    cell_array = vtkCellArray()
    cell_array.SetData(numpy_to_vtkIdTypeArray(offsets, deep=1),
                       numpy_to_vtkIdTypeArray(cells.ravel().astype(np.int64), deep=1))
    grid.SetCells(_VTK_CELL_TYPE[dim], cell_array)
    grid.GetPointData().AddArray(_named(numpy_to_vtk(marker, deep=1, array_type=VTK_INT),
                                        MARKER_ARRAY))
    zeros = np.zeros((len(points), 3))
    grid.GetPointData().AddArray(_named(numpy_to_vtk(zeros, deep=1, array_type=VTK_DOUBLE),
                                        DISPLACEMENT_ARRAY))
    return grid


def _named(array, name):
    """Set a VTK array's name and return it."""
    array.SetName(name)
    return array


def write_and_check(grid, path):
    """Write inline binary (zlib) XML, read it back, assert the counts survived."""
    writer = vtkXMLUnstructuredGridWriter()
    writer.SetFileName(path)
    writer.SetInputData(grid)
    writer.SetDataModeToBinary()
    writer.SetCompressorTypeToZLib()
    assert writer.Write() == 1, f"could not write {path}"
    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    back = reader.GetOutput()
    counts = (back.GetNumberOfPoints(), back.GetNumberOfCells())
    expected = (grid.GetNumberOfPoints(), grid.GetNumberOfCells())
    assert counts == expected, f"{path}: read back {counts} points/cells, wrote {expected}"
    assert back.GetPointData().GetArray(MARKER_ARRAY) is not None, f"{path}: {MARKER_ARRAY} lost"


def print_summary(path, grid):
    """One line: nodes, cells and static/moving boundary nodes."""
    values = vtk_to_numpy(grid.GetPointData().GetArray(MARKER_ARRAY))
    print(f"{path}: {grid.GetNumberOfPoints()} nodes, {grid.GetNumberOfCells()} cells, "
          f"boundary nodes {np.count_nonzero(values == STATIC)} static / "
          f"{np.count_nonzero(values == MOVING)} moving")
