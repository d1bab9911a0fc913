#!/usr/bin/env python3
"""Deforms an OpenFOAM case with dgmf-deform and judges the result with OpenFOAM's own tools.

    check_deformed_case.py --deform BIN --case SRC --work DIR --name NAME [checks] -- OPTIONS

Runs `dgmf-deform SRC DIR/NAME OPTIONS`, then `checkMesh` on the written case, and asserts:
- dgmf-deform succeeds, the source case is unchanged (every file's bytes) unless it is the output;
- the written points file has the source's number of points and format (ascii/binary, gzip);
- checkMesh has no FATAL ERROR and fails no check that the undeformed mesh (--baseline, the log
  of checkMesh on it) does not fail; with --mesh-ok, it says "Mesh OK.";
- the points on the outer box of the domain did not move, bit for bit;
- one-cell-thick meshes (--one-cell-thick): each front/back pair of points keeps one (x, y),
  and every point keeps its z, bit for bit.
--expect-failure expects checkMesh to fail (an unguarded large motion), with the same predictions.
Optional: --solver N runs simpleFoam for N iterations on the result; --convert binary|compressed
first converts a copy of the source with foamFormatConvert; --in-place writes into a copy of the
source itself (OUT = CASE, with --time); --same-as OTHER compares the written points with another
run's; --expect-error TEXT expects dgmf-deform to fail with TEXT in its messages.
Prints what it checked; exits 1 on the first failed assertion.
"""
import argparse
import hashlib
import os
import re
import shutil
import struct
import subprocess
import sys
import gzip


def fail(message):
    print("FAILED: " + message)
    sys.exit(1)


def run(command, cwd=None):
    env = dict(os.environ)
    env.setdefault("WM_PROJECT_DIR", "/usr/share/openfoam")
    done = subprocess.run(command, cwd=cwd, env=env, stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, text=True)
    return done.returncode, done.stdout


def case_hash(directory):
    digest = hashlib.sha256()
    for root, dirs, files in sorted(os.walk(directory)):
        dirs.sort()
        for name in sorted(files):
            path = os.path.join(root, name)
            digest.update(os.path.relpath(path, directory).encode())
            with open(path, "rb") as handle:
                digest.update(handle.read())
    return digest.hexdigest()


def points_file(poly_mesh):
    for name in ("points", "points.gz"):
        if os.path.isfile(os.path.join(poly_mesh, name)):
            return os.path.join(poly_mesh, name)
    fail("no points file in " + poly_mesh)


def read_points(path):
    """(points as a list of (x, y, z), format, compressed) of an OpenFOAM points file."""
    opener = gzip.open if path.endswith(".gz") else open
    with opener(path, "rb") as handle:
        data = handle.read()
    header_end = data.index(b"}", data.index(b"FoamFile")) + 1
    header = data[:header_end].decode()
    form = re.search(r"format\s+(\w+);", header).group(1)
    body = re.compile(rb"(?:\s|//[^\n]*\n)*(\d+)\s*\(").match(data, header_end)
    count = int(body.group(1))
    start = body.end()
    if form == "binary":
        values = struct.unpack("<%dd" % (3 * count), data[start:start + 24 * count])
        points = [values[3 * i:3 * i + 3] for i in range(count)]
    else:
        text = data[start:].decode()
        numbers = re.findall(r"\(([^()]*)\)", text[:text.rindex(")")])
        points = [tuple(float(v) for v in triple.split()) for triple in numbers[:count]]
    if len(points) != count:
        fail("%s: %d points read, the file says %d" % (path, len(points), count))
    return points, form, path.endswith(".gz")


def failed_checks(log):
    """The kinds of the checks checkMesh failed (' ***' lines, numbers removed)."""
    kinds = set()
    for line in log.splitlines():
        if line.startswith(" ***"):
            kinds.add(re.sub(r"[-+]?\d+(\.\d*)?(e[-+]?\d+)?", "#", line.split(",")[0].split(":")[0]).strip())
    return kinds


def check_mesh(case, time):
    code, log = run(["checkMesh", "-time", time] if time != "constant" else
                    ["checkMesh", "-constant"], cwd=case)
    if "FOAM FATAL" in log or code != 0:
        fail("checkMesh stopped (exit %d):\n%s" % (code, log[-1500:]))
    verdicts = re.findall(r"^(Mesh OK\.|Failed \d+ mesh checks\.)$", log, re.M)
    if not verdicts:
        fail("checkMesh gave no verdict:\n" + log[-1500:])
    return verdicts[-1], failed_checks(log), log


