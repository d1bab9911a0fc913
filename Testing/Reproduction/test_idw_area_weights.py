"""IDW on a 3D mesh weighs each boundary node by the boundary area it represents (A_i of
Documentation/methods/idw.md). Until commit 6bddefb the filter found no boundary face of a 3D
unstructured grid (VTK 9.2's vtkGeometryFilter passes the points through without an original-id
array) and silently gave every node A_i = 1; the wing fold's IDW result changed when that was
fixed. Here the plugin's IDW on Data/sphere_in_box.vtu (a shape motion of the sphere) must equal
a numpy evaluation of the documented formula with the area weights, and differ from the one with
A_i = 1. Usage: pvpython test_idw_area_weights.py [--plugin DGMFPlugin.so] [--data DIR]
"""
import os
import sys

import numpy as np

sys.dont_write_bytecode = True
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                "Reproduction"))
import dgmfrun  # noqa: E402
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402

ALPHA, A, B = 5.0, 3.0, 5.0  # the filter's defaults (IDWAlpha; a and b are fixed)


def tetrahedra(grid):
    """The cells as an (n, 4) array of point ids (the mesh holds tetrahedra only)."""
    cells = grid.GetCells()
    offsets = vtk_to_numpy(cells.GetOffsetsArray())
    assert (np.diff(offsets) == 4).all(), "expected tetrahedra only"
    return vtk_to_numpy(cells.GetConnectivityArray()).reshape(-1, 4)


def area_weights(points, tets):
    """Each node's share of the boundary area: the faces used by one tetrahedron, a third of each
    face's area to each of its nodes."""
    faces = np.concatenate([tets[:, [0, 1, 2]], tets[:, [0, 1, 3]], tets[:, [0, 2, 3]],
                            tets[:, [1, 2, 3]]])
    unique, counts = np.unique(np.sort(faces, axis=1), axis=0, return_counts=True)
    boundary = unique[counts == 1]
    p = points[boundary]
    area = 0.5 * np.linalg.norm(np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), axis=1)
    weights = np.zeros(len(points))
    for k in range(3):
        np.add.at(weights, boundary[:, k], area / 3.0)
    return weights


def idw(points, sources, displacement, weights):
    """The documented IDW: s(x) = sum w_i s_i / sum w_i, w_i = A_i [(L/d)^a + (alpha L/d)^b],
    L the largest distance of a boundary node from their centroid."""
    L = np.sqrt(((sources - sources.mean(axis=0)) ** 2).sum(axis=1).max())
    weights = weights / weights.max()
    result = np.empty_like(points)
    for start in range(0, len(points), 256):
        d = np.sqrt(((points[start:start + 256, None, :] - sources[None]) ** 2).sum(axis=2))
        with np.errstate(divide="ignore"):
            t = L / d
        w = weights * (t ** A + (ALPHA * t) ** B)
        exact = ~np.isfinite(w)
        w = np.where(exact.any(axis=1)[:, None], exact.astype(float), w)  # a boundary node
        result[start:start + 256] = w @ displacement / w.sum(axis=1)[:, None]
    return points + result


def main():
    """Compare the plugin's IDW with the formula, with and without the area weights."""
    args = dgmfrun.parser(__doc__).parse_args()
    dgmfrun.load_plugin(args.plugin)
    grid = dgmfrun.read_grid(os.path.join(args.data, "sphere_in_box.vtu"), 3200, 15892)
    points = dgmfrun.points_of(grid).astype(float)
    marker = dgmfrun.marker_of(grid)
    # A shape motion of the sphere: its nodes rise in proportion to x (up to 0.3 at x = 1).
    displacement = np.zeros_like(points)
    displacement[marker == dgmfrun.MOVING, 2] = 0.3 * points[marker == dgmfrun.MOVING, 0]
    dgmfrun.set_point_vectors(grid, "Shape", displacement)
    deform = dgmfrun.deform_filter(dgmfrun.producer(grid))
    deform.ComputeQuality = 0
    dgmfrun.configure(deform, "IDW", displacement="Shape")
    output = dgmfrun.execute(deform)[0]
    ours = vtk_to_numpy(output.GetPoints().GetData()).astype(float)

    on_boundary = marker > 0
    sources, moved = points[on_boundary], displacement[on_boundary]
    weights = area_weights(points, tetrahedra(grid))[on_boundary]
    assert (weights > 0).all(), "a marked node is on no boundary face"
    with_areas = idw(points, sources, moved, weights)
    uniform = idw(points, sources, moved, np.ones(len(sources)))
    error = np.abs(ours - with_areas).max()
    spread = np.abs(uniform - with_areas).max()
    print(f"largest difference from the formula with area weights {error:.3g}, "
          f"with A_i = 1 {np.abs(ours - uniform).max():.3g} (the two formulas differ by "
          f"{spread:.3g})")
    assert spread > 1e-3, "the test mesh does not tell the weights apart"
    assert error < 1e-12, "IDW does not use the boundary-area weights A_i"
    print("IDW area weights OK")


if __name__ == "__main__":
    main()
