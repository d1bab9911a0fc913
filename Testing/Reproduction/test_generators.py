"""The 2D mesh generators are deterministic: two runs give the same points, cells and arrays
(compared as arrays, not bytes), with the committed point and cell counts. With --committed, one
run instead, which must equal the committed file in Data/; exit code 77 (ctest: skipped) when it
differs and the gmsh version is not the one that made the committed files, since another gmsh may
give another, equally valid mesh.

Usage: pvpython test_generators.py --pvpython PVPYTHON [--committed] [--work DIR] [CASE ...]
"""
import argparse
import os
import subprocess
import sys
import tempfile

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy

sys.dont_write_bytecode = True
HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(ROOT, "Reproduction"))
import dgmfrun  # noqa: E402

COMMITTED_GMSH = "4.8.0"  # gmsh.__version__ of Debian 12's python3-gmsh 4.8.4+ds2-3
SKIP = 77


def generate(pvpython, case, path):
    """Run Data/generators/<case>.py into path."""
    script = os.path.join(ROOT, "Data", "generators", case + ".py")
    subprocess.run([pvpython, script, path], check=True, stdout=subprocess.DEVNULL)


def contents(grid):
    """Points, connectivity, offsets, cell types and every point array, as numpy arrays."""
    cells = grid.GetCells()
    result = {"points": vtk_to_numpy(grid.GetPoints().GetData()),
              "connectivity": vtk_to_numpy(cells.GetConnectivityArray()),
              "offsets": vtk_to_numpy(cells.GetOffsetsArray()),
              "types": vtk_to_numpy(grid.GetCellTypesArray())}
    data = grid.GetPointData()
    for i in range(data.GetNumberOfArrays()):
        result["point array " + data.GetArrayName(i)] = vtk_to_numpy(data.GetArray(i))
    return result


def differences(a, b):
    """Names of the entries that differ between two contents() dicts."""
    return sorted(k for k in a.keys() | b.keys()
                  if k not in a or k not in b or a[k].shape != b[k].shape
                  or not np.array_equal(a[k], b[k]))


def check_twice(pvpython, case, work):
    """Generate the case twice; assert both runs are identical and have the committed counts."""
    paths = [os.path.join(work, f"{case}_{run}.vtu") for run in (1, 2)]
    for path in paths:
        generate(pvpython, case, path)
    first, second = (contents(dgmfrun.read_grid(path, *dgmfrun.MESHES[case])) for path in paths)
    diff = differences(first, second)
    assert not diff, f"{case}: the two runs differ in {diff}"
    print(f"{case}: two runs identical ({len(first['points'])} points, "
          f"{len(first['types'])} cells)")


def check_committed(pvpython, case, work):
    """Generate the case once; True if equal to Data/<case>.vtu, False if skipped."""
    import gmsh
    path = os.path.join(work, case + ".vtu")
    generate(pvpython, case, path)
    fresh = contents(dgmfrun.read_grid(path))
    diff = differences(fresh, contents(dgmfrun.read_case(case, dgmfrun.DATA)))  # counts asserted
    if diff and gmsh.__version__ != COMMITTED_GMSH:
        print(f"{case}: differs from Data/ in {diff} with gmsh {gmsh.__version__} "
              f"(committed files: gmsh {COMMITTED_GMSH}): skipped")
        return False
    assert not diff, f"{case}: differs from Data/{case}.vtu in {diff}"
    print(f"{case}: equal to Data/{case}.vtu")
    return True


def main():
    """Check each case; exit 77 if a comparison with Data/ had to be skipped."""
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("cases", nargs="*", default=sorted(dgmfrun.MESHES))
    parser.add_argument("--pvpython", required=True, help="pvpython (runs the generators)")
    parser.add_argument("--committed", action="store_true", help="compare with Data/<case>.vtu")
    parser.add_argument("--work", help="folder for the generated files (default: a temporary one)")
    args = parser.parse_args()
    complete = True
    with tempfile.TemporaryDirectory(dir=args.work) as work:
        for case in args.cases:
            if args.committed:
                complete &= check_committed(args.pvpython, case, work)
            else:
                check_twice(args.pvpython, case, work)
    if not complete:
        sys.exit(SKIP)
    print("generators OK")


if __name__ == "__main__":
    main()
