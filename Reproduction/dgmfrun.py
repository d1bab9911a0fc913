"""Shared helpers of the reproduction scripts (run them with pvpython; see scripts/reproduce.sh).

A script reads a mesh with VTK's XML reader (asserting its point and cell counts), adds the point
arrays it needs (the twisted bar's bump, the wing's fold) with numpy, feeds the grid to the
plugin's ``DGMFDeform`` filter through a trivial producer, and reads the quality summary from the
filter's output. Results go to CSV files (``write_csv``) and quality pictures (``render_quality``).

Conventions shared by all scripts:
- Angles are given in the paper's sense. The paper's rotation matrices turn clockwise for a
  positive angle, ours (``RotationAngles``) counter-clockwise, so ``PAPER_SENSE = -1`` converts.
- The DGMF runs use r0s = 1 and u1 unless stated (the paper's settings).
"""
import argparse
import csv
import math
import os
import time

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader

from paraview import simple

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DATA = os.path.join(ROOT, "Data")
RESULTS = os.path.join(ROOT, "Documentation", "results")
DEFAULT_PLUGIN = os.path.join(ROOT, "build", "lib", "dgmf-plugins", "DGMFPlugin", "DGMFPlugin.so")

PAPER_SENSE = -1.0
"""Multiply the paper's (clockwise) angles by this to get our RotationAngles (counter-clockwise)."""

MESHES = {
    "rotating_circle": (822, 1529),
    "rotating_rectangle": (768, 1434),
    "twisted_bar": (2232, 4154),
}
"""Point and cell counts of the committed meshes (Data/README.md)."""

MARKER = "BoundaryMarker"
MOVING = 2


def parser(description):
    """An argparse parser with the options every script takes."""
    result = argparse.ArgumentParser(description=description)
    result.add_argument("--plugin", default=os.environ.get("DGMF_PLUGIN", DEFAULT_PLUGIN),
                        help="path of DGMFPlugin.so (default: $DGMF_PLUGIN or the build tree)")
    result.add_argument("--data", default=DATA, help="folder of the committed meshes")
    result.add_argument("--output", default=RESULTS, help="folder for CSV files and pictures")
    result.add_argument("--no-pictures", action="store_true", help="skip the rendered pictures")
    return result


def load_plugin(path):
    """Load the DGMF plugin into paraview.simple (the filter becomes simple.DGMFDeform)."""
    if not os.path.exists(path):
        raise SystemExit(f"plugin not found: {path} (build first: bash scripts/build.sh)")
    simple.LoadPlugin(path, remote=False, ns=vars(simple))


def read_grid(path, points=None, cells=None):
    """Read a .vtu file; assert its point and cell counts when given (Debian 12's expat bug
    makes failed reads look like empty meshes)."""
    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    grid = reader.GetOutput()
    counts = (grid.GetNumberOfPoints(), grid.GetNumberOfCells())
    assert counts[0] > 0 and counts[1] > 0, f"{path}: read an empty mesh"
    if points is not None:
        expected = (points, cells)
        assert counts == expected, f"{path}: {counts} points/cells, expected {expected}"
    return grid


def read_case(name, data_dir=DATA):
    """Read one of the committed 2D meshes by name, with its counts checked."""
    return read_grid(os.path.join(data_dir, name + ".vtu"), *MESHES[name])


def points_of(grid):
    """The grid's points as an (n, 3) numpy array (a view)."""
    return vtk_to_numpy(grid.GetPoints().GetData())


def marker_of(grid):
    """The BoundaryMarker array as numpy."""
    return vtk_to_numpy(grid.GetPointData().GetArray(MARKER))


def set_point_vectors(grid, name, values):
    """Add (or replace) a 3-component double point array."""
    array = numpy_to_vtk(np.ascontiguousarray(values, dtype=np.float64), deep=1)
    array.SetName(name)
    grid.GetPointData().AddArray(array)
    grid.Modified()


def producer(grid):
    """A pipeline source that outputs ``grid`` (builtin session)."""
    source = simple.PVTrivialProducer()
    source.GetClientSideObject().SetOutput(grid)
    source.UpdatePipeline()
    return source


def _entry(proxy, name, prefix):
    """The enumeration text of property ``name`` that starts with ``prefix``."""
    for text in proxy.GetProperty(name).Available:
        if text.startswith(prefix):
            return text
    raise KeyError(f"{name}: no entry starting with {prefix!r}")


def deform_filter(source, center=(0.0, 0.0, 0.0), threads=0):
    """A DGMFDeform proxy on ``source`` reading the BoundaryMarker array, no displacement."""
    deform = simple.DGMFDeform(Input=source)
    deform.BoundaryMarkerArray = ["POINTS", MARKER]
    deform.DisplacementArray = ["POINTS", "None"]
    deform.RotationCenter = list(center)
    deform.NumberOfThreads = threads
    return deform


def configure(deform, method, angle=0.0, displacement=None, mode=2, damping=1):
    """Set the method (DGMF, DGM, DGRBF, RBF, IDW), the rotation angle about z (our sense, degrees),
    the displacement array (None: no shape deformation), DGMF's mode (1 or 2) and damping (1..7)."""
    deform.Method = method
    deform.RotationAngles = [0.0, 0.0, angle]
    deform.DisplacementArray = ["POINTS", displacement or "None"]
    deform.DeformationMode = _entry(deform, "DeformationMode", f"DGMF{mode}:")
    deform.DampingFunction = _entry(deform, "DampingFunction", f"u{damping}:")


