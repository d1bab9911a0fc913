"""Paper Section 3.2: the rotating circle turned by 90 degrees. DGM produces inverted cells, DGMF
(u1, r0s = 1) none. Usage: pvpython test_circle_90.py [--plugin DGMFPlugin.so] [--data DIR]
"""
import os
import sys

sys.dont_write_bytecode = True
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                "Reproduction"))
import dgmfrun  # noqa: E402


def main():
    """Run DGM and DGMF on the circle at 90 degrees; exit non-zero if the claim fails."""
    args = dgmfrun.parser(__doc__).parse_args()
    dgmfrun.load_plugin(args.plugin)
    grid = dgmfrun.read_case("rotating_circle", args.data)  # asserts 822 points, 1529 cells
    deform = dgmfrun.deform_filter(dgmfrun.producer(grid))
    results = {method: dgmfrun.run(deform, method, angle=dgmfrun.PAPER_SENSE * 90.0)
               for method in ("DGM", "DGMF")}
    for method, result in results.items():
        print(f"{method}: mean {result['mean']:.4f}, minimum {result['minimum']:.4f}, "
              f"{result['inverted']} inverted cells")
    assert results["DGM"]["inverted"] > 0, "DGM gave no inverted cells at 90 degrees"
    assert results["DGMF"]["inverted"] == 0, "DGMF gave inverted cells at 90 degrees"
    assert results["DGMF"]["minimum"] > 0.0
    print("circle 90 OK")


if __name__ == "__main__":
    main()
