"""The ParaView proxy exposes the large-motion properties, and they work: the thin slab rotated by
90 degrees about z, with the quality guard on (automatic sub-steps, threshold 0.2), has no inverted
cell and a minimum SizeSkew of at least 0.2, and reports the sub-steps and repairs in field data;
with the defaults it has inverted cells."""
import argparse
import sys

from paraview import servermanager
from paraview import simple


def field(proxy, name):
    array = servermanager.Fetch(proxy).GetFieldData().GetArray(name)
    assert array is not None, name
    return array.GetTuple1(0)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--plugin", required=True)
    parser.add_argument("--data", required=True)
    args = parser.parse_args()
    simple.LoadPlugin(args.plugin, remote=False, ns=globals())
    reader = simple.XMLUnstructuredGridReader(FileName=[args.data])
    reader.UpdatePipeline()
    assert reader.GetDataInformation().GetNumberOfPoints() == 2810

    deform = DGMFDeform(Input=reader)  # noqa: F821 (defined by LoadPlugin)
    assert deform.SubSteps == 1 and deform.RepairThreshold == 0, "large motions must be off by default"
    assert deform.RepairLayers == 2 and deform.RepairPasses == 20
    deform.BoundaryMarkerArray = ["POINTS", "BoundaryMarker"]
    deform.DisplacementArray = ["POINTS", "Displacement"]
    deform.RotationCenter = [0, 0, 0]
    deform.RotationAngles = [0, 0, 90]
    deform.UpdatePipeline()
    inverted = field(deform, "InvertedCellCount")
    print("one step: %d inverted cells" % inverted)
    assert inverted > 0

    deform.SubSteps = 0
    deform.RepairThreshold = 0.2
    deform.UpdatePipeline()
    inverted = field(deform, "InvertedCellCount")
    minimum = field(deform, "SizeSkewMinimum")
    steps, repaired = field(deform, "SubStepsUsed"), field(deform, "RepairedCellCount")
    print("guarded: %d inverted cells, minimum %.4f, %d sub-steps, %d cells repaired"
          % (inverted, minimum, steps, repaired))
    assert inverted == 0 and minimum >= 0.2 and steps >= 1 and repaired > 0
    assert field(deform, "UnrepairedCellCount") == 0
    print("large motion OK")
    return 0


if __name__ == "__main__":
    sys.exit(main())
