/**
 * @class vtkDGMFMeshFileWriter
 * @brief Writes a deformed mesh back into its solver's mesh file (gmsh `.msh`, SU2 `.su2`, Exodus
 * II
 * `.exo`/`.e`/`.ex2`, CGNS `.cgns`): a copy of the file it was read from in which only the node
 * coordinates change.
 *
 * The input is vtkDGMFMeshFileReader's multiblock after the deformation (or its `internalMesh`
 * block alone): the points of `internalMesh` are the file's nodes in the file's order. Or, for an
 * Exodus file, the blocks of ParaView's own Exodus readers (vtkExodusIIReader, or the IOSS
 * reader with SourceFileName set): their points are placed by their node ids (point arrays
 * `GlobalNodeId` or `ids`, the file's node number map), and nodes no block holds keep their
 * coordinates. The source file is SourceFileName, or the file of the reader upstream. The target
 * has the source's format: a gmsh file keeps its version (2.2 or 4), mode (ASCII or binary), node
 * tags, elements and physical groups; an SU2 file keeps every line but the coordinates; an Exodus
 * or CGNS file keeps every block, set, boundary condition and variable, and the precision of its
 * coordinates. The file is written beside its final name and renamed over it (never half a file);
 * the target may be the source. Errors (no source, another mesh, another format, a file that
 * cannot be written) leave the target untouched.
 */
#ifndef vtkDGMFMeshFileWriter_h
#define vtkDGMFMeshFileWriter_h

#include "DGMFIOModule.h" // for export macro
#include "vtkWriter.h"

#include <string> // for std::string

class DGMFIO_EXPORT vtkDGMFMeshFileWriter : public vtkWriter
{
public:
  static vtkDGMFMeshFileWriter* New();
  vtkTypeMacro(vtkDGMFMeshFileWriter, vtkWriter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The file to write, in the source's format (`.msh`, `.su2`, `.exo`/`.e`/`.ex2`, `.cgns`).
  /// Default: none.
  vtkSetFilePathMacro(FileName);
  vtkGetFilePathMacro(FileName);
  ///@}

  ///@{
  /**
   * The file the mesh was read from. Default: empty, which means the file of the
   * vtkDGMFMeshFileReader (or vtkExodusIIReader) upstream of the input.
   */
  vtkSetFilePathMacro(SourceFileName);
  vtkGetFilePathMacro(SourceFileName);
  ///@}

protected:
  vtkDGMFMeshFileWriter();
  ~vtkDGMFMeshFileWriter() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  void WriteData() override;

  /// Writes the input's points placed by node id into a copy of `source` (the input of a reader
  /// other than vtkDGMFMeshFileReader).
  void WriteByNodeId(const std::string& source, const std::string& target);

private:
  vtkDGMFMeshFileWriter(const vtkDGMFMeshFileWriter&) = delete;
  void operator=(const vtkDGMFMeshFileWriter&) = delete;

  char* FileName = nullptr;
  char* SourceFileName = nullptr;
};

#endif
