"""A mesh written as a CFD reader gives it, for the distributed tests: a multiblock (.vtm) of the
volume (`internalMesh`) and, under `boundary`, one polydata per named patch on points of its own
(as the OpenFOAM reader's patches)."""
from vtkmodules.vtkCommonDataModel import (vtkCellArray, vtkCompositeDataSet, vtkMultiBlockDataSet,
                                           vtkPolyData)
from vtkmodules.vtkFiltersCore import vtkCleanPolyData
from vtkmodules.vtkIOXML import vtkXMLMultiBlockDataWriter


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
