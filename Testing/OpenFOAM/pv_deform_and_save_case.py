"""The OpenFOAM round trip from pvpython, as a ParaView user does it: OpenFOAMReader (ParaView's
defaults: polyhedra decomposed), DGMF Deform with the moving patch picked by name, SaveData into a
new case with the plugin's writer. Asserts that the written case has the case's point count, that
checkMesh fails no check the undeformed mesh passes, and that the points are those dgmf-deform
wrote for the same motion (--reference: another run's case), bit for bit.

    pvpython pv_deform_and_save_case.py --plugin P --case CASE --out OUT --baseline LOG
             --reference OTHER_CASE --angle DEGREES
"""
import argparse
import os
import re
import shutil
import subprocess
import sys

from paraview.simple import (LoadPlugin, OpenFOAMReader, SaveData, UpdatePipeline)

parser = argparse.ArgumentParser()
parser.add_argument("--plugin", required=True)
parser.add_argument("--case", required=True)
parser.add_argument("--out", required=True)
parser.add_argument("--baseline", required=True)
parser.add_argument("--reference", required=True)
parser.add_argument("--angle", type=float, required=True)
args = parser.parse_args()


def fail(message):
    print("FAILED: " + message)
    sys.exit(1)


def points_text(case):
    with open(os.path.join(case, "constant", "polyMesh", "points")) as handle:
        text = handle.read()
    body = text[text.index("}", text.index("FoamFile")) + 1:]
    return re.findall(r"\(([^()]*)\)", body)


LoadPlugin(args.plugin, ns=globals())
reader = OpenFOAMReader(FileName=os.path.join(args.case, "case.foam"))
reader.MeshRegions = ["internalMesh", "patch/wing", "patch/inlet", "patch/outlet",
                      "patch/topAndBottom", "patch/front", "patch/back"]
if reader.Decomposepolyhedra != 1:
    fail("ParaView's reader should decompose polyhedra by default")
deform = DGMFDeform(Input=reader)  # noqa: F821 (defined by LoadPlugin)
deform.MovingBoundaries = ["/Root/boundary/wing"]
deform.RotationCenter = [0.25, 0.007, 0.0]
deform.RotationAngles = [0.0, 0.0, args.angle]
UpdatePipeline(proxy=deform)

shutil.rmtree(args.out, ignore_errors=True)
SaveData(os.path.join(args.out, "case.foam"), proxy=deform)
written = points_text(args.out)
expected = points_text(args.reference)
source = points_text(args.case)
if len(written) != len(source):
    fail("%d points written, the case has %d" % (len(written), len(source)))
differing = sum(1 for a, b in zip(written, expected) if a != b)
if differing:
    fail("%d of %d points differ from dgmf-deform's" % (differing, len(written)))
print("SaveData wrote %d points, the same as dgmf-deform's" % len(written))

env = dict(os.environ, WM_PROJECT_DIR=os.environ.get("WM_PROJECT_DIR", "/usr/share/openfoam"))
env.pop("LD_PRELOAD", None)
log = subprocess.run(["checkMesh", "-constant"], cwd=args.out, env=env, text=True,
                     stdout=subprocess.PIPE, stderr=subprocess.STDOUT).stdout
with open(args.baseline) as handle:
    baseline = handle.read()
if "FOAM FATAL" in log:
    fail("checkMesh: " + log[-1000:])
failures = lambda text: set(l.split("=")[0].split(":")[0] for l in text.splitlines()
                            if l.startswith(" ***"))
new = failures(log) - failures(baseline)
if new:
    fail("new checkMesh failures: %s" % new)
print("checkMesh: no failed check that the undeformed mesh does not have")
print("OpenFOAM case written from pvpython")
