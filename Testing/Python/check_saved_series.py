"""Reads back the series ParaView's Save Data wrote (a .pvd) and checks it frame by frame.

    pvpython check_saved_series.py SERIES.pvd FRAMES POINTS

Every frame must have POINTS points (Debian 12's expat can make VTK read a file as empty: the
count is checked), the times must run from 0 to 1, the airfoil must have moved at a quarter period,
and the last frame (one period later) must have the first frame's points, bit for bit. Prints
"series OK".
"""
import sys

from paraview import servermanager
from paraview.simple import PVDReader
from vtkmodules.util.numpy_support import vtk_to_numpy

path, frames, points = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
reader = PVDReader(FileName=path)
reader.UpdatePipelineInformation()
times = list(reader.TimestepValues)
if len(times) != frames or times[0] != 0.0 or abs(times[-1] - 1.0) > 1e-12:
    sys.exit("FAILED: times %s" % times)
coordinates = []
for t in times:
    reader.UpdatePipeline(t)
    data = servermanager.Fetch(reader)
    block = data.GetBlock(0) if data.IsA("vtkMultiBlockDataSet") else data
    if block.GetNumberOfPoints() != points:
        sys.exit("FAILED: time %g has %d points, not %d" % (t, block.GetNumberOfPoints(), points))
    if block.GetFieldData().GetArray("MotionTime").GetTuple1(0) != t:
        sys.exit("FAILED: time %g has the motion of another time" % t)
    coordinates.append(vtk_to_numpy(block.GetPoints().GetData()).copy())
quarter = frames // 4
if abs(coordinates[quarter] - coordinates[0]).max() < 0.05:
    sys.exit("FAILED: the airfoil did not move at a quarter period")
if not (coordinates[-1] == coordinates[0]).all():
    sys.exit("FAILED: one period later the points differ")
print("series OK: %d frames of %d points" % (frames, points))
