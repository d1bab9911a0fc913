"""Pictures of an OpenFOAM case before and after dgmf-deform (Documentation/openfoam.md):
the mesh around the wing of the wingMotion 2D tutorial, read with ParaView's OpenFOAM reader.

    build/bin/dgmf-pvpython Examples/openfoam_wing_pictures.py CASE DEFORMED_CASE OUT_PREFIX

writes OUT_PREFIX_before.png and OUT_PREFIX_after.png (OUT_PREFIX's folder made if new; exit 1
if a picture cannot be written) (the front plane, edges shown, cells
coloured by the deformed case's SizeSkew computed with the Size Skew Quality filter when the
plugin is given in DGMF_PLUGIN; dgmf-pvpython sets it). Without an X display the script runs
itself again under xvfb-run (dgmf_display.py).
"""
import os
import sys

from paraview.simple import (ColorBy, GetActiveViewOrCreate, GetColorTransferFunction, Hide,
                             OpenFOAMReader, Render, SaveScreenshot, Show)

from dgmf_display import ensure_display

ensure_display("openfoam_wing_pictures.py")
case, deformed, prefix = sys.argv[1:4]
# The pictures' folder is made if new (SaveScreenshot does not, and only says it cannot write).
if os.path.dirname(prefix):
    os.makedirs(os.path.dirname(prefix), exist_ok=True)


def read(directory):
    foam = os.path.join(directory, "case.foam")
    if not os.path.exists(foam):
        open(foam, "w").close()
    reader = OpenFOAMReader(FileName=foam)
    reader.MeshRegions = ["internalMesh"]
    reader.Decomposepolyhedra = 0
    reader.CellArrays = []
    return reader


view = GetActiveViewOrCreate("RenderView")
view.ViewSize = [800, 600]
view.OrientationAxesVisibility = 0
view.Background = [1, 1, 1]
if hasattr(view, "UseColorPaletteForBackground"):
    view.UseColorPaletteForBackground = 0
before = read(case)
after = read(deformed)
plugin = os.environ.get("DGMF_PLUGIN")
colour = None
if plugin:
    from paraview.simple import LoadPlugin
    LoadPlugin(plugin, ns=globals())
    colour = SizeSkewQuality(Input=after, Reference=before)  # noqa: F821 (from the plugin)
    colour.UpdatePipeline()

for name, source in (("before", before), ("after", colour or after)):
    display = Show(source, view)
    display.SetRepresentationType("Surface With Edges")
    display.EdgeColor = [0.15, 0.15, 0.15]
    if name == "after" and colour is not None:
        ColorBy(display, ("CELLS", "SizeSkew"))
        lut = GetColorTransferFunction("SizeSkew")
        lut.ApplyPreset("Viridis (matplotlib)", True)
        lut.RescaleTransferFunction(0.0, 1.0)
        display.SetScalarBarVisibility(view, True)
    else:
        display.ColorArrayName = ["POINTS", ""]
        display.AmbientColor = display.DiffuseColor = [0.85, 0.88, 0.95]
    Render(view)  # the first render places the camera on the data: then the close-up
    view.CameraPosition = [0.45, -0.2, 5.0]
    view.CameraFocalPoint = [0.45, -0.2, 0.125]
    view.CameraViewUp = [0, 1, 0]
    view.CameraParallelProjection = 1
    view.CameraParallelScale = 0.62
    Render(view)
    picture = "%s_%s.png" % (prefix, name)
    if not SaveScreenshot(picture, view, ImageResolution=[800, 600]) or not os.path.exists(picture):
        sys.exit("could not write %s" % picture)
    Hide(source, view)
print("wrote %s_before.png and %s_after.png" % (prefix, prefix))
