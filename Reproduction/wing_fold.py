"""Paper Section 3.4 (Figs. 15, 16): the wing-body mesh (Data/generators/wing_body.py, cached)
with the wing folded by the paper's "30 degrees" (METHOD.md's reading of the mangled formula):

    dz = 0                 for y < 200
    dz = (y - 200) sin30   for 200 <= y <= 500
    dz = 300 sin30 = 150   for y > 500

DGMF1 gets dz at every node (array FoldField; the filter scales it by f), the other methods at the
moving boundary nodes only (array FoldBoundary) and interpolate it.

Timing (one thread, quality off, wall clock and CPU time of the filter's own Update): for each
method a fresh filter runs once (graph + location + mapping), then with a changed motion (a fold
of 15 degrees: mapping only, the graph and the locations are cached), then 30 degrees again;
the best of 3 repeats is kept (IDW, about a minute per run: one run, the first).
Quality: mean and minimum SizeSkew, inverted cells (all threads).

Writes <prefix>_time.csv, <prefix>_quality.csv, and the pictures fig15_<prefix>_surface.png (the
deformed body) and fig16_<prefix>_slice_<method>.png (the cells cut by the plane x = 200, coloured
by SizeSkew); the prefix is wing_fold unless --prefix says otherwise.
Usage: pvpython wing_fold.py [--mesh FILE.vtu] [--prefix NAME] [--skip-idw] ...
"""
import json
import math
import os
import sys

import numpy as np

sys.dont_write_bytecode = True
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import dgmfrun  # noqa: E402
from paraview import simple  # noqa: E402

FOLD_START, FOLD_END = 200.0, 500.0
# (label, Method, DeformationMode, array prefix)
METHODS = [("DGM", "DGM", 2, "FoldBoundary"), ("DGMF1", "DGMF", 1, "FoldField"),
           ("DGMF2", "DGMF", 2, "FoldBoundary"), ("DGRBF", "DGRBF", 2, "FoldBoundary"),
           ("IDW", "IDW", 2, "FoldBoundary")]
SLICE_X = 200.0


def default_mesh():
    """The generator's cache path: ${XDG_CACHE_HOME:-$HOME/.cache}/dgmf/wing_body.vtu."""
    cache = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return os.path.join(cache, "dgmf", "wing_body.vtu")


def fold(y, degrees=30.0):
    """The fold's z displacement at span positions y."""
    span = np.clip(np.asarray(y) - FOLD_START, 0.0, FOLD_END - FOLD_START)
    return span * math.sin(math.radians(degrees))


def set_fold(grid, degrees, suffix):
    """Add FoldField<suffix> (every node) and FoldBoundary<suffix> (moving nodes only)."""
    points = dgmfrun.points_of(grid)
    field = np.zeros_like(points)
    field[:, 2] = fold(points[:, 1], degrees)
    boundary = np.where((dgmfrun.marker_of(grid) == dgmfrun.MOVING)[:, None], field, 0.0)
    dgmfrun.set_point_vectors(grid, "FoldField" + suffix, field)
    dgmfrun.set_point_vectors(grid, "FoldBoundary" + suffix, boundary)


def read_mesh(path):
    """The wing-body grid, its counts checked against the generator's sidecar file."""
    with open(path + ".json") as stream:
        record = json.load(stream)
    return dgmfrun.read_grid(path, record["points"], record["cells"])


def timings(source, methods, repeats=3):
    """For each method, ``repeats`` times (IDW once): a fresh filter runs the 30-degree fold
    (graph + location + mapping), then a changed motion (15 degrees: mapping only, the graph and
    the locations are cached), then 30 degrees again. Rows: the best of the repeats."""
    rows = []
    runs = ("first run of a fresh filter", "changed motion (15 degrees)", "30 degrees again")
    for label, method, mode, array in methods:
        times = {run: [] for run in runs}
        for _ in range(1 if label == "IDW" else repeats):
            deform = dgmfrun.deform_filter(source, threads=1)
            deform.ComputeQuality = 0
            for run, suffix in zip(runs[:1] if label == "IDW" else runs, ("30", "15", "30")):
                dgmfrun.configure(deform, method, displacement=array + suffix, mode=mode)
                times[run].append(dgmfrun.execute(deform)[1:])
            simple.Delete(deform)
        for run, measured in times.items():
            if measured:
                wall, cpu = min(measured)
                rows.append({"method": label, "run": run, "threads": 1, "repeats": len(measured),
                             "wall": wall, "cpu": cpu})
                print(f"{label}: {run}: {wall:.3f} s (best of {len(measured)})")
    return rows


