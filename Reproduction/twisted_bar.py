"""Paper Fig. 12, 13, 14 and Table 2: the twisted bar (Data/twisted_bar.vtu).

Shape deformation: the bar's boundary is lifted by the bump dy(x) for |x| < 4 (0 elsewhere),
- form "paper" (default): dy = A exp(-1 / (1 - (x/4)^2)), the paper's printed formula, peak A/e;
- form "method": dy = A exp(1 - 1 / (1 - (x/4)^2)), METHOD.md's version, peak A.
Methods: RBF, DGM, DGRBF and DGMF2 get the bump at the moving boundary nodes only (array
BumpBoundary, zero elsewhere) and interpolate it; DGMF1 gets it evaluated at every node (array
BumpField, DeformationMode 1), as the paper's DGMF1 does.

With rotation (Table 2, Fig. 14): the bar is twisted, then rotated by 45 degrees about its centre
(the origin) in the paper's (clockwise) sense. The rigid part goes to RotationAngles; the shape
part is the bump turned with the bar, R d, so the boundary ends at c + R (x + d - c). DGMF scales
the angle and R d by f; the other methods interpolate the total boundary motion.

Writes fig12_twisted_bar_<form>.csv (no rotation) and table2_twisted_bar_<form>.csv (45 degrees),
both for A in 4, 8, 16, 32 (with the rotation also A = 0); table2_rbf_support.csv (RBF with
compact support radii, paper form); with --fine-mesh, bar_fine_mesh.csv (the same sweeps on a
finer, uncommitted mesh); and, for the chosen form, the pictures fig13_bar_A16_<method>.png and fig14_bar_A16_rot45_<method>.png.
Usage: pvpython twisted_bar.py [--form paper|method] [--fine-mesh FILE.vtu] ...
"""
import os
import sys

import numpy as np

sys.dont_write_bytecode = True
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import dgmfrun  # noqa: E402

AMPLITUDES = (4, 8, 16, 32)
PICTURE_AMPLITUDE = 16
ROTATION = 45.0
# (label, Method, DeformationMode, displacement array)
METHODS = [("RBF", "RBF", 2, "BumpBoundary"), ("DGM", "DGM", 2, "BumpBoundary"),
           ("DGRBF", "DGRBF", 2, "BumpBoundary"), ("DGMF1", "DGMF", 1, "BumpField"),
           ("DGMF2", "DGMF", 2, "BumpBoundary")]
FORMS = ("paper", "method")
SUPPORT_RADII = (0.0, 40.0, 20.0, 10.0, 5.0)  # 0: the filter's automatic (global) support
COLUMNS = ["form", "method", "A", "rotation", "mean", "minimum", "inverted"]


def bump(x, amplitude, form="paper"):
    """The bump's vertical displacement at abscissae x (0 for |x| >= 4)."""
    s2 = np.minimum((np.asarray(x) / 4.0) ** 2, 1.0)
    inside = s2 < 1.0
    exponent = -1.0 / np.where(inside, 1.0 - s2, 1.0) + (1.0 if form == "method" else 0.0)
    return np.where(inside, amplitude * np.exp(exponent), 0.0)


def set_bump(grid, amplitude, form, angle):
    """Set BumpField (every node) and BumpBoundary (moving nodes) to R(angle) (0, dy(x), 0)."""
    points = dgmfrun.points_of(grid)
    local = np.zeros_like(points)
    local[:, 1] = bump(points[:, 0], amplitude, form)
    field = local @ dgmfrun.rotation_z(angle).T
    boundary = np.where((dgmfrun.marker_of(grid) == dgmfrun.MOVING)[:, None], field, 0.0)
    dgmfrun.set_point_vectors(grid, "BumpField", field)
    dgmfrun.set_point_vectors(grid, "BumpBoundary", boundary)


def run_case(deform, grid, amplitude, form, paper_angle):
    """All five methods for one amplitude and rotation; one row each."""
    angle = dgmfrun.PAPER_SENSE * paper_angle
    set_bump(grid, amplitude, form, angle)
    rows = []
    for label, method, mode, array in METHODS:
        result = dgmfrun.run(deform, method, angle=angle, displacement=array, mode=mode)
        rows.append(dict(result, method=label, A=amplitude, rotation=paper_angle, form=form))
    return rows


