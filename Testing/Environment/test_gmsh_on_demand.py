"""gmsh's library is loaded only when a .msh file is read or written (GmshModule.h): libgmsh and
its ~70 libraries cost every process that linked them 0.12 - 0.15 s at start-up.

    /usr/bin/python3 test_gmsh_on_demand.py --deform DGMF_DEFORM --data Data/rotating_circle.vtu
        --work DIR --not-linked FILE [FILE ...] [--launchers INSTALLED_BIN_DIR]

Checks:
- no FILE (dgmf-deform, the DGMF::IO library, the ParaView plugin) depends on libgmsh (ldd);
- dgmf-deform on a .vtu never loads libgmsh (the dynamic loader's log, LD_DEBUG=files), and
  writes its output;
- dgmf-deform on a gmsh .msh file of version 4.1 and of version 2.2 (made here by gmsh's Python
  API: a box around a sphere, groups "wing" and "farfield") reads and writes it without gmsh
  (MshReader41.h, MshReader22.h, MshNodes.h): libgmsh not loaded, even with DGMF_GMSH_MODULE
  naming a missing module, the mesh deformed by name and written back with every node;
- the same mesh as a version 4.0 file, which is read through gmsh, loads it, and is written back
  with every node;
- DGMF_GMSH_MODULE naming a missing module, or (--not-a-module) a shared library that is not this
  build's module: the .msh run fails with exit code 1, a message that says gmsh's library cannot
  be loaded (and why), and no output file;
- with --launchers (an install tree's bin): the installed plugin reads the .msh in dgmf-pvpython,
  through the module installed beside it (the loader's log shows it opened from under the install
  prefix, not from the build tree).
"""
import argparse
import os
import re
import shutil
import subprocess
import sys

import gmsh


def make_msh(path, version):
    """A unit box around a sphere of radius 0.2, tetrahedra, as a .msh of `version`; returns its
    node count."""
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.model.add("box")
    occ = gmsh.model.occ
    cut, _ = occ.cut([(3, occ.addBox(0, 0, 0, 1, 1, 1))], [(3, occ.addSphere(0.5, 0.5, 0.5, 0.2))])
    occ.synchronize()
    boundary = [t for _, t in gmsh.model.getBoundary(cut, oriented=False)]
    wing = [t for t in boundary
            if max(abs(c - 0.5) for c in occ.getCenterOfMass(2, t)) < 1e-6]
    farfield = [t for t in boundary if t not in wing]
    for tag, (dim, entities, name) in enumerate(
            [(3, [cut[0][1]], "fluid"), (2, wing, "wing"), (2, farfield, "farfield")], start=1):
        gmsh.model.addPhysicalGroup(dim, entities, tag)
        gmsh.model.setPhysicalName(dim, tag, name)
    gmsh.option.setNumber("Mesh.MeshSizeMax", 0.15)
    gmsh.model.mesh.generate(3)
    gmsh.option.setNumber("Mesh.MshFileVersion", version)
    gmsh.write(path)
    count = len(gmsh.model.mesh.getNodes()[0])
    gmsh.finalize()
    return count


def msh_node_count(path):
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.open(path)
    count = len(gmsh.model.mesh.getNodes()[0])
    gmsh.finalize()
    return count


def run(command, env_extra=None):
    env = dict(os.environ)
    env.pop("DGMF_GMSH_MODULE", None)
    env.update(env_extra or {})
    return subprocess.run(command, env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                          universal_newlines=True, timeout=600)


def loaded_gmsh(loader_log):
    """The libgmsh files the dynamic loader's LD_DEBUG=files log says it opened."""
    return sorted(set(re.findall(r"file=(\S*libgmsh\.so[.0-9]*)", loader_log)))


