"""The committed wing-fold qualities (Documentation/results/wing_fold_quality.csv) are what this
build computes: every method of Reproduction/wing_fold.py is run again on the cached wing-body
mesh and its mean and minimum SizeSkew (to the CSV's 6 significant digits) and inverted cells are
compared with the committed row. The results are deterministic (no thread count or machine
changes them); a difference means the code changed a result and Documentation/results was not
regenerated (scripts/reproduce.sh). Exit code 77 (ctest: skipped) when the mesh is not cached
(scripts/reproduce.sh or Data/generators/wing_body.py makes it; 3 minutes, 3 GB).
Usage: pvpython test_wing_fold_current.py [--plugin DGMFPlugin.so] [--mesh FILE.vtu]
                                          [--results DIR] [--methods NAME,...]
"""
import csv
import os
import sys

sys.dont_write_bytecode = True
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                "Reproduction"))
import dgmfrun  # noqa: E402
import wing_fold  # noqa: E402

SKIP = 77


def committed_rows(results):
    """The committed quality rows by method."""
    with open(os.path.join(results, "wing_fold_quality.csv")) as stream:
        return {row["method"]: row for row in csv.DictReader(stream)}


def differences(label, fresh, committed):
    """Descriptions of the values of a fresh run that differ from the committed row."""
    found = []
    for key in ("mean", "minimum"):
        if f"{fresh[key]:.6g}" != f"{float(committed[key]):.6g}":
            found.append(f"{label} {key}: computed {fresh[key]:.6g}, committed {committed[key]}")
    if fresh["inverted"] != int(committed["inverted"]):
        found.append(f"{label} inverted: computed {fresh['inverted']}, committed "
                     f"{committed['inverted']}")
    return found


def main():
    """Run the wing fold's methods and compare with the committed CSV; exit 1 on a difference."""
    parser = dgmfrun.parser(__doc__)
    parser.add_argument("--mesh", default=wing_fold.default_mesh(), help="cached wing-body .vtu")
    parser.add_argument("--results", default=dgmfrun.RESULTS, help="the committed results")
    parser.add_argument("--methods", default=None,
                        help="comma-separated labels to check (default: all of wing_fold.py)")
    args = parser.parse_args()
    if not (os.path.exists(args.mesh) and os.path.exists(args.mesh + ".json")):
        print(f"{args.mesh}: not generated (scripts/reproduce.sh makes it): skipped")
        return SKIP
    committed = committed_rows(args.results)
    methods = [m for m in wing_fold.METHODS
               if args.methods is None or m[0] in args.methods.split(",")]
    dgmfrun.load_plugin(args.plugin)
    grid = wing_fold.read_mesh(args.mesh)
    wing_fold.set_fold(grid, 30, "30")
    deform = dgmfrun.deform_filter(dgmfrun.producer(grid))
    found = []
    for row in wing_fold.qualities(deform, methods):
        found += differences(row["method"], row, committed[row["method"]])
    for line in found:
        print("DIFFERS: " + line)
    if found:
        print("the committed wing-fold results are not this build's: run scripts/reproduce.sh")
        return 1
    print(f"wing fold current: {', '.join(m[0] for m in methods)} as committed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
