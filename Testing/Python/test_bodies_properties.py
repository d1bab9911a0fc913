"""The ParaView proxy exposes the body-id array, the per-body motions and the rigid-motion modes,
and they work: two circles turning +-45 degrees through the plugin give the C++ filter's result
(no inverted cell, the same minimum quality), and the extracted mode reports the fitted angles."""
import argparse
import sys

from paraview import servermanager
from paraview import simple
from vtkmodules.vtkCommonCore import vtkDoubleArray


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--plugin", required=True)
    parser.add_argument("--data", required=True)
    args = parser.parse_args()
    simple.LoadPlugin(args.plugin, remote=False, ns=globals())
    reader = simple.XMLUnstructuredGridReader(FileName=[args.data])
    reader.UpdatePipeline()
    assert reader.GetDataInformation().GetNumberOfPoints() == 1118

    deform = DGMFDeform(Input=reader)  # noqa: F821 (defined by LoadPlugin)
    for name in ("BodyIdArray", "BodyMotions", "RigidMotionMode"):
        assert name in deform.ListProperties(), name
    assert "Extracted" in deform.GetProperty("RigidMotionMode").Available
    # The body-id array is opt-in: it must not default to another 1-component array (the marker).
    assert deform.BodyIdArray[1] == "None", deform.BodyIdArray
    deform.BoundaryMarkerArray = ["POINTS", "BoundaryMarker"]
    deform.BodyIdArray = ["POINTS", "BodyId"]
    deform.BodyMotions = [1, 0, 0, 0, -2.5, 0, 0, 0, 0, 45, 2, 0, 0, 0, 2.5, 0, 0, 0, 0, -45]
    deform.UpdatePipeline()
    field = servermanager.Fetch(deform).GetFieldData()
    inverted = field.GetArray("InvertedCellCount").GetTuple1(0)
    minimum = field.GetArray("SizeSkewMinimum").GetTuple1(0)
    print("two circles +-45 degrees: %d inverted cells, SizeSkew minimum %.4f" % (inverted, minimum))
    assert inverted == 0 and minimum > 0.03, (inverted, minimum)

    # The same rotations given as displacements, extracted per body.
    displaced = simple.Calculator(Input=reader, ResultArrayName="Rotation")
    displaced.Function = (
        "(BodyId==1)*((-2.5+cos(0.7853981633974483)*(coordsX+2.5)-sin(0.7853981633974483)*coordsY-coordsX)*iHat"
                          "+(sin(0.7853981633974483)*(coordsX+2.5)+cos(0.7853981633974483)*coordsY-coordsY)*jHat)"
                          "+(BodyId==2)*((2.5+cos(0.7853981633974483)*(coordsX-2.5)+sin(0.7853981633974483)*coordsY-coordsX)*iHat"
                          "+(-sin(0.7853981633974483)*(coordsX-2.5)+cos(0.7853981633974483)*coordsY-coordsY)*jHat)")
    extracted = DGMFDeform(Input=displaced)  # noqa: F821
    extracted.BoundaryMarkerArray = ["POINTS", "BoundaryMarker"]
    extracted.BodyIdArray = ["POINTS", "BodyId"]
    extracted.DisplacementArray = ["POINTS", "Rotation"]
    extracted.RigidMotionMode = "Extracted"
    extracted.UpdatePipeline()
    angles = servermanager.Fetch(extracted).GetFieldData().GetArray("FittedRotationAngle")
    assert angles is not None and angles.GetNumberOfTuples() == 2
    print("fitted angles: %.6f, %.6f" % (angles.GetTuple1(0), angles.GetTuple1(1)))
    assert abs(angles.GetTuple1(0) - 45) < 1e-6 and abs(angles.GetTuple1(1) - 45) < 1e-6
    print("bodies OK")
    return 0


if __name__ == "__main__":
    sys.exit(main())
