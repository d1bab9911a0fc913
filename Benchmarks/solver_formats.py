"""The whole command on a solver's mesh file (issue 18, "speed as users meet it"): how long
`dgmf-deform` takes to read, deform and write the same mesh in each format it reads, gmsh .msh
(version 4.1 binary, and the legacy version 2.2, binary and ASCII), SU2, Exodus II and CGNS,
against the filter alone.

The mesh: gmsh's tetrahedra around a sphere of radius 0.2 in the unit box (physical groups
"wing", the sphere, and "farfield", the box), largest element size 0.015 by default: about 257,000
nodes and 1.29 million tetrahedra, the size of the paper's wing-body. gmsh writes the .msh and .su2
files (generated once into the cache folder) and the version 2.2 files (the 4.1 file opened and
written again); the Exodus and CGNS files are converted from the .msh by the build's
dgmf-test-convert-mesh. Each format is then deformed `--repeats` times into a
file of the same format (the wing rotated by 10 degrees about z through its centre, 2 threads), and
the page gives the medians of the wall time, of the read and write the command prints, and of the
filter (deformation and quality), and the wall time over the filter.

Usage: /usr/bin/python3 solver_formats.py BUILD_DIR OUTPUT.md [--repeats 3] [--size 0.015]
"""
import argparse
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time

# (label, the file's suffix after the mesh's name)
FORMATS = (("gmsh .msh 4.1 binary", "msh"), ("gmsh .msh 2.2 binary", "v22.msh"),
           ("gmsh .msh 2.2 ASCII", "v22a.msh"), ("SU2 (text)", "su2"), ("Exodus II", "exo"),
           ("CGNS", "cgns"))


def cache_folder():
    base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    folder = os.path.join(base, "dgmf", "solver_formats")
    os.makedirs(folder, exist_ok=True)
    return folder


def make_mesh(folder, size):
    """The .msh and .su2 files of the sphere in the box (gmsh), made once per size."""
    stem = os.path.join(folder, "sphere_box_%g" % size)
    if os.path.exists(stem + ".msh") and os.path.exists(stem + ".su2"):
        return stem
    import gmsh
    gmsh.initialize()
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.model.add("sphere_box")
        occ = gmsh.model.occ
        box = occ.addBox(0, 0, 0, 1, 1, 1)
        ball = occ.addSphere(0.5, 0.5, 0.5, 0.2)
        cut, _ = occ.cut([(3, box)], [(3, ball)])
        occ.synchronize()
        surfaces = [t for _, t in gmsh.model.getBoundary(cut, oriented=False)]
        sphere = [s for s in surfaces if gmsh.model.getType(2, s) == "Sphere"]
        box_faces = [s for s in surfaces if s not in sphere]
        gmsh.model.addPhysicalGroup(2, sphere, 1)
        gmsh.model.setPhysicalName(2, 1, "wing")
        gmsh.model.addPhysicalGroup(2, box_faces, 2)
        gmsh.model.setPhysicalName(2, 2, "farfield")
        gmsh.model.addPhysicalGroup(3, [cut[0][1]], 3)
        gmsh.model.setPhysicalName(3, 3, "fluid")
        gmsh.option.setNumber("Mesh.MeshSizeMax", size)
        gmsh.model.mesh.generate(3)
        gmsh.option.setNumber("Mesh.MshFileVersion", 4.1)
        gmsh.option.setNumber("Mesh.Binary", 1)
        gmsh.write(stem + ".msh")
        gmsh.option.setNumber("Mesh.Binary", 0)
        gmsh.write(stem + ".su2")
    finally:
        gmsh.finalize()
    return stem


def write_version_22(stem):
    """The version 2.2 files, binary and ASCII, of the mesh (gmsh's writer), made once."""
    if os.path.exists(stem + ".v22.msh") and os.path.exists(stem + ".v22a.msh"):
        return
    import gmsh
    gmsh.initialize()
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.open(stem + ".msh")
        gmsh.option.setNumber("Mesh.MshFileVersion", 2.2)
        for binary, suffix in ((1, ".v22.msh"), (0, ".v22a.msh")):
            gmsh.option.setNumber("Mesh.Binary", binary)
            gmsh.write(stem + suffix)
    finally:
        gmsh.finalize()


def run_once(command, source, target):
    start = time.perf_counter()
    done = subprocess.run([command, source, target, "--moving", "wing", "--rotate", "0", "0", "10",
                           "--center", "0.5", "0.5", "0.5", "--threads", "2"],
                          capture_output=True, text=True)
    wall = time.perf_counter() - start
    if done.returncode != 0:
        sys.exit("dgmf-deform failed on %s:\n%s%s" % (source, done.stdout, done.stderr))
    line = done.stdout.strip().splitlines()[-1]
    found = re.search(r"(\d+) points, (\d+) cells, ([0-9.e-]+) s .*read ([0-9.e-]+) s, "
                      r"written ([0-9.e-]+) s", line)
    if not found:
        sys.exit("unexpected output of dgmf-deform: " + line)
    points, cells = int(found.group(1)), int(found.group(2))
    return points, cells, wall, float(found.group(4)), float(found.group(5)), float(found.group(3))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("build")
    parser.add_argument("output")
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--size", type=float, default=0.015)
    args = parser.parse_args()
    command = os.path.join(args.build, "bin", "dgmf-deform")
    convert = os.path.join(args.build, "bin", "dgmf-test-convert-mesh")
    stem = make_mesh(cache_folder(), args.size)
    write_version_22(stem)
    for extension in ("exo", "cgns"):
        if not os.path.exists(stem + "." + extension):
            subprocess.run([convert, stem + ".msh", stem + "." + extension], check=True,
                           capture_output=True)
    rows = []
    with tempfile.TemporaryDirectory(prefix="dgmf-formats-") as work:
        for label, extension in FORMATS:
            runs = [run_once(command, stem + "." + extension,
                             os.path.join(work, "out." + extension))
                    for _ in range(args.repeats)]
            points, cells = runs[0][0], runs[0][1]
            if any(r[0] != points or r[1] != cells for r in runs):
                sys.exit("the point or cell count changed from run to run on " + extension)
            medians = [statistics.median(r[k] for r in runs) for k in range(2, 6)]
            rows.append((label, points, cells) + tuple(medians))
    with open(args.output, "w") as page:
        page.write("# The whole command on a solver's mesh file\n\n")
        page.write("Written by `Benchmarks/solver_formats.py` (`scripts/run-benchmark.sh`), %s.\n"
                   % time.strftime("%Y-%m-%d"))
        page.write("`dgmf-deform FILE OUT --moving wing --rotate 0 0 10 --center 0.5 0.5 0.5 "
                   "--threads 2`, each file into a file of its own format; medians of %d runs. "
                   "The mesh: gmsh's tetrahedra around a sphere in the unit box, largest element "
                   "size %g (see the script). *Filter*: the deformation and the quality metric "
                   "as the command prints them; *read* and *write*: the same.\n\n"
                   % (args.repeats, args.size))
        page.write("| format | points | cells | whole command | read | write | filter "
                   "| whole / filter |\n|---|---|---|---|---|---|---|---|\n")
        for label, points, cells, wall, read, written, filtered in rows:
            page.write("| %s | %d | %d | %.3f s | %.3f s | %.3f s | %.3f s | %.1f |\n"
                       % (label, points, cells, wall, read, written, filtered, wall / filtered))
    print("wrote " + args.output)


if __name__ == "__main__":
    main()
