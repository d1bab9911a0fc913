/**
 * @class vtkDGMFOpenFOAMWriter
 * @brief Writes a deformed mesh back into an OpenFOAM case: the new points in
 * `constant/polyMesh/points` or in a time directory's `polyMesh/points`.
 *
 * The input is the deformed mesh as vtkDGMFDeformFilter gives it for a case read with VTK's or
 * ParaView's OpenFOAM reader: the reader's multiblock (the block named `internalMesh` is used) or
 * the internal mesh alone. Its first points are OpenFOAM's points, in OpenFOAM's order (the reader
 * appends one point per polyhedron when it decomposes polyhedra: those are not written).
 *
 * Only the points change; faces, cells, patches and fields are OpenFOAM's own. The written points
 * are the case's own double-precision points plus the deformation (deformed minus undeformed
 * input points), so points that do not move are written exactly as they were, and the reader's
 * rounding of the points to single precision does not reach the case. The file keeps the case's
 * format (ascii or binary, compressed or not) and is replaced atomically.
 *
 * Where the undeformed mesh and the case come from:
 * - the Reference input (port 1, optional): the mesh as read, before the deformation;
 * - else the first vtkOpenFOAMReader upstream of the input (its output, and its file's case).
 *
 * The input case is never modified unless FileName names it: FileName is the case to write, a new
 * directory (the source case is copied into it first: system, constant, the first time directory,
 * the other files) or a case made earlier from the same mesh.
 *
 * Runs on one process: under MPI, gather the mesh first (or use dgmf-deform).
 */
#ifndef vtkDGMFOpenFOAMWriter_h
#define vtkDGMFOpenFOAMWriter_h

#include "DGMFIOModule.h" // for export macro
#include "vtkWriter.h"

#include <filesystem>
#include <string>
#include <vector>

class DGMFIO_EXPORT vtkDGMFOpenFOAMWriter : public vtkWriter
{
public:
  static vtkDGMFOpenFOAMWriter* New();
  vtkTypeMacro(vtkDGMFOpenFOAMWriter, vtkWriter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The case to write: its directory, or a `.foam` (or `.OpenFOAM`) file in it, which is created
   * (empty) so that ParaView can open the written case. Default: none (an error).
   */
  vtkSetFilePathMacro(FileName);
  vtkGetFilePathMacro(FileName);
  ///@}

  ///@{
  /**
   * The case the mesh was read from (its directory, or its `.foam` file). Default: empty, which
   * means the case of the OpenFOAM reader upstream of the input.
   */
  vtkSetFilePathMacro(SourceCase);
  vtkGetFilePathMacro(SourceCase);
  ///@}

  ///@{
  /**
   * Where the points go: "constant" (`constant/polyMesh/points`, the mesh every solver starts
   * from), or a time such as "1" (`1/polyMesh/points`: OpenFOAM takes the faces from constant).
   * Default: "constant".
   */
  vtkSetStringMacro(TimeDirectory);
  vtkGetStringMacro(TimeDirectory);
  ///@}

  ///@{
  /**
   * The time directories a series writes with this writer, one Write() per frame (empty: one
   * time alone, the default). Write() warns about the other meshes of the case a solver would read
   * instead of the points written (a later time's polyMesh, processor directories); the series'
   * own times are not among them (the series replaces them), and the processor directories are
   * said at its last time only.
   */
  void SetSeriesTimes(const std::vector<std::string>& times) { this->SeriesTimes = times; }
  const std::vector<std::string>& GetSeriesTimes() const { return this->SeriesTimes; }
  ///@}

  /// The undeformed mesh (port 1, optional): the mesh as read, before the deformation.
  void SetReferenceConnection(vtkAlgorithmOutput* output);
  void SetReferenceData(vtkDataObject* reference);

  /// The points file written by the last successful Write(), or "".
  const std::string& GetLastWrittenFile() const { return this->LastWrittenFile; }

protected:
  vtkDGMFOpenFOAMWriter();
  ~vtkDGMFOpenFOAMWriter() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  void WriteData() override;
  /// Warns about meshes a solver would read instead of the one written (an earlier time's
  /// polyMesh, processor directories).
  void WarnAboutOtherMeshes(const std::filesystem::path& caseDirectory);
  std::vector<std::string> SeriesTimes;

  char* FileName = nullptr;
  char* SourceCase = nullptr;
  char* TimeDirectory = nullptr;
  std::string LastWrittenFile;

private:
  vtkDGMFOpenFOAMWriter(const vtkDGMFOpenFOAMWriter&) = delete;
  void operator=(const vtkDGMFOpenFOAMWriter&) = delete;
};

#endif