def fail(message):
    print("FAILED: " + message)
    sys.exit(1)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--deform", required=True)
    parser.add_argument("--data", required=True)
    parser.add_argument("--work", required=True)
    parser.add_argument("--not-linked", nargs="+", required=True)
    parser.add_argument("--launchers")
    parser.add_argument("--not-a-module")
    args = parser.parse_args()
    shutil.rmtree(args.work, ignore_errors=True)
    os.makedirs(args.work)

    for library in args.not_linked:
        result = run(["ldd", library])
        if result.returncode != 0 or "libgmsh" in result.stdout:
            fail("%s depends on libgmsh (or ldd failed):\n%s" % (library, result.stdout))
    print("not linked to libgmsh: %d files" % len(args.not_linked))

    vtu_out = os.path.join(args.work, "circle_out.vtu")
    result = run([args.deform, args.data, vtu_out, "--rotate", "0", "0", "10"],
                 {"LD_DEBUG": "files"})
    if result.returncode != 0 or not os.path.exists(vtu_out):
        fail("dgmf-deform on the .vtu: exit %d\n%s" % (result.returncode, result.stderr[-3000:]))
    if loaded_gmsh(result.stderr):
        fail("dgmf-deform on a .vtu loaded %s" % loaded_gmsh(result.stderr))
    print("dgmf-deform on a .vtu: written, libgmsh not loaded")

    nodes = None
    for version in (4.1, 2.2):
        source = os.path.join(args.work, "box%s.msh" % version)
        made = make_msh(source, version)
        if nodes is not None and made != nodes:
            fail("gmsh made another mesh for version %s" % version)
        nodes = made
        written = os.path.join(args.work, "box%s_out.msh" % version)
        missing = os.path.join(args.work, "no_such_dir", "libDGMFGmshFile.so")
        result = run([args.deform, source, written, "--moving", "wing", "--rotate", "10", "20",
                      "30", "--center", "0.5", "0.5", "0.5"],
                     {"LD_DEBUG": "files", "DGMF_GMSH_MODULE": missing})
        if result.returncode != 0 or not os.path.exists(written):
            fail("dgmf-deform on the %s .msh: exit %d\n%s" % (version, result.returncode,
                                                               result.stderr[-3000:]))
        if loaded_gmsh(result.stderr):
            fail("dgmf-deform on a %s .msh loaded %s" % (version, loaded_gmsh(result.stderr)))
        if msh_node_count(written) != nodes:
            fail("the written %s .msh has %d nodes, the source %d" % (
                version, msh_node_count(written), nodes))
        print("dgmf-deform on a %s .msh (%d nodes): read and written without gmsh" % (
            version, nodes))

    msh = os.path.join(args.work, "box40.msh")
    if make_msh(msh, 4.0) != nodes:
        fail("gmsh made another mesh for version 4.0")
    msh_out = os.path.join(args.work, "box_out.msh")
    result = run([args.deform, msh, msh_out, "--moving", "wing", "--rotate", "10", "20", "30",
                  "--center", "0.5", "0.5", "0.5"], {"LD_DEBUG": "files"})
    if result.returncode != 0 or not os.path.exists(msh_out):
        fail("dgmf-deform on the .msh: exit %d\n%s" % (result.returncode, result.stderr[-3000:]))
    if not loaded_gmsh(result.stderr):
        fail("dgmf-deform on a .msh did not load libgmsh, yet wrote it?")
    written = msh_node_count(msh_out)
    if written != nodes:
        fail("the written .msh has %d nodes, the source %d" % (written, nodes))
    print("dgmf-deform on a 4.0 .msh (%d nodes): gmsh loaded (%s), written back with every node" %
          (nodes, ", ".join(loaded_gmsh(result.stderr))))

    missing_out = os.path.join(args.work, "missing_out.msh")
    result = run([args.deform, msh, missing_out, "--moving", "wing", "--rotate", "0", "0", "5"],
                 {"DGMF_GMSH_MODULE": missing})
    if result.returncode != 1 or os.path.exists(missing_out) or \
            "gmsh's library cannot be loaded" not in result.stderr:
        fail("without the module: exit %d, output %s, message:\n%s" % (
            result.returncode, os.path.exists(missing_out), result.stderr[-2000:]))
    print("without the module: exit 1, nothing written: %s" % result.stderr.strip().splitlines()[-1])

    if args.not_a_module:
        result = run([args.deform, msh, missing_out, "--moving", "wing", "--rotate", "0", "0", "5"],
                      {"DGMF_GMSH_MODULE": args.not_a_module})
        if result.returncode != 1 or os.path.exists(missing_out) or \
                "not a gmsh module of this program" not in result.stderr:
            fail("another library as the module: exit %d, output %s, message:\n%s" % (
                result.returncode, os.path.exists(missing_out), result.stderr[-2000:]))
        print("another library as the module: refused, nothing written")

    if args.launchers:
        script = os.path.join(args.work, "read_msh.py")
        with open(script, "w") as out:
            out.write("import sys\nfrom paraview import simple, servermanager\n"
                      "reader = simple.DGMFMeshFileReader(FileName=sys.argv[1])\n"
                      "data = servermanager.Fetch(reader)\n"
                      "print('installed plugin read: %d points' % "
                      "data.GetBlock(0).GetNumberOfPoints())\n")
        result = run([os.path.join(args.launchers, "dgmf-pvpython"), "--force-offscreen-rendering",
                      script, msh], {"LD_DEBUG": "files"})
        prefix = os.path.dirname(os.path.abspath(args.launchers))
        modules = sorted(set(re.findall(r"file=(\S*libDGMFGmshFile\.so)", result.stderr)))
        if result.returncode != 0 or ("installed plugin read: %d points" % nodes) not in \
                result.stdout:
            fail("the installed plugin on the .msh: exit %d\n%s\n%s" % (
                result.returncode, result.stdout[-2000:], result.stderr[-2000:]))
        if not modules or not all(os.path.abspath(m).startswith(prefix + os.sep) for m in modules):
            fail("the installed plugin loaded the gmsh module from %s, not under %s" % (
                modules, prefix))
        print("the installed plugin read the .msh (%d points) with %s" % (nodes, modules[0]))
    print("gmsh on demand OK")


if __name__ == "__main__":
    main()
