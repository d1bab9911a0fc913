"""The plugin's choices come from the core's one method table: the Method property offers exactly
the methods of MethodTable.def (values and names), each runs and names itself in the field data;
and Size Skew Quality measures the multiblock output that DGMF Deform gives for a multiblock."""
import argparse
import re

from paraview import servermanager
from paraview import simple


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--plugin", required=True)
    parser.add_argument("--data", required=True)
    parser.add_argument("--table", required=True)
    args = parser.parse_args()
    table = []
    with open(args.table) as lines:
        for line in lines:
            match = re.match(r"DGMF_METHOD\((\d+), (\w+), (\w+),", line)
            if match:
                table.append((int(match.group(1)), match.group(2)))
    assert [value for value, _ in table] == list(range(len(table))), table

    simple.LoadPlugin(args.plugin, remote=False, ns=globals())
    reader = simple.XMLUnstructuredGridReader(FileName=[args.data])
    reader.UpdatePipeline()
    assert reader.GetDataInformation().GetNumberOfPoints() == 822
    deform = DGMFDeform(Input=reader)  # noqa: F821 (defined by LoadPlugin)
    offered = list(deform.GetProperty("Method").Available)
    assert offered == [name for _, name in table], (offered, table)
    deform.BoundaryMarkerArray = ["POINTS", "BoundaryMarker"]
    deform.RotationAngles = [0, 0, 10]
    for value, name in table:
        deform.Method = name
        deform.UpdatePipeline()
        result = servermanager.Fetch(deform)
        assert result.GetNumberOfPoints() == 822, name
        reported = result.GetFieldData().GetAbstractArray("Method").GetValue(0)
        assert reported == name, (reported, name)

    # Size Skew Quality on a multiblock: the DGMF Deform output of the same blocks.
    blocks = simple.GroupDatasets(Input=[reader])
    deformed = DGMFDeform(Input=blocks)  # noqa: F821
    deformed.BoundaryMarkerArray = ["POINTS", "BoundaryMarker"]
    deformed.RotationAngles = [0, 0, 45]
    quality = SizeSkewQuality(Input=deformed, Reference=blocks)  # noqa: F821
    quality.UpdatePipeline()
    measured = servermanager.Fetch(quality).GetFieldData()
    own = servermanager.Fetch(deformed).GetFieldData()
    for name in ("SizeSkewMinimum", "InvertedCellCount"):
        assert measured.GetArray(name).GetTuple1(0) == own.GetArray(name).GetTuple1(0), name
    print("method table OK: %s" % ", ".join(name for _, name in table))


if __name__ == "__main__":
    main()
