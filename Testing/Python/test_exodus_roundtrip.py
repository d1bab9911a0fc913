"""A mesh through a CFD reader and writer that ParaView ships (Exodus II), deformed by the plugin.

Writes Data/sphere_in_box.vtu as an Exodus file, reads it back with ParaView's Exodus reader (a
multiblock, with the marker stored as doubles, as Exodus stores every variable), applies DGMFDeform,
writes the result as Exodus again and reads it back: nothing may be lost on the way (points, cells,
arrays), the sphere must have turned rigidly and the box must not have moved.
"""
import argparse
import math
import os
import sys

from paraview import servermanager
from paraview import simple
from vtkmodules.util.numpy_support import vtk_to_numpy


def first_leaf(data):
    """The first leaf of a composite dataset."""
    iterator = data.NewIterator()
    iterator.InitTraversal()
    return iterator.GetCurrentDataObject()


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--plugin", required=True)
    parser.add_argument("--data", required=True)
    parser.add_argument("--work", required=True)
    args = parser.parse_args()
    simple.LoadPlugin(args.plugin, remote=False, ns=globals())
    os.makedirs(args.work, exist_ok=True)

    source = simple.XMLUnstructuredGridReader(FileName=[args.data])
    source.UpdatePipeline()
    original = servermanager.Fetch(source)
    assert (original.GetNumberOfPoints(), original.GetNumberOfCells()) == (3200, 15892)
    exodus_in = os.path.join(args.work, "sphere_in_box.e")
    simple.SaveData(exodus_in, proxy=source)

    reader = simple.ExodusIIReader(FileName=[exodus_in])
    reader.PointVariables = ["BoundaryMarker"]
    deform = DGMFDeform(Input=reader)  # noqa: F821 (defined by LoadPlugin)
    deform.BoundaryMarkerArray = ["POINTS", "BoundaryMarker"]
    deform.DisplacementArray = ["POINTS", "None"]
    deform.RotationAngles = [10.0, 20.0, 30.0]
    deform.UpdatePipeline()
    result = servermanager.Fetch(deform)
    assert result.IsA("vtkMultiBlockDataSet"), result.GetClassName()
    leaf = first_leaf(result)
    assert (leaf.GetNumberOfPoints(), leaf.GetNumberOfCells()) == (3200, 15892)
    for name in ("BoundaryMarker", "GlobalNodeId", "PedigreeNodeId", "r", "f"):
        assert leaf.GetPointData().GetArray(name) is not None, name
    assert leaf.GetCellData().GetArray("SizeSkew") is not None
    assert result.GetFieldData().GetArray("InvertedCellCount").GetTuple1(0) == 0

    # The sphere turned rigidly about the origin; the box did not move.
    before = vtk_to_numpy(first_leaf(servermanager.Fetch(reader)).GetPoints().GetData())
    after = vtk_to_numpy(leaf.GetPoints().GetData())
    marker = vtk_to_numpy(leaf.GetPointData().GetArray("BoundaryMarker"))
    radius_change = max(abs(math.dist(a, (0, 0, 0)) - math.dist(b, (0, 0, 0)))
                        for a, b, m in zip(after, before, marker) if m == 2)
    static_change = max(abs(a - b).max() for a, b, m in zip(after, before, marker) if m == 1)
    moved = max(abs(a - b).max() for a, b, m in zip(after, before, marker) if m == 2)
    assert radius_change < 1e-12 and static_change == 0.0 and moved > 0.1, (
        radius_change, static_change, moved)

    # Written back as Exodus and read again: the same points and arrays.
    exodus_out = os.path.join(args.work, "sphere_in_box_deformed.e")
    simple.SaveData(exodus_out, proxy=deform)
    again = simple.ExodusIIReader(FileName=[exodus_out])
    again.PointVariables = ["BoundaryMarker", "r", "f"]
    again.ElementVariables = ["SizeSkew"]
    again.UpdatePipeline()
    reread = first_leaf(servermanager.Fetch(again))
    assert (reread.GetNumberOfPoints(), reread.GetNumberOfCells()) == (3200, 15892)
    # ParaView's Exodus writer stores single precision: the points agree to float round-off.
    difference = abs(vtk_to_numpy(reread.GetPoints().GetData()) - after).max()
    assert difference < 2e-7 * abs(after).max(), difference
    for name in ("BoundaryMarker", "r", "f"):
        assert reread.GetPointData().GetArray(name) is not None, name
    assert reread.GetCellData().GetArray("SizeSkew") is not None
    print("Exodus round trip: 3200 points, 15892 cells, largest point difference %g" % difference)
    return 0


if __name__ == "__main__":
    sys.exit(main())
