"""Two circles of radius 0.8 centred at (-2.5, 0) and (2.5, 0) in a square of side 10, triangles,
with a BodyId point array (1 on the left circle, 2 on the right one, 0 elsewhere): the case of
several moving bodies.

Usage: pvpython two_circles.py OUTPUT.vtu [--size-min 0.08] [--size-max 0.8] [--dist-max 3]
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.dont_write_bytecode = True  # keep Data/generators free of __pycache__
import gmsh  # noqa: E402
import numpy as np  # noqa: E402
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy  # noqa: E402
from vtkmodules.util.vtkConstants import VTK_INT  # noqa: E402
import meshgen  # noqa: E402

RADIUS, CENTRE, SIDE = 0.8, 2.5, 10.0


def build_geometry():
    """The square minus the two disks."""
    occ = gmsh.model.occ
    square = occ.addRectangle(-SIDE / 2, -SIDE / 2, 0, SIDE, SIDE)
    left = occ.addDisk(-CENTRE, 0, 0, RADIUS, RADIUS)
    right = occ.addDisk(CENTRE, 0, 0, RADIUS, RADIUS)
    occ.cut([(2, square)], [(2, left), (2, right)])


def add_body_ids(grid):
    """BodyId: 1 for the moving nodes left of x = 0, 2 for those right of it, 0 elsewhere."""
    marker = vtk_to_numpy(grid.GetPointData().GetArray(meshgen.MARKER_ARRAY))
    x = vtk_to_numpy(grid.GetPoints().GetData())[:, 0]
    body = np.where(marker == 2, np.where(x < 0, 1, 2), 0).astype(np.int32)
    array = numpy_to_vtk(body, deep=1, array_type=VTK_INT)
    array.SetName("BodyId")
    grid.GetPointData().AddArray(array)


if __name__ == "__main__":
    args = meshgen.parse_args(__doc__, size_min=0.08, size_max=0.8, dist_max=3.0)
    box = CENTRE + 1.1 * RADIUS
    grid = meshgen.generate(args, 2, build_geometry, (-box, -1.1 * RADIUS, -1, box, 1.1 * RADIUS, 1))
    add_body_ids(grid)
    meshgen.write_and_check(grid, args.output)
    meshgen.print_summary(args.output, grid)
