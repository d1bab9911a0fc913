"""Paper Table 2: the twisted bar with the bump (A = 16 by default, the paper's printed form) and
the 45-degree rotation.

The paper claims that DGMF's minimum SizeSkew (DGMF1 and DGMF2) is above RBF's and DGM's. On our
mesh it is not (every method's minimum is about 0; see Documentation/results/README.md), and that
part is printed, not asserted. What is asserted is the part of Table 2 that holds here: DGMF1 and
DGMF2 have the best mean SizeSkew of the five methods, and invert far fewer cells than DGM.
Usage: pvpython test_bar_rotation.py [--amplitude A] [--form paper|method] ...
"""
import os
import sys

sys.dont_write_bytecode = True
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                "Reproduction"))
import dgmfrun  # noqa: E402
import twisted_bar  # noqa: E402


def main():
    """Run the five methods; exit non-zero if DGMF's mean is not the best or it inverts as much as DGM."""
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
    mean = {row["method"]: row["mean"] for row in rows}
    inverted = {row["method"]: row["inverted"] for row in rows}
    for row in rows:
        print(f"{row['method']}: mean {row['mean']:.4f}, minimum {row['minimum']:.4f}, "
              f"{row['inverted']} inverted cells")
    # The paper's minimum claim, reported only (it does not hold on this mesh).
    for dgmf in ("DGMF1", "DGMF2"):
        for other in ("RBF", "DGM"):
            print(f"paper's claim {dgmf} minimum > {other} minimum: "
                  f"{'holds' if minimum[dgmf] > minimum[other] else 'does not hold'}")
    failed = [f"{dgmf} mean <= {other} mean" for dgmf in ("DGMF1", "DGMF2")
              for other in ("RBF", "DGM", "DGRBF") if not mean[dgmf] > mean[other]]
    failed += [f"{dgmf} inverts {inverted[dgmf]} cells, DGM {inverted['DGM']}"
               for dgmf in ("DGMF1", "DGMF2") if not 10 * inverted[dgmf] < inverted["DGM"]]
    assert not failed, "; ".join(failed)
    print("bar rotation OK")


if __name__ == "__main__":
    main()
