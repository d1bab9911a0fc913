"""The ParaView plugin loads in pvpython and gives the same points as the C++ filter.

Reads the rotating circle, applies DGMFDeform with a 90-degree rotation through the plugin, and
compares the points with those written by the C++ command-line program (dgmf-deform) for the same
input and motion.
"""
import argparse
import sys

from paraview import simple
from paraview import servermanager
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader
from vtkmodules.util.numpy_support import vtk_to_numpy


def read_points(path):
    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    mesh = reader.GetOutput()
    return mesh, vtk_to_numpy(mesh.GetPoints().GetData())


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--plugin", required=True)
    parser.add_argument("--data", required=True)
    parser.add_argument("--reference", required=True)
    args = parser.parse_args()

    simple.LoadPlugin(args.plugin, remote=False, ns=globals())
    source, source_points = read_points(args.data)
    reference, reference_points = read_points(args.reference)
    assert source.GetNumberOfPoints() > 0, "the input mesh was read as empty"
    assert reference.GetNumberOfPoints() == source.GetNumberOfPoints(), (
        "the C++ output has %d points, the input %d"
        % (reference.GetNumberOfPoints(), source.GetNumberOfPoints()))

    reader = simple.XMLUnstructuredGridReader(FileName=[args.data])
    deform = DGMFDeform(Input=reader)  # noqa: F821 (defined by LoadPlugin)
    deform.BoundaryMarkerArray = ["POINTS", "BoundaryMarker"]
    deform.DisplacementArray = ["POINTS", "Displacement"]
    deform.RotationCenter = [0.0, 0.0, 0.0]
    deform.RotationAngles = [0.0, 0.0, 90.0]
    deform.UpdatePipeline()
    result = servermanager.Fetch(deform)
    points = vtk_to_numpy(result.GetPoints().GetData())
    assert points.shape == reference_points.shape, (points.shape, reference_points.shape)
    difference = abs(points - reference_points).max()
    print("points: %d, largest difference from the C++ filter: %g" % (len(points), difference))
    assert difference == 0.0, "the plugin and the C++ filter disagree"
    for name in ("r", "f"):
        assert result.GetPointData().GetArray(name) is not None, name
    assert result.GetCellData().GetArray("SizeSkew") is not None
    assert result.GetFieldData().GetArray("InvertedCellCount").GetTuple1(0) == 0
    return 0


if __name__ == "__main__":
    sys.exit(main())
