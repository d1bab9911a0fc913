"""ParaView does not go down when the deformation runs out of memory (issue 17).

The parent (pvpython) makes a 125,000-node mesh, then runs a child pvpython per limit: the child
loads the plugin, reads the mesh, sets its address-space limit to what it uses plus EXTRA bytes,
and deforms. At every limit the child must end normally (exit 0, no signal) with either the whole
mesh deformed or the filter's out-of-memory error and an empty output. Then the same with the mesh
and its boundary surface as two blocks of a multiblock, merged by the filter first (the merge
running out of memory is one of the outcomes).

  pvpython test_plugin_memory.py --plugin PLUGIN --work WORK_DIR
"""
import argparse
import os
import resource
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

MEMORY_MESSAGES = ("Out of memory", "needs about", "Out of resources")


def virtual_size():
    with open("/proc/self/status") as status:
        for line in status:
            if line.startswith("VmSize:"):
                return int(line.split()[1]) * 1024
    raise RuntimeError("no VmSize")


def child(args):
    from paraview import simple

    simple.LoadPlugin(args.plugin, remote=False, ns=globals())
    reader = simple.XMLUnstructuredGridReader(FileName=[args.mesh])
    source = reader
    if args.composite:  # the volume and its boundary surface, merged by the filter
        source = simple.GroupDatasets(Input=[reader, simple.ExtractSurface(Input=reader)])
    source.UpdatePipeline()
    points = source.GetDataInformation().GetNumberOfPoints()
    deform = DGMFDeform(Input=source)  # noqa: F821 (defined by LoadPlugin)
    deform.BoundaryMarkerArray = ["POINTS", "BoundaryMarker"]
    deform.RotationCenter = [0.5, 0.5, 0.5]
    deform.RotationAngles = [10.0, 20.0, 30.0]
    limit = virtual_size() + args.child
    resource.setrlimit(resource.RLIMIT_AS, (limit, limit))
    deform.UpdatePipeline()
    print("RESULT %d of %d" % (deform.GetDataInformation().GetNumberOfPoints(), points),
          flush=True)
    return 0


def parent(args):
    import failure_meshes as meshes

    os.makedirs(args.work, exist_ok=True)
    mesh = os.path.join(args.work, "plugin_memory.vtu")
    points, cells = meshes.cube_in_box(50, mesh)
    for composite in (False, True):
        failed, succeeded = 0, 0
        for extra_mib in (8, 16, 24, 32, 48, 64, 96, 128, 192, 256, 512):
            command = [shutil.which("pvpython"), "--force-offscreen-rendering",
                       os.path.abspath(__file__), "--plugin", args.plugin, "--mesh", mesh,
                       "--child", str(extra_mib << 20)] + (["--composite"] if composite else [])
            done = subprocess.run(command, capture_output=True, text=True, timeout=600)
            result = [line for line in done.stdout.splitlines() if line.startswith("RESULT")]
            print("%s, %4d MiB more: exit %d, %s" % (
                "multiblock" if composite else "grid", extra_mib, done.returncode,
                result[0] if result else "no result"))
            assert done.returncode == 0, "pvpython did not survive (%d):\n%s" % (
                done.returncode, done.stderr[-3000:])
            assert result, done.stderr[-3000:]
            deformed, expected = int(result[0].split()[1]), int(result[0].split()[3])
            assert expected >= points, result[0]  # the grid's points (and the surface's)
            if deformed == expected:
                succeeded += 1
            else:
                assert deformed == 0, result[0]
                assert any(m in done.stderr for m in MEMORY_MESSAGES), done.stderr[-3000:]
                failed += 1
        print("%s: deformed at %d limits, out of memory at %d" % (
            "multiblock" if composite else "grid", succeeded, failed))
        assert failed >= 2 and succeeded >= 1, "the limits did not cover both outcomes"
    print("ParaView up at all")
    return 0


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--plugin", required=True)
    parser.add_argument("--work")
    parser.add_argument("--mesh")
    parser.add_argument("--child", type=int)
    parser.add_argument("--composite", action="store_true")
    args = parser.parse_args()
    return child(args) if args.child is not None else parent(args)


if __name__ == "__main__":
    sys.exit(main())
