"""Paper Table 2: the twisted bar with the bump (A = 16 by default, the paper's printed form) and
the 45-degree rotation. The paper's claim: DGMF's minimum SizeSkew (DGMF1 and DGMF2) is above
RBF's and DGM's. Usage: pvpython test_bar_rotation.py [--amplitude A] [--form paper|method] ...
"""
import os
import sys

sys.dont_write_bytecode = True
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                "Reproduction"))
import dgmfrun  # noqa: E402
import twisted_bar  # noqa: E402


def main():
    """Run the five methods; exit non-zero if a DGMF minimum is not above RBF's and DGM's."""
    parser = dgmfrun.parser(__doc__)
    parser.add_argument("--amplitude", type=float, default=16.0)
    parser.add_argument("--form", choices=twisted_bar.FORMS, default="paper")
    args = parser.parse_args()
    dgmfrun.load_plugin(args.plugin)
    grid = dgmfrun.read_case("twisted_bar", args.data)  # asserts 2232 points, 4154 cells
    twisted_bar.set_bump(grid, 0.0, args.form, 0.0)
    deform = dgmfrun.deform_filter(dgmfrun.producer(grid))
    rows = twisted_bar.run_case(deform, grid, args.amplitude, args.form, twisted_bar.ROTATION)
    minimum = {row["method"]: row["minimum"] for row in rows}
    for row in rows:
        print(f"{row['method']}: mean {row['mean']:.4f}, minimum {row['minimum']:.4f}, "
              f"{row['inverted']} inverted cells")
    failed = [f"{dgmf} <= {other}" for dgmf in ("DGMF1", "DGMF2") for other in ("RBF", "DGM")
              if not minimum[dgmf] > minimum[other]]
    assert not failed, "minimum SizeSkew: " + ", ".join(failed)
    print("bar rotation OK")


if __name__ == "__main__":
    main()