def execute(deform):
    """Run the filter (forced) and return (output grid, wall-clock seconds, CPU seconds)."""
    algorithm = deform.GetClientSideObject()
    algorithm.Modified()
    wall, cpu = time.perf_counter(), time.process_time()
    algorithm.Update()
    wall, cpu = time.perf_counter() - wall, time.process_time() - cpu
    return algorithm.GetOutputDataObject(0), wall, cpu


def quality(output):
    """The filter's quality summary: dict with mean, minimum and inverted (cell count)."""
    field = output.GetFieldData()
    value = lambda name: field.GetArray(name).GetTuple1(0)  # noqa: E731
    return {"mean": value("SizeSkewMean"), "minimum": value("SizeSkewMinimum"),
            "inverted": int(value("InvertedCellCount"))}


def run(deform, method, **kwargs):
    """configure() then execute(); return the quality dict (with wall/cpu seconds)."""
    configure(deform, method, **kwargs)
    output, wall, cpu = execute(deform)
    result = quality(output)
    result.update(wall=wall, cpu=cpu)
    return result


def write_csv(path, rows, columns):
    """Write rows (dicts) with the given columns; floats with 6 significant digits."""
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w", newline="") as stream:
        writer = csv.writer(stream, lineterminator="\n")
        writer.writerow(columns)
        for row in rows:
            writer.writerow([_format(row[c]) for c in columns])
    print(f"wrote {path}")


def _format(value):
    """CSV text of a value: floats with 6 significant digits."""
    return f"{value:.6g}" if isinstance(value, float) else str(value)


def rotation_z(degrees):
    """The 3x3 matrix of a counter-clockwise rotation about z."""
    c, s = math.cos(math.radians(degrees)), math.sin(math.radians(degrees))
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


def render_quality(source, path, center, half_height, title, size=(800, 600), camera=None,
                   lit=False, edges=True):
    """Render ``source`` coloured by SizeSkew (cells, bands of 0.1) with its edges, offscreen.

    2D: ``center`` (x, y) and ``half_height`` (parallel projection, looking down z). 3D:
    ``camera`` = (position, focal point, view up), with a parallel projection of ``half_height``
    when it is given, a perspective one otherwise. Unlit (flat colours) unless ``lit``; cell
    edges drawn unless ``edges`` is false.
    """
    view = simple.CreateRenderView()
    view.ViewSize = list(size)
    view.OrientationAxesVisibility = 0
    view.Background = [1.0, 1.0, 1.0]
    if hasattr(view, "UseColorPaletteForBackground"):
        view.UseColorPaletteForBackground = 0
    display = simple.Show(source, view)
    display.Representation = "Surface With Edges" if edges else "Surface"
    display.EdgeColor = [0.15, 0.15, 0.15]
    if not lit:
        display.Ambient, display.Diffuse, display.Specular = 1.0, 0.0, 0.0
    simple.ColorBy(display, ("CELLS", "SizeSkew"))
    _quality_colors(view)
    label = simple.Text(Text=title)
    text = simple.Show(label, view)
    text.Color, text.FontSize, text.WindowLocation = [0.0, 0.0, 0.0], 14, "Upper Center"
    text.ShowBorder, text.BackgroundColor = "Always", [1.0, 1.0, 1.0, 0.85]
    simple.Render(view)  # the first render resets the camera: set ours after it
    if camera is None:
        camera = ([center[0], center[1], 10.0], [center[0], center[1], 0.0], [0.0, 1.0, 0.0])
    view.CameraPosition, view.CameraFocalPoint, view.CameraViewUp = (list(v) for v in camera)
    if half_height is not None:
        view.CameraParallelProjection = 1
        view.CameraParallelScale = half_height
    simple.Render(view)
    simple.SaveScreenshot(path, view, ImageResolution=list(size), CompressionLevel="9")
    simple.Delete(label)
    simple.Delete(view)
    shrink_png(path)
    print(f"wrote {path}")


def _quality_colors(view):
    """The SizeSkew colour map: Jet on [0, 1] in 10 bands, with its scalar bar."""
    lut = simple.GetColorTransferFunction("SizeSkew")
    lut.ApplyPreset("Jet", True)
    lut.RescaleTransferFunction(0.0, 1.0)
    lut.AutomaticRescaleRangeMode = "Never"
    lut.Discretize, lut.NumberOfTableValues = 1, 10
    bar = simple.GetScalarBar(lut, view)
    bar.Title, bar.ComponentTitle = "SizeSkew", ""
    bar.TitleColor = bar.LabelColor = [0.0, 0.0, 0.0]
    bar.RangeLabelFormat, bar.LabelFormat = "%.1f", "%.1f"
    bar.DrawBackground, bar.BackgroundColor = 1, [1.0, 1.0, 1.0, 0.8]
    bar.WindowLocation = "Lower Right Corner"
    bar.Visibility = 1


def shrink_png(path, colors=64):
    """Rewrite a PNG with a palette of ``colors`` colours (pictures use 10 colour bands, so this
    loses next to nothing and makes the files 4 to 5 times smaller)."""
    from PIL import Image  # matplotlib's dependency, present with Debian's python3-matplotlib
    with Image.open(path) as image:
        palette = image.convert("RGB").quantize(colors=colors, dither=0)
    palette.save(path, optimize=True)
