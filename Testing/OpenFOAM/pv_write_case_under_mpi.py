"""The OpenFOAM round trip from pvbatch under MPI (2 processes), as openfoam.md says to write it:
ParaView's reader (not redistributed, every patch read), DGMF Deform by name, the plugin's writer
proxy. Process 0 compares the written points with dgmf-deform's for the same motion (--deform) and
prints the largest difference; the test (CMake) asserts it is below 1e-12, that the case has its
point count, and that no process printed an error (the process without a piece said "The input has
no unstructured grid" until 2026-11-30).

    mpiexec -np 2 pvbatch --symmetric pv_write_case_under_mpi.py --plugin P --case CASE --out OUT
            --deform DGMF_DEFORM
"""
import argparse
import os
import re
import shutil
import subprocess

from paraview import servermanager
from paraview.simple import LoadPlugin, OpenFOAMReader
from vtkmodules.vtkParallelCore import vtkMultiProcessController

parser = argparse.ArgumentParser()
parser.add_argument("--plugin", required=True)
parser.add_argument("--case", required=True)
parser.add_argument("--out", required=True)
parser.add_argument("--deform", required=True)
args = parser.parse_args()
LoadPlugin(args.plugin, ns=globals())  # DGMFDeform
rank = vtkMultiProcessController.GetGlobalController().GetLocalProcessId()
if rank == 0:
    shutil.rmtree(args.out, ignore_errors=True)
reader = OpenFOAMReader(FileName=os.path.join(args.case, "case.foam"))
# Every patch: in a distributed run the boundary not read is not found (distributed.md).
reader.MeshRegions = list(reader.MeshRegions.Available)
deform = DGMFDeform(Input=reader)
deform.DisplacementArray = ["POINTS", "None"]
deform.BoundaryMarkerArray = ["POINTS", "None"]
deform.MovingBoundaries = ["wing"]
# The one-cell-thick mesh's planes as slip boundaries: distributed runs need them named
# (distributed.md); the serial command finds them itself and gives the same 2D result.
deform.SlipBoundaries = ["front", "back"]
deform.RotationCenter = [0.25, 0.007, 0.0]
deform.RotationAngles = [0.0, 0.0, -10.0]
writer = servermanager.writers.DGMFOpenFOAMPointsWriter(
    Input=deform, FileName=os.path.join(args.out, "case.foam"), SourceCase=args.case)
writer.UpdatePipeline()


def points_of(case):
    with open(os.path.join(case, "constant", "polyMesh", "points")) as handle:
        text = handle.read()
    body = text[text.index("}", text.index("FoamFile")) + 1:]
    return [[float(v) for v in triple.split()] for triple in re.findall(r"\(([^()]*)\)", body)]


if rank == 0:
    written = points_of(args.out)
    reference = args.out + "_dgmf_deform"
    shutil.rmtree(reference, ignore_errors=True)
    subprocess.run([args.deform, args.case, reference, "--moving", "wing", "--rotate", "0", "0",
                    "-10", "--center", "0.25", "0.007", "0"], check=True, capture_output=True)
    expected = points_of(reference)
    largest = max(abs(a - b) for p, q in zip(written, expected) for a, b in zip(p, q))
    print("written by process 0: %d points, %s from dgmf-deform's" %
          (len(written), "within 1e-12" if len(written) == len(expected) and largest < 1e-12
           else "%g" % largest))
