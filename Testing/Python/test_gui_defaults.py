"""What the ParaView proxy gives a user who does not set everything: array choices that never
default to an unrelated array (a velocity is not a displacement), the conventional names taken when
present, the rotation centre's default as its help says (0 0 0), and the Body Centroid
mode turning a body about itself."""
import argparse

from paraview import servermanager
from paraview import simple


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--plugin", required=True)
    parser.add_argument("--data", required=True)
    args = parser.parse_args()
    simple.LoadPlugin(args.plugin, remote=False, ns=globals())

    # A solver's result: p (active scalars) and U (active vectors), no marker, no displacement.
    wavelet = simple.Wavelet()
    pressure = simple.Calculator(Input=wavelet, ResultArrayName="p", Function="RTData")
    velocity = simple.Calculator(Input=pressure, ResultArrayName="U",
                                 Function="RTData*iHat+jHat")
    velocity.ResultArrayType = "Double"
    result = simple.Tetrahedralize(Input=velocity)
    result.UpdatePipeline()
    deform = DGMFDeform(Input=result)  # noqa: F821 (defined by LoadPlugin)
    assert deform.BoundaryMarkerArray[1] == "None", deform.BoundaryMarkerArray
    assert deform.DisplacementArray[1] == "None", deform.DisplacementArray
    assert list(deform.RotationCenter) == [0.0, 0.0, 0.0], deform.RotationCenter
    assert deform.RotationCenterMode == "Given", deform.RotationCenterMode

    # The conventional names are taken.
    reader = simple.XMLUnstructuredGridReader(FileName=[args.data])
    reader.UpdatePipeline()
    assert reader.GetDataInformation().GetNumberOfPoints() == 822
    circle = DGMFDeform(Input=reader)  # noqa: F821
    assert circle.BoundaryMarkerArray[1] == "BoundaryMarker", circle.BoundaryMarkerArray
    assert circle.DisplacementArray[1] == "Displacement", circle.DisplacementArray

    # The centroid mode: the circle moved by (3, 1) turns about its moving nodes' centroid, as the
    # circle in place turns about that centroid given as the centre.
    mesh = servermanager.Fetch(reader)
    marker = mesh.GetPointData().GetArray("BoundaryMarker")
    moving = [mesh.GetPoint(i) for i in range(822) if marker.GetTuple1(i) == 2]
    centroid = [sum(p[c] for p in moving) / len(moving) for c in range(3)]
    circle.DisplacementArray = ["POINTS", "None"]
    circle.RotationAngles = [0, 0, 90]
    circle.RotationCenter = centroid
    circle.UpdatePipeline()
    shifted = simple.Transform(Input=reader)
    shifted.Transform.Translate = [3.0, 1.0, 0.0]
    turned = DGMFDeform(Input=shifted)  # noqa: F821
    turned.BoundaryMarkerArray = ["POINTS", "BoundaryMarker"]
    turned.DisplacementArray = ["POINTS", "None"]
    turned.RotationAngles = [0, 0, 90]
    turned.RotationCenterMode = "Body Centroid"
    turned.UpdatePipeline()
    a = servermanager.Fetch(circle)
    b = servermanager.Fetch(turned)
    assert a.GetNumberOfPoints() == b.GetNumberOfPoints() == 822
    worst = 0.0
    for i in range(822):
        p, q = a.GetPoint(i), b.GetPoint(i)
        worst = max(worst, abs(q[0] - 3.0 - p[0]), abs(q[1] - 1.0 - p[1]))
    print("centroid mode against the centroid given: %.3g" % worst)
    assert worst < 1e-6, worst  # the moved mesh's points are single precision
    print("defaults OK")


if __name__ == "__main__":
    main()