def sweep(deform, grid, form, paper_angle):
    """The undeformed mesh (method "undeformed", A = 0), then run_case for every amplitude, and
    with a rotation also for A = 0 (the rotation alone)."""
    set_bump(grid, 0.0, form, 0.0)
    rows = [dict(dgmfrun.run(deform, "DGMF"), method="undeformed", A=0, rotation=0.0, form=form)]
    amplitudes = ((0,) if paper_angle else ()) + AMPLITUDES
    return rows + [row for amplitude in amplitudes
                   for row in run_case(deform, grid, amplitude, form, paper_angle)]


def rbf_support(deform, grid):
    """Table 2's RBF (paper form, 45 degrees) for A = 4 and 16 and several support radii."""
    rows = []
    angle = dgmfrun.PAPER_SENSE * ROTATION
    for amplitude in (4, 16):
        set_bump(grid, amplitude, "paper", angle)
        for radius in SUPPORT_RADII:
            deform.SupportRadius = radius
            result = dgmfrun.run(deform, "RBF", angle=angle, displacement="BumpBoundary")
            rows.append(dict(result, A=amplitude, support_radius=radius or "auto"))
    deform.SupportRadius = 0.0
    return rows


def fine_mesh(path):
    """The sweeps (paper form, without and with rotation) on another mesh of the same case."""
    grid = dgmfrun.read_grid(path)
    set_bump(grid, 0.0, "paper", 0.0)
    deform = dgmfrun.deform_filter(dgmfrun.producer(grid))
    rows = sweep(deform, grid, "paper", 0.0) + sweep(deform, grid, "paper", ROTATION)
    for row in rows:
        row.update(points=grid.GetNumberOfPoints(), cells=grid.GetNumberOfCells())
    return rows


def pictures(deform, grid, form, output):
    """Figs. 13 and 14: the five methods at A = 16, without and with the rotation."""
    peak = float(bump(0.0, PICTURE_AMPLITUDE, form))
    for paper_angle, name in ((0.0, "fig13_bar_A16"), (ROTATION, "fig14_bar_A16_rot45")):
        angle = dgmfrun.PAPER_SENSE * paper_angle
        set_bump(grid, PICTURE_AMPLITUDE, form, angle)
        centre = dgmfrun.rotation_z(angle) @ np.array([0.0, 0.5 * peak, 0.0])
        for label, method, mode, array in METHODS:
            result = dgmfrun.run(deform, method, angle=angle, displacement=array, mode=mode)
            title = (f"bar, A = {PICTURE_AMPLITUDE}{', 45 deg' if paper_angle else ''}, "
                     f"{label}: mean {result['mean']:.3f}, min {result['minimum']:.3f}, "
                     f"{result['inverted']} inverted")
            path = os.path.join(output, f"{name}_{label.lower()}.png")
            dgmfrun.render_quality(deform, path, centre[:2], 0.5 * peak + 5.0, title)


def main():
    """Sweep A for each bump form, with and without the rotation; pictures for the default form."""
    parser = dgmfrun.parser(__doc__)
    parser.add_argument("--form", choices=FORMS, default="paper",
                        help="bump form for the pictures (CSV files are written for both)")
    parser.add_argument("--fine-mesh", help="a finer twisted-bar mesh for bar_fine_mesh.csv")
    args = parser.parse_args()
    dgmfrun.load_plugin(args.plugin)
    grid = dgmfrun.read_case("twisted_bar", args.data)
    set_bump(grid, 0.0, "paper", 0.0)  # create the arrays before the pipeline sees the grid
    deform = dgmfrun.deform_filter(dgmfrun.producer(grid))
    for form in FORMS:
        for paper_angle, name in ((0.0, "fig12_twisted_bar"), (ROTATION, "table2_twisted_bar")):
            rows = sweep(deform, grid, form, paper_angle)
            dgmfrun.write_csv(os.path.join(args.output, f"{name}_{form}.csv"), rows, COLUMNS)
    dgmfrun.write_csv(os.path.join(args.output, "table2_rbf_support.csv"),
                      rbf_support(deform, grid),
                      ["A", "support_radius", "mean", "minimum", "inverted"])
    if args.fine_mesh:
        dgmfrun.write_csv(os.path.join(args.output, "bar_fine_mesh.csv"), fine_mesh(args.fine_mesh),
                          ["points", "cells"] + COLUMNS)
    if not args.no_pictures:
        pictures(deform, grid, args.form, args.output)


if __name__ == "__main__":
    main()
