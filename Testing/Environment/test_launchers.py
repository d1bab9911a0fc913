"""dgmf-pvpython, dgmf-pvbatch and dgmf-paraview: the plugin and the expat work-around without
LoadPlugin or LD_PRELOAD, and appended-mode .vtu files read whole.

    python3 test_launchers.py --launchers BIN_DIR --data Data/rotating_circle.vtu --work DIR
        [--mpiexec MPIEXEC] [--xvfb-run XVFB_RUN --xvfb-args ARGS] [--prefix PREFIX]

Checks:
- dgmf-pvpython -c writes the circle (822 points, 1529 cells) in appended mode, the mode that
  Debian 12's libexpat (deb12u2 and later) breaks without the work-around;
- dgmf-pvpython -c reads it back whole, has DGMFDeform without LoadPlugin, deforms it, and runs
  with the work-around loaded (its marker dgmf_expat_fix_loaded is in the process);
- mpiexec -np 2 dgmf-pvbatch --symmetric: RedistributeDataSet of the appended file keeps every
  node (the data loss of issue 17 dropped a rank's half);
- dgmf-paraview under xvfb-run (the preload after xvfb-run) loads the plugin and reads the file;
- with --prefix: the plugin and the work-around the launchers load are those under PREFIX (the
  install tree's).
"""
import argparse
import os
import subprocess
import sys

POINTS, CELLS = 822, 1529

WRITE = """
import sys
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader, vtkXMLUnstructuredGridWriter
reader = vtkXMLUnstructuredGridReader()
reader.SetFileName(sys.argv[1])
writer = vtkXMLUnstructuredGridWriter()
writer.SetInputConnection(reader.GetOutputPort())
writer.SetFileName(sys.argv[2])
writer.SetDataModeToAppended()
writer.Write()
print("wrote appended: %d points" % reader.GetOutput().GetNumberOfPoints())
"""

READ = """
import ctypes, sys
from paraview import simple
mesh = simple.XMLUnstructuredGridReader(FileName=[sys.argv[1]])
deform = simple.DGMFDeform(Input=mesh)
deform.BoundaryMarkerArray = ["POINTS", "BoundaryMarker"]
deform.RotationAngles = [0.0, 0.0, 30.0]
deform.UpdatePipeline()
info = deform.GetDataInformation()
maps = open("/proc/self/maps").read().split()
loaded = sorted({p for p in maps if p.endswith(("DGMFPlugin.so", "libdgmf_expat_fix.so"))})
print("read: %d points, %d cells; marker: %s; loaded: %s" % (
    info.GetNumberOfPoints(), info.GetNumberOfCells(),
    hasattr(ctypes.CDLL(None), "dgmf_expat_fix_loaded"), " ".join(loaded)))
"""

REDISTRIBUTE = """
import sys
from paraview import simple
from vtkmodules.vtkCommonCore import vtkDoubleArray
from vtkmodules.vtkParallelCore import vtkMultiProcessController
controller = vtkMultiProcessController.GetGlobalController()
mesh = simple.XMLUnstructuredGridReader(FileName=[sys.argv[1]])
pieces = simple.RedistributeDataSet(Input=mesh)
assert hasattr(simple, "DGMFDeform"), "the plugin is not loaded"
pieces.UpdatePipeline()
piece = pieces.GetClientSideObject().GetOutputDataObject(0)
local = vtkDoubleArray()
local.SetNumberOfComponents(3)
for k in range(piece.GetNumberOfPoints()):
    local.InsertNextTuple(piece.GetPoint(k))
everything = vtkDoubleArray()
controller.AllGatherV(local, everything)
distinct = len({everything.GetTuple3(k) for k in range(everything.GetNumberOfTuples())})
if controller.GetLocalProcessId() == 0:
    print("redistributed on %d processes: %d distinct points" % (
        controller.GetNumberOfProcesses(), distinct))
"""

GUI = """
import os
from paraview import simple
mesh = simple.XMLUnstructuredGridReader(FileName=[os.environ["DGMF_TEST_VTU"]])
deform = simple.DGMFDeform(Input=mesh)
deform.BoundaryMarkerArray = ["POINTS", "BoundaryMarker"]
deform.UpdatePipeline()
print("gui: %d points" % deform.GetDataInformation().GetNumberOfPoints())
"""


def run(command, expected, env=None):
    """Runs `command` without LD_PRELOAD or PV_PLUGIN_PATH of ours; its output must hold `expected`."""
    environment = dict(os.environ)
    for name in ("LD_PRELOAD", "PV_PLUGIN_PATH", "DGMF_PLUGIN"):
        environment.pop(name, None)
    environment.update(env or {})
    result = subprocess.run(command, env=environment, stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, universal_newlines=True, timeout=300)
    if result.returncode != 0 or expected not in result.stdout:
        sys.exit("FAILED (exit %d, expected %r): %s\n%s"
                 % (result.returncode, expected, " ".join(command), result.stdout))
    line = next(l for l in result.stdout.splitlines() if expected in l)
    print(line.strip())
    return line


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--launchers", required=True)
    parser.add_argument("--data", required=True)
    parser.add_argument("--work", required=True)
    parser.add_argument("--mpiexec")
    parser.add_argument("--xvfb-run")
    parser.add_argument("--xvfb-args", default="-screen 0 1280x1024x24 -noreset")
    parser.add_argument("--prefix")
    args = parser.parse_args()
    os.makedirs(args.work, exist_ok=True)
    appended = os.path.join(args.work, "circle_appended.vtu")
    if os.path.exists(appended):
        os.remove(appended)
    pvpython = os.path.join(args.launchers, "dgmf-pvpython")
    run([pvpython, "-c", WRITE, args.data, appended], "wrote appended: %d points" % POINTS)
    if b'format="appended"' not in open(appended, "rb").read(4096):
        sys.exit("FAILED: %s is not in appended mode" % appended)
    line = run([pvpython, "-c", READ, appended],
               "read: %d points, %d cells; marker: True" % (POINTS, CELLS))
    if args.prefix:
        prefix = os.path.realpath(args.prefix)
        loaded = line.split("loaded: ")[1].split()
        if len(loaded) != 2 or not all(os.path.realpath(p).startswith(prefix + "/") for p in loaded):
            sys.exit("FAILED: the plugin and the work-around are not those of %s: %s"
                     % (prefix, loaded))
    if args.mpiexec:
        script = os.path.join(args.work, "redistribute.py")
        with open(script, "w") as f:
            f.write(REDISTRIBUTE)
        run([args.mpiexec, "--allow-run-as-root", "--oversubscribe", "-np", "2",
             os.path.join(args.launchers, "dgmf-pvbatch"), "--symmetric", script, appended],
            "redistributed on 2 processes: %d distinct points" % POINTS)
    if args.xvfb_run:
        script = os.path.join(args.work, "gui_read.py")
        with open(script, "w") as f:
            f.write(GUI)
        run([args.xvfb_run, "-a", "-s", args.xvfb_args,
             os.path.join(args.launchers, "dgmf-paraview"), "--script=" + script, "--exit"],
            "gui: %d points" % POINTS, {"DGMF_TEST_VTU": appended})
    print("launchers OK")


main()
