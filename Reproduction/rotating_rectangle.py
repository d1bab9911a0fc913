"""Paper Fig. 4, 5 and 6: the rotating rectangle (Data/rotating_rectangle.vtu) turned about its
centre by 10 to 90 degrees (0: the undeformed mesh); mean and minimum SizeSkew for DGMF with
u1..u6 and for DGM.

Writes fig4_rectangle.csv and the quality pictures fig5_rectangle_90_dgmf.png (DGMF u1) and
fig6_rectangle_90_dgm.png (DGM). Usage: pvpython rotating_rectangle.py [--output DIR] ...
"""
import os
import sys

sys.dont_write_bytecode = True
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import dgmfrun  # noqa: E402

ANGLES = range(0, 100, 10)  # 0: the undeformed mesh
CASES = [("DGMF", u) for u in range(1, 7)] + [("DGM", None)]


def label(method, damping):
    """Column label: DGMF-u1 ... DGMF-u6, DGM."""
    return f"{method}-u{damping}" if damping else method


def sweep(deform):
    """One row per (case, angle)."""
    rows = []
    for method, damping in CASES:
        for angle in ANGLES:
            result = dgmfrun.run(deform, method, angle=dgmfrun.PAPER_SENSE * angle,
                                 damping=damping or 1)
            rows.append(dict(result, case=label(method, damping), angle=angle))
    return rows


def pictures(deform, output):
    """Figs. 5 and 6: the mesh around the rectangle after 90 degrees, DGMF (u1) and DGM."""
    for method, name in (("DGMF", "fig5_rectangle_90_dgmf.png"),
                         ("DGM", "fig6_rectangle_90_dgm.png")):
        result = dgmfrun.run(deform, method, angle=dgmfrun.PAPER_SENSE * 90)
        title = (f"rectangle, 90 deg, {method}{' (u1)' if method == 'DGMF' else ''}: "
                 f"mean {result['mean']:.3f}, min {result['minimum']:.3f}, "
                 f"{result['inverted']} inverted")
        dgmfrun.render_quality(deform, os.path.join(output, name), (0.0, 0.0), 5.2, title)


def main():
    """Run the sweep, write the CSV and the pictures."""
    args = dgmfrun.parser(__doc__).parse_args()
    dgmfrun.load_plugin(args.plugin)
    grid = dgmfrun.read_case("rotating_rectangle", args.data)
    deform = dgmfrun.deform_filter(dgmfrun.producer(grid))
    rows = sweep(deform)
    dgmfrun.write_csv(os.path.join(args.output, "fig4_rectangle.csv"), rows,
                      ["case", "angle", "mean", "minimum", "inverted"])
    if not args.no_pictures:
        pictures(deform, args.output)


if __name__ == "__main__":
    main()
