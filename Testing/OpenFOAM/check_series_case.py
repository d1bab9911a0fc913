#!/usr/bin/env python3
"""A pitching wing written into the OpenFOAM case as a series, one time directory per time.

    check_series_case.py --deform BIN --case SRC --work DIR --baseline LOG -- OPTIONS

Runs `dgmf-deform SRC DIR/Series OPTIONS` (OPTIONS with a law and --times), then asserts:
- one time directory per time the command printed (each its own), each with a points file of the
  source's size;
- checkMesh at each of those times fails no check that the undeformed mesh (--baseline) does not;
- the wing pitches: the frames differ, and two frames a period apart are the same points;
- the outer box of the domain did not move, bit for bit, in any frame.
"""
import argparse
import os
import re
import shutil
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_deformed_case import check_mesh, fail, failed_checks, points_file, read_points, run  # noqa: E402,E501


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--deform", required=True)
    parser.add_argument("--case", required=True)
    parser.add_argument("--work", required=True)
    parser.add_argument("--baseline", required=True)
    parser.add_argument("options", nargs=argparse.REMAINDER)
    args = parser.parse_args()
    options = [o for o in args.options if o != "--"]
    output = os.path.join(args.work, "Series")
    shutil.rmtree(output, ignore_errors=True)
    os.makedirs(args.work, exist_ok=True)
    code, log = run([args.deform, args.case, output] + options)
    print(log[-2000:])
    if code != 0:
        fail("dgmf-deform exited with %d" % code)
    times = re.findall(r"^dgmf-deform: time (\S+) \(frame", log, re.M)
    if len(times) < 3:
        fail("fewer than 3 frames: %s" % times)
    if len(set(times)) != len(times):
        fail("frames share a time directory: %s" % times)
    source, _, _ = read_points(points_file(os.path.join(args.case, "constant", "polyMesh")))
    low = [min(p[c] for p in source) for c in range(3)]
    high = [max(p[c] for p in source) for c in range(3)]
    on_box = [i for i, p in enumerate(source)
              if any(p[c] in (low[c], high[c]) for c in range(2))]
    with open(args.baseline) as handle:
        allowed = failed_checks(handle.read())
    frames = []
    for time in times:
        poly_mesh = os.path.join(output, time, "polyMesh")
        points, _, _ = read_points(points_file(poly_mesh))
        if len(points) != len(source):
            fail("time %s: %d points, the case has %d" % (time, len(points), len(source)))
        if any(points[i] != source[i] for i in on_box):
            fail("time %s: a point of the outer box moved" % time)
        verdict, failed, _ = check_mesh(output, time)
        new = failed - allowed
        if new:
            fail("time %s: checkMesh fails checks the undeformed mesh passes: %s" % (time, new))
        print("time %s: %d points, checkMesh: %s" % (time, len(points), verdict))
        frames.append(points)
    if frames[0] == frames[1]:
        fail("the first two frames are the same: the wing did not move")
    # --times 0:1:5 with one period a unit of time: the first and the last frame are one period apart
    if frames[0] != frames[-1]:
        fail("the frames a period apart differ")
    print("PASSED: %d time directories, each checked" % len(times))


if __name__ == "__main__":
    main()