def qualities(deform, methods):
    """Mean and minimum SizeSkew and inverted cells: undeformed, then after the 30-degree fold."""
    rows = [dict(dgmfrun.run(deform, "DGMF"), method="undeformed")]
    for label, method, mode, array in methods:
        result = dgmfrun.run(deform, method, displacement=array + "30", mode=mode)
        rows.append(dict(result, method=label))
        print(f"{label}: mean {result['mean']:.4f}, minimum {result['minimum']:.4f}, "
              f"{result['inverted']} inverted")
    return rows


def pictures(deform, output, rows, prefix):
    """Fig. 15 (the folded body) and Fig. 16 (a slice x = 200 through the wing) per method."""
    by_method = {row["method"]: row for row in rows}
    slice_view = ([SLICE_X + 3000.0, 400.0, 80.0], [SLICE_X, 400.0, 80.0], [0.0, 0.0, 1.0])
    for label, method, mode, array in METHODS[:2]:
        dgmfrun.configure(deform, method, displacement=array + "30", mode=mode)
        cut = simple.Slice(Input=deform, SliceType="Plane", Crinkleslice=1)
        cut.SliceType.Origin, cut.SliceType.Normal = [SLICE_X, 0.0, 0.0], [1.0, 0.0, 0.0]
        row = by_method[label]
        title = (f"wing fold, {label}, cells cut by x = {SLICE_X:g}\n(whole mesh: mean "
                 f"{row['mean']:.3f}, min {row['minimum']:.3f}, {row['inverted']} inverted)")
        path = os.path.join(output, f"fig16_{prefix}_slice_{label.lower()}.png")
        dgmfrun.render_quality(cut, path, None, 380.0, title, camera=slice_view)
        simple.Delete(cut)
    surface_view = ([-2600.0, 1900.0, 1500.0], [150.0, 380.0, 60.0], [0.0, 0.0, 1.0])
    surface = simple.ExtractSurface(Input=deform)
    body = simple.Threshold(Input=surface, Scalars=["POINTS", dgmfrun.MARKER])
    body.LowerThreshold, body.UpperThreshold, body.AllScalars = 2, 2, 1
    row = by_method["DGMF1"]
    title = (f"wing fold, DGMF1: SizeSkew of the cells at the wall\n(whole mesh: mean "
             f"{row['mean']:.3f}, min {row['minimum']:.3f}, {row['inverted']} inverted)")
    dgmfrun.render_quality(body, os.path.join(output, f"fig15_{prefix}_surface.png"), None, 520.0,
                           title, camera=surface_view, lit=True, edges=False)
    simple.Delete(body)
    simple.Delete(surface)


def main():
    """Timings, qualities and pictures of the wing fold."""
    parser = dgmfrun.parser(__doc__)
    parser.add_argument("--mesh", default=default_mesh(),
                        help="wing-body .vtu (default: %(default)s)")
    parser.add_argument("--skip-idw", action="store_true", help="leave out IDW (the slow one)")
    parser.add_argument("--prefix", default="wing_fold", help="output names (default %(default)s)")
    args = parser.parse_args()
    methods = [m for m in METHODS if not (args.skip_idw and m[0] == "IDW")]
    dgmfrun.load_plugin(args.plugin)
    grid = read_mesh(args.mesh)
    for degrees in (30, 15):
        set_fold(grid, degrees, str(degrees))
    source = dgmfrun.producer(grid)
    time_rows = timings(source, methods)
    dgmfrun.write_csv(os.path.join(args.output, args.prefix + "_time.csv"), time_rows,
                      ["method", "run", "threads", "repeats", "wall", "cpu"])
    deform = dgmfrun.deform_filter(source)
    rows = qualities(deform, methods)
    for row in rows:
        row.update(points=grid.GetNumberOfPoints(), cells=grid.GetNumberOfCells())
    dgmfrun.write_csv(os.path.join(args.output, args.prefix + "_quality.csv"), rows,
                      ["method", "points", "cells", "mean", "minimum", "inverted"])
    if not args.no_pictures:
        pictures(deform, args.output, rows, args.prefix)


if __name__ == "__main__":
    main()
