"""Motion in time through the ParaView proxy (issue 19): the axis-and-angle properties, a
trajectory table from ParaView's CSV reader on the Trajectory input, its times reported, a law's
series written into one Exodus file by ParaView's Exodus writer, and a table with unsorted times
refused (no output).

    pvpython test_motion_properties.py --plugin PLUGIN --data rotating_rectangle.vtu --work DIR

Prints "motion properties OK".
"""
import argparse
import os
import sys

from paraview import servermanager
from paraview.simple import CSVReader, LoadPlugin, OpenDataFile, XMLUnstructuredGridReader
from vtkmodules.util.numpy_support import vtk_to_numpy

parser = argparse.ArgumentParser()
parser.add_argument("--plugin", required=True)
parser.add_argument("--data", required=True)
parser.add_argument("--work", required=True)
args = parser.parse_args()
os.makedirs(args.work, exist_ok=True)
LoadPlugin(args.plugin, remote=False, ns=globals())

mesh = XMLUnstructuredGridReader(FileName=[args.data])
mesh.UpdatePipeline()
points = servermanager.Fetch(mesh).GetNumberOfPoints()
if points != 768:  # Debian 12's expat can make VTK read the file as empty
    sys.exit("FAILED: read %d points" % points)


def deformed(**properties):
    deform = DGMFDeform(Input=mesh)  # noqa: F821 (defined by LoadPlugin)
    deform.BoundaryMarkerArray = ["POINTS", "BoundaryMarker"]
    for name, value in properties.items():
        setattr(deform, name, value)
    return deform


def coordinates(proxy, time=None):
    proxy.UpdatePipeline(time) if time is not None else proxy.UpdatePipeline()
    data = servermanager.Fetch(proxy)
    return vtk_to_numpy(data.GetPoints().GetData()).copy(), data.GetFieldData()


euler, _ = coordinates(deformed(RotationCenter=[0.3, 0.1, 0], RotationAngles=[0, 0, 30]))
axis, _ = coordinates(deformed(RotationCenter=[0.3, 0.1, 0], RotationAxis=[0, 0, 3],
                               RotationAngle=30))
if abs(euler - axis).max() > 1e-12:
    sys.exit("FAILED: RotationAngle about RotationAxis is not RotationAngles' rotation")

table_path = os.path.join(args.work, "trajectory.csv")
with open(table_path, "w") as handle:
    handle.write("Time,Body,TX,TY,TZ,QW,QX,QY,QZ\n"
                 "0,1,0,0,0,1,0,0,0\n"
                 "1,1,0.4,0,0,0.96592582628906831,0,0,0.25881904510252074\n"  # 30 degrees
                 "2,1,0.4,0,0,1,0,0,0\n")
table = CSVReader(FileName=[table_path])
moved = deformed(Trajectory=table)
moved.UpdatePipelineInformation()
if list(moved.TimestepValues) != [0.0, 1.0, 2.0]:
    sys.exit("FAILED: the table's times are not reported: %s" % list(moved.TimestepValues))
halfway, field = coordinates(moved, 0.5)
if field.GetArray("MotionTime").GetTuple1(0) != 0.5:
    sys.exit("FAILED: MotionTime")
still, _ = coordinates(deformed(Translation=[0.2, 0, 0], RotationAngle=15))
if abs(halfway - still).max() > 1e-12:
    sys.exit("FAILED: the table's motion at t = 0.5 is not half of it")
# The table removed, the filter goes back to its properties' motion (none here) and reports no
# times of its own (until 2026-11-30 the table stayed connected and kept moving the mesh).
moved.Trajectory = None
moved.UpdatePipelineInformation()
if list(moved.TimestepValues):
    sys.exit("FAILED: the removed table's times are still reported: %s" % list(moved.TimestepValues))
unmoved, field = coordinates(moved, 1.0)
original, _ = coordinates(deformed())
if abs(unmoved - original).max() != 0.0 or field.GetArray("MotionTime") is not None:
    sys.exit("FAILED: the removed table still moves the mesh")

# A law's times are increasing and distinct whatever the Time Range: given end first, it is taken
# from its low end; empty, it is one time (until 2026-11-30: [1, 0.5, 0] and [0.5, 0.5, 0.5]).
for time_range, expected in (([1.0, 0.0], [0.0, 0.5, 1.0]), ([0.5, 0.5], [0.5])):
    law = deformed(RotationLaw="Harmonic", RotationLawParameters=[0, 20, 1, 0],
                   TimeRange=time_range, NumberOfTimeSteps=3)
    law.UpdatePipelineInformation()
    if list(law.TimestepValues) != expected:
        sys.exit("FAILED: Time Range %s gives the times %s" % (time_range, list(law.TimestepValues)))

# The series in one Exodus file, through ParaView's own Exodus writer with all time steps (Save
# Data of a .exo picks the DGMF mesh-file writer, which writes into a copy of a source file).
pitching = deformed(RotationLaw="Harmonic", RotationLawParameters=[0, 20, 1, 0], NumberOfTimeSteps=5)
exodus_path = os.path.join(args.work, "pitching.exo")
if os.path.exists(exodus_path):
    os.remove(exodus_path)
writer = servermanager.writers.ExodusIIWriter(Input=pitching, FileName=exodus_path,
                                              WriteAllTimeSteps=1)
writer.UpdatePipeline()
series = OpenDataFile(exodus_path)
series.UpdatePipelineInformation()
if len(series.TimestepValues) != 5 or series.TimestepValues[-1] != 1.0:
    sys.exit("FAILED: the Exodus series has the times %s" % list(series.TimestepValues))

# Unsorted times: no output (the message naming the row is tested in C++ and on the command line).
bad_path = os.path.join(args.work, "unsorted.csv")
with open(bad_path, "w") as handle:
    handle.write("Time,TX\n0,0\n1,0.5\n0.5,0.2\n")
refused = deformed(Trajectory=CSVReader(FileName=[bad_path]))
refused.UpdatePipeline(0.5)
if servermanager.Fetch(refused).GetNumberOfPoints() != 0:
    sys.exit("FAILED: an unsorted table gave an output")
print("motion properties OK")
