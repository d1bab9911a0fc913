/**
 * @class vtkDGMFMeshFileReader
 * @brief Reads a solver's mesh file with its boundary names: gmsh `.msh` (physical groups; versions
 * 2.2 and 4, ASCII and binary, through gmsh's library) and SU2 `.su2` (MARKER_TAGs).
 *
 * The output is a multiblock shaped as ParaView's OpenFOAM reader's, so that boundaries are picked
 * by name the same way (vtkDGMFDeformFilter::AddMovingBoundary, `dgmf-deform --moving`):
 * - block 0, `internalMesh`: every node of the file, in the file's order, with the cells of the
 *   mesh's dimension; the point array `FileNodeId` holds the file's id of each node (gmsh tags,
 *   SU2 indices);
 * - block 1, `boundary`: one unstructured grid per named boundary (gmsh physical groups of the
 *   dimension below the mesh's, SU2 markers), named after it, with the nodes its faces use;
 * - field data `NonBoundaryGroups` and `NonBoundaryGroupDimensions`, when the file has them: the
 *   named groups of other dimensions (a gmsh physical curve of a 3D mesh, a volume group), which
 *   are not boundaries, so that a program told such a name can say what it is.
 *
 * A file that cannot be read is an error naming the file and the line or section, and an empty
 * output. vtkDGMFMeshFileWriter writes the deformed points back into a copy of the file.
 */
#ifndef vtkDGMFMeshFileReader_h
#define vtkDGMFMeshFileReader_h

#include "DGMFIOModule.h" // for export macro
#include "vtkMultiBlockDataSetAlgorithm.h"

class DGMFIO_EXPORT vtkDGMFMeshFileReader : public vtkMultiBlockDataSetAlgorithm
{
public:
  static vtkDGMFMeshFileReader* New();
  vtkTypeMacro(vtkDGMFMeshFileReader, vtkMultiBlockDataSetAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The file to read: `.msh` (gmsh) or `.su2` (SU2). Default: none.
  vtkSetFilePathMacro(FileName);
  vtkGetFilePathMacro(FileName);
  ///@}

  /// True for the file names this reader reads (by extension): .msh and .su2.
  static bool CanReadFileName(const char* fileName);

  /// ParaView's reader factory: 1 when the file has a readable extension.
  int CanReadFile(const char* fileName) { return CanReadFileName(fileName) ? 1 : 0; }

protected:
  vtkDGMFMeshFileReader();
  ~vtkDGMFMeshFileReader() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkDGMFMeshFileReader(const vtkDGMFMeshFileReader&) = delete;
  void operator=(const vtkDGMFMeshFileReader&) = delete;

  char* FileName = nullptr;
};

#endif
