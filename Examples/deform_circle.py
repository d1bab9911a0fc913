"""Deform the rotating circle with the DGMF plugin in pvpython (the README's script).

    pvpython Examples/deform_circle.py Data/rotating_circle.vtu circle_90.vtu

The plugin is found from the DGMF_PLUGIN environment variable (the path of DGMFPlugin.so).
"""
import os
import sys

from paraview.simple import *  # noqa: F401,F403 (ParaView's scripting style)

input_path, output_path = sys.argv[1], sys.argv[2]
LoadPlugin(os.environ["DGMF_PLUGIN"], remote=False, ns=globals())

mesh = XMLUnstructuredGridReader(FileName=[input_path])
deform = DGMFDeform(Input=mesh)
deform.BoundaryMarkerArray = ["POINTS", "BoundaryMarker"]
deform.RotationCenter = [0.0, 0.0, 0.0]
deform.RotationAngles = [0.0, 0.0, 90.0]  # degrees about x, y, z
deform.DampingFunction = "u1: (1-r)^2 (r+1)"
deform.UpdatePipeline()

# Inline binary: appended-mode files cannot be read back with Debian 12's expat.
SaveData(output_path, proxy=deform, DataMode="Binary")

quality = servermanager.Fetch(deform).GetFieldData()
print("SizeSkew mean: %.4f, minimum: %.4f, inverted cells: %d" % (
    quality.GetArray("SizeSkewMean").GetTuple1(0),
    quality.GetArray("SizeSkewMinimum").GetTuple1(0),
    int(quality.GetArray("InvertedCellCount").GetTuple1(0))))