def convert(source, target, kind):
    shutil.copytree(source, target)
    control = os.path.join(target, "system", "controlDict")
    entries = {"binary": [("writeFormat", "binary")],
               "compressed": [("writeFormat", "ascii"), ("writeCompression", "on")]}[kind]
    for key, value in entries:
        code, log = run(["foamDictionary", "-entry", key, "-set", value, control])
        if code != 0:
            fail("foamDictionary: " + log)
    code, log = run(["foamFormatConvert", "-constant"], cwd=target)
    if code != 0:
        fail("foamFormatConvert: " + log)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--deform", required=True)
    parser.add_argument("--case", required=True)
    parser.add_argument("--work", required=True)
    parser.add_argument("--name", required=True)
    parser.add_argument("--baseline")
    parser.add_argument("--mesh-ok", action="store_true")
    parser.add_argument("--expect-failure", action="store_true")
    parser.add_argument("--one-cell-thick", action="store_true")
    parser.add_argument("--solver", type=int, default=0)
    parser.add_argument("--convert", choices=["binary", "compressed"])
    parser.add_argument("--in-place", action="store_true")
    parser.add_argument("--time", default="constant")
    parser.add_argument("--same-as")
    parser.add_argument("--same-tolerance", type=float, default=0.0)
    parser.add_argument("--expect-error")
    parser.add_argument("--corrupt-points", action="store_true",
                        help="run on a copy whose points file has a word for a number")
    parser.add_argument("options", nargs=argparse.REMAINDER)
    args = parser.parse_args()
    options = [o for o in args.options if o != "--"]

    os.makedirs(args.work, exist_ok=True)
    out = os.path.join(args.work, args.name)
    shutil.rmtree(out, ignore_errors=True)
    source = args.case
    if args.convert:
        source = out + ".source"
        shutil.rmtree(source, ignore_errors=True)
        convert(args.case, source, args.convert)
    if args.in_place:
        shutil.copytree(args.case, out)
        source = out
    if args.corrupt_points:
        source = out + ".source"
        shutil.rmtree(source, ignore_errors=True)
        shutil.copytree(args.case, source)
        path = os.path.join(source, "constant", "polyMesh", "points")
        with open(path) as f:
            lines = f.read().split("\n")
        first = next(k for k, line in enumerate(lines) if re.match(r"^\(\S+ \S+ \S+\)$", line))
        lines[first] = "(0 0 nonsense)"
        with open(path, "w") as f:
            f.write("\n".join(lines))
    before = case_hash(source)
    constant_before = case_hash(os.path.join(source, "constant"))
    if args.corrupt_points:
        source_points = None
    else:
        source_points, source_format, source_gz = read_points(
            points_file(os.path.join(source, "constant", "polyMesh")))

    command = [args.deform, source, out] + options
    if args.time != "constant":
        command += ["--time", args.time]
    code, log = run(command)
    print("$ " + " ".join(command) + "\n" + log)
    if args.expect_error is not None:
        if code == 0 or args.expect_error not in log:
            fail("dgmf-deform should fail with '%s' (exit %d)" % (args.expect_error, code))
        if case_hash(source) != before:
            fail("the source case was modified by a failed run")
        print("dgmf-deform failed as expected, the source case unchanged")
        print("PASSED")
        return
    if code != 0:
        fail("dgmf-deform exit code %d" % code)

    if args.in_place:
        if case_hash(os.path.join(source, "constant")) != constant_before:
            fail("writing into time %s changed constant/" % args.time)
    elif case_hash(source) != before:
        fail("the source case was modified")
    print("source case unchanged")

    written = points_file(os.path.join(out, args.time, "polyMesh"))
    points, form, compressed = read_points(written)
    if len(points) != len(source_points):
        fail("%d points written, the case has %d" % (len(points), len(source_points)))
    if (form, compressed) != (source_format, source_gz):
        fail("written as %s%s, the case's points are %s%s" % (
            form, " gzip" if compressed else "", source_format, " gzip" if source_gz else ""))
    print("%s: %d points, %s%s as the case's" % (
        written, len(points), form, " gzip" if compressed else ""))

    # The outer box of the domain is a static boundary: its points keep their bits.
    low = [min(p[k] for p in source_points) for k in range(2)]
    high = [max(p[k] for p in source_points) for k in range(2)]
    outer = [i for i, p in enumerate(source_points)
             if p[0] in (low[0], high[0]) or p[1] in (low[1], high[1])]
    moved_outer = [i for i in outer if points[i] != source_points[i]]
    if not outer or moved_outer:
        fail("%d of %d points on the outer box moved (first: %s)" % (
            len(moved_outer), len(outer), moved_outer[:3]))
    moved = sum(1 for p, q in zip(points, source_points) if p != q)
    print("%d points on the outer box kept their bits; %d points moved" % (len(outer), moved))
    if moved == 0:
        fail("no point moved")

    if args.one_cell_thick:
        z = sorted(set(p[2] for p in source_points))
        if len(z) != 2:
            fail("a one-cell-thick mesh has two planes; found %d z values" % len(z))
        back = {(p[0], p[1]): i for i, p in enumerate(source_points) if p[2] == z[1]}
        pairs = 0
        for i, p in enumerate(source_points):
            if p[2] != z[0]:
                continue
            j = back.get((p[0], p[1]))
            if j is None:
                fail("point %d has no partner on the other plane" % i)
            if points[i][:2] != points[j][:2]:
                fail("points %d and %d moved apart: %s %s" % (i, j, points[i], points[j]))
            pairs += 1
        if any(q[2] != p[2] for p, q in zip(source_points, points)):
            fail("a point changed its z")
        print("%d front/back pairs kept one (x, y) each; every z unchanged" % pairs)

    if args.same_as:
        other, _, _ = read_points(points_file(os.path.join(args.same_as, args.time, "polyMesh")))
        if len(other) != len(points):
            fail("%d points in %s" % (len(other), args.same_as))
        differences = [max(abs(a - b) for a, b in zip(p, q)) for p, q in zip(points, other)]
        differing = sum(1 for d in differences if d > 0)
        if max(differences) > args.same_tolerance:
            fail("%d points differ from %s, by up to %g" % (
                differing, args.same_as, max(differences)))
        print("the same points as %s: %d bit for bit, %d within %g (largest difference %g)" % (
            args.same_as, len(points) - differing, differing, args.same_tolerance,
            max(differences)))

    verdict, failures, check_log = check_mesh(out, args.time)
    print("checkMesh: " + verdict + "".join("\n  failed: " + f for f in sorted(failures)))
    for line in check_log.splitlines():
        if "non-orthogonality Max" in line:
            print(line.strip())
    # What dgmf-deform predicted: the same maximum non-orthogonality (checkMesh's definition,
    # within 0.5 degree: the reader gives the points in single precision), and no cell inverted
    # when checkMesh finds no negative volume. Decomposed polyhedra are other cells: not compared.
    if "--decompose-polyhedra" not in options:
        predicted = re.search(r"non-orthogonality max (\S+) \(input (\S+)\)", log)
        measured = re.search(r"Mesh non-orthogonality Max: (\S+)", check_log)
        if not predicted or not measured:
            fail("no non-orthogonality to compare")
        difference = abs(float(predicted.group(1)) - float(measured.group(1)))
        print("non-orthogonality: dgmf-deform %s, checkMesh %s (difference %.4f)" % (
            predicted.group(1), measured.group(1), difference))
        if difference > 0.5:
            fail("dgmf-deform's non-orthogonality is not checkMesh's")
        if args.baseline:
            with open(args.baseline) as handle:
                before = re.search(r"Mesh non-orthogonality Max: (\S+)", handle.read())
            if abs(float(predicted.group(2)) - float(before.group(1))) > 0.5:
                fail("the input's non-orthogonality %s is not checkMesh's %s" % (
                    predicted.group(2), before.group(1)))
        inverted = int(re.search(r"inverted cells (\d+)", log).group(1))
        negative = re.search(r"Number of negative volume cells: (\d+)", check_log)
        negative = int(negative.group(1)) if negative else 0
        # Inverted means a corner (or a face-centre tetrahedron) turned inside out: every cell of
        # negative volume, and possibly more.
        if (negative == 0 and inverted != 0) or inverted < negative:
            fail("%d cells said inverted, checkMesh finds %d of negative volume" % (
                inverted, negative))
        print("inverted cells: %d; checkMesh's negative volumes: %d" % (inverted, negative))
    if args.expect_failure:
        if verdict == "Mesh OK." or not failures:
            fail("checkMesh should fail this mesh")
        print("checkMesh fails it, as expected, and as dgmf-deform predicted")
    if args.mesh_ok and verdict != "Mesh OK.":
        fail("checkMesh should say Mesh OK")
    if args.baseline:
        with open(args.baseline) as handle:
            allowed = failed_checks(handle.read())
        new = failures - allowed
        if new:
            fail("checks failed that the undeformed mesh passes: " + ", ".join(sorted(new)))
        print("no failed check that the undeformed mesh does not have")

    if args.solver:
        control = os.path.join(out, "system", "controlDict")
        for key, value in (("endTime", args.solver), ("writeInterval", args.solver)):
            run(["foamDictionary", "-entry", key, "-set", str(value), control])
        code, solver_log = run(["simpleFoam"], cwd=out)
        if code != 0 or "FOAM FATAL" in solver_log or not re.search(r"^End\s*$", solver_log, re.M):
            fail("simpleFoam did not run to its end (exit %d):\n%s" % (code, solver_log[-2000:]))
        if re.search(r"\bnan\b", solver_log, re.I):
            fail("simpleFoam produced NaN")
        times = re.findall(r"^Time = (\S+)$", solver_log, re.M)
        print("simpleFoam ran %s iterations to its end on the deformed mesh" % len(times))
    print("PASSED")


if __name__ == "__main__":
    main()
