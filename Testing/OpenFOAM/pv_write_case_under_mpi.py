"""The OpenFOAM round trip from pvbatch under MPI (2 processes), as openfoam.md says to write it:
ParaView's reader (not redistributed), DGMF Deform by name, the plugin's writer proxy. Each process
prints what its writer said; the test (CMake) asserts that the case was written with the case's
point count and that no process printed an error (the process without a piece said "The input has
no unstructured grid" until 2026-11-30).

    mpiexec -np 2 pvbatch --symmetric pv_write_case_under_mpi.py --plugin P --case CASE --out OUT
"""
import argparse
import os
import shutil

from paraview import servermanager
from paraview.simple import LoadPlugin, OpenFOAMReader
from vtkmodules.vtkParallelCore import vtkMultiProcessController

parser = argparse.ArgumentParser()
parser.add_argument("--plugin", required=True)
parser.add_argument("--case", required=True)
parser.add_argument("--out", required=True)
args = parser.parse_args()
LoadPlugin(args.plugin, ns=globals())  # DGMFDeform
rank = vtkMultiProcessController.GetGlobalController().GetLocalProcessId()
if rank == 0:
    shutil.rmtree(args.out, ignore_errors=True)
reader = OpenFOAMReader(FileName=os.path.join(args.case, "case.foam"))
reader.MeshRegions = ["internalMesh", "patch/wing"]
deform = DGMFDeform(Input=reader)
deform.DisplacementArray = ["POINTS", "None"]
deform.BoundaryMarkerArray = ["POINTS", "None"]
deform.MovingBoundaries = ["wing"]
deform.RotationCenter = [0.25, 0.007, 0.0]
deform.RotationAngles = [0.0, 0.0, -10.0]
writer = servermanager.writers.DGMFOpenFOAMPointsWriter(
    Input=deform, FileName=os.path.join(args.out, "case.foam"), SourceCase=args.case)
writer.UpdatePipeline()
if rank == 0:
    points = os.path.join(args.out, "constant", "polyMesh", "points")
    with open(points) as handle:
        text = handle.read()
    count = text[text.index("}", text.index("FoamFile")) + 1:].split("(")[0].split()[-1]
    print("written by process 0: %s points" % count)
