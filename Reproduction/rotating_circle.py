"""Paper Fig. 8 and 9: the rotating circle (Data/rotating_circle.vtu: radius 1 in a square of side
10) turned about its centre by 10 to 90 degrees (0: the undeformed mesh); mean and minimum SizeSkew
for DGMF (u1), DGM and RBF (the paper's three), and DGRBF and IDW as well.

Writes fig8_circle.csv and the quality pictures fig9_circle_90_<method>.png.
Usage: pvpython rotating_circle.py [--output DIR] ...
"""
import os
import sys

sys.dont_write_bytecode = True
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import dgmfrun  # noqa: E402

ANGLES = range(0, 100, 10)  # 0: the undeformed mesh
METHODS = ["DGMF", "DGM", "RBF", "DGRBF", "IDW"]
PICTURES = ["DGMF", "DGM", "RBF"]


def sweep(deform):
    """One row per (method, angle)."""
    return [dict(dgmfrun.run(deform, method, angle=dgmfrun.PAPER_SENSE * angle),
                 method=method, angle=angle)
            for method in METHODS for angle in ANGLES]


def pictures(deform, output):
    """Fig. 9 (DGMF after 90 degrees), and the same for DGM and RBF."""
    for method in PICTURES:
        result = dgmfrun.run(deform, method, angle=dgmfrun.PAPER_SENSE * 90)
        title = (f"circle, 90 deg, {method}: mean {result['mean']:.3f}, "
                 f"min {result['minimum']:.3f}, {result['inverted']} inverted")
        path = os.path.join(output, f"fig9_circle_90_{method.lower()}.png")
        dgmfrun.render_quality(deform, path, (0.0, 0.0), 5.2, title)


def main():
    """Run the sweep, write the CSV and the pictures."""
    args = dgmfrun.parser(__doc__).parse_args()
    dgmfrun.load_plugin(args.plugin)
    grid = dgmfrun.read_case("rotating_circle", args.data)
    deform = dgmfrun.deform_filter(dgmfrun.producer(grid))
    rows = sweep(deform)
    dgmfrun.write_csv(os.path.join(args.output, "fig8_circle.csv"), rows,
                      ["method", "angle", "mean", "minimum", "inverted"])
    if not args.no_pictures:
        pictures(deform, args.output)


if __name__ == "__main__":
    main()
