"""ParaView does not go down when the deformation runs out of memory (issue 17).

The parent (pvpython) makes a 125,000-node mesh, then runs a child pvpython per limit: the child
loads the plugin, reads the mesh, sets its address-space limit to what it uses plus EXTRA bytes,
and deforms. At every limit the child must end normally (exit 0, no signal) with either the whole
mesh deformed or the filter's out-of-memory error and an empty output.

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
    reader.UpdatePipeline()
    points = reader.GetDataInformation().GetNumberOfPoints()
    deform = DGMFDeform(Input=reader)  # noqa: F821 (defined by LoadPlugin)
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
    failed, succeeded = 0, 0
    for extra_mib in (8, 16, 24, 32, 48, 64, 96, 128, 192, 256, 512):
        done = subprocess.run(
            [shutil.which("pvpython"), "--force-offscreen-rendering", os.path.abspath(__file__),
             "--plugin", args.plugin, "--mesh", mesh, "--child", str(extra_mib << 20)],
            capture_output=True, text=True, timeout=600)
        result = [line for line in done.stdout.splitlines() if line.startswith("RESULT")]
        print("%4d MiB more: exit %d, %s" % (extra_mib, done.returncode,
                                             result[0] if result else "no result"))
        assert done.returncode == 0, "pvpython did not survive (%d):\n%s" % (
            done.returncode, done.stderr[-3000:])
        assert result, done.stderr[-3000:]
        deformed = int(result[0].split()[1])
        if deformed == points:
            succeeded += 1
        else:
            assert deformed == 0, result[0]
            assert any(m in done.stderr for m in MEMORY_MESSAGES), done.stderr[-3000:]
            failed += 1
    print("deformed at %d limits, out of memory at %d, ParaView up at all" % (succeeded, failed))
    assert failed >= 2 and succeeded >= 1, "the limits did not cover both outcomes"
    return 0


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--plugin", required=True)
    parser.add_argument("--work")
    parser.add_argument("--mesh")
    parser.add_argument("--child", type=int)
    args = parser.parse_args()
    return child(args) if args.child is not None else parent(args)


if __name__ == "__main__":
    sys.exit(main())
