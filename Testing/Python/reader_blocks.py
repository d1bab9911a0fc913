"""A mesh written as a CFD reader gives it, for the distributed tests: a multiblock (.vtm) of the
volume (`internalMesh`) and, under `boundary`, one polydata per named patch on points of its own
(as the OpenFOAM reader's patches)."""
from vtkmodules.vtkCommonDataModel import (vtkCellArray, vtkCompositeDataSet, vtkMultiBlockDataSet,
                                           vtkPolyData)
from vtkmodules.vtkFiltersCore import vtkCleanPolyData
from vtkmodules.vtkIOXML import vtkXMLMultiBlockDataWriter, vtkXMLUnstructuredGridWriter


def write_reader_blocks(volume, points, patches, path):
    """Writes `volume` and `patches` ({name: [faces as point-id lists of `points`]}) to `path`."""
    boundary = vtkMultiBlockDataSet()
    for index, (name, faces) in enumerate(patches.items()):
        polys = vtkCellArray()
        for face in faces:
            polys.InsertNextCell(len(face), face)
        patch = vtkPolyData()
        patch.SetPoints(points)
        patch.SetPolys(polys)
        clean = vtkCleanPolyData()  # keeps the points its faces use, unmerged
        clean.SetInputData(patch)
        clean.PointMergingOff()
        clean.Update()
        boundary.SetBlock(index, clean.GetOutput())
        boundary.GetMetaData(index).Set(vtkCompositeDataSet.NAME(), name)
    blocks = vtkMultiBlockDataSet()
    blocks.SetBlock(0, volume)
    blocks.GetMetaData(0).Set(vtkCompositeDataSet.NAME(), "internalMesh")
    blocks.SetBlock(1, boundary)
    blocks.GetMetaData(1).Set(vtkCompositeDataSet.NAME(), "boundary")
    writer = vtkXMLMultiBlockDataWriter()
    writer.SetInputData(blocks)
    writer.SetFileName(path)
    writer.SetDataModeToBinary()
    assert writer.Write() == 1, path


def deform_by_name(plugin, path, moving, **properties):
    """The plugin's DGMF Deform on the blocks at `path` (as written above), boundaries chosen by
    name (`moving`: a list), no marker or displacement array, the other `properties` set (pvbatch,
    one process: the serial reference). Returns its output, a multiblock."""
    from paraview import simple
    simple.LoadPlugin(plugin, remote=False, ns=globals())
    deform = globals()["DGMFDeform"](Input=simple.XMLMultiBlockDataReader(FileName=[path]))
    deform.BoundaryMarkerArray = ["POINTS", "None"]
    deform.DisplacementArray = ["POINTS", "None"]
    deform.MovingBoundaries = moving
    for name, value in properties.items():
        setattr(deform, name, value)
    deform.UpdatePipeline()
    return deform.GetClientSideObject().GetOutputDataObject(0)


def write_binary(grid, path):
    """Writes the unstructured grid `grid` to `path` (.vtu, inline binary: stock VTK reads it)."""
    writer = vtkXMLUnstructuredGridWriter()
    writer.SetInputData(grid)
    writer.SetFileName(path)
    writer.SetDataModeToBinary()
    assert writer.Write() == 1, path
