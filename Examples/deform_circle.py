"""Deform the rotating circle with the DGMF plugin in pvpython (the README's script).

    build/bin/dgmf-pvpython Examples/deform_circle.py Data/rotating_circle.vtu circle_90.vtu
    LD_PRELOAD=$PWD/build/lib/libdgmf_expat_fix.so pvpython Examples/deform_circle.py \
        Data/rotating_circle.vtu circle_90.vtu

The plugin is the file the DGMF_PLUGIN environment variable names (dgmf-pvpython sets it) or,
when that is not set, build/lib/dgmf-plugins/DGMFPlugin/DGMFPlugin.so in this source tree; when
the file is not there, the script exits with a message saying what to run. The preload is the
expat work-around that Debian 12's libexpat (deb12u2 and later) needs: see the README.
"""
import os
import sys

from paraview.simple import *  # noqa: F401,F403 (ParaView's scripting style)

input_path, output_path = sys.argv[1], sys.argv[2]
plugin = os.environ.get("DGMF_PLUGIN") or os.path.join(
    os.path.dirname(os.path.abspath(__file__)), os.pardir, "build", "lib", "dgmf-plugins",
    "DGMFPlugin", "DGMFPlugin.so")
if not os.path.isfile(plugin):
    sys.exit("deform_circle.py: no DGMF plugin at %s: run the script with build/bin/dgmf-pvpython, "
             "or set DGMF_PLUGIN to the path of DGMFPlugin.so" % os.path.normpath(plugin))
LoadPlugin(plugin, remote=False, ns=globals())

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
