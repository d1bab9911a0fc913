/**
 * @file DGMFCommandData.h
 * @brief What dgmf-deform reads and writes: a VTK mesh file (.vtu, .vtk), a solver's mesh file
 * with boundary names (gmsh .msh, SU2 .su2) or an OpenFOAM case; the deformed mesh written as
 * .vtu or .vtk, back into the solver's file format, or back into a case.
 */
#ifndef DGMFCommandData_h
#define DGMFCommandData_h

#include "vtkSmartPointer.h"

#include <string>
#include <vector>

class vtkAlgorithm;
class vtkDataObject;
class vtkUnstructuredGrid;

namespace dgmf_cli
{
/// True when `path` names an OpenFOAM case: its directory, its system/controlDict or a .foam file.
bool IsOpenFOAMCase(const std::string& path);

/// True for the solver mesh files with boundary names: gmsh .msh and SU2 .su2.
bool IsSolverMeshFile(const std::string& path);

/**
 * A reader (vtkDGMFMeshFileReader) of the .msh or .su2 file `path`, updated; null when the file
 * cannot be read (the error is printed).
 */
vtkSmartPointer<vtkAlgorithm> ReadSolverMeshFile(const std::string& path);

/// The names of the boundary blocks of a reader's multiblock (the blocks under `boundary`, or
/// the OpenFOAM reader's patches).
std::vector<std::string> BoundaryNamesOf(vtkDataObject* blocks);

/// The family (dgmf::names::BoundaryFamily: a CGNS family) of each block of BoundaryNamesOf, in
/// its order, "" where a block has none.
std::vector<std::string> BoundaryFamiliesOf(vtkDataObject* blocks);

/**
 * `names` with each OpenFOAM patch group of the case at `path` (a name no patch has, in some
 * patches' `inGroups`: "wall", "motorBikeGroup") made the alternatives of its patches
 * ("wing|flap"): one boundary, one body, as the filter reads such an entry. Other names as given.
 */
std::vector<std::string> ExpandPatchGroups(
  const std::string& path, const std::vector<std::string>& names);

/// True for a .vtu file name (in any case).
bool IsVTUFileName(const std::string& path);

/**
 * Writes the deformed output of `deformer` into a copy of the solver's mesh file `source` at
 * `target` (same format: vtkDGMFMeshFileWriter); false when it cannot (the error is printed).
 */
bool WriteSolverMeshFile(
  vtkAlgorithm* deformer, const std::string& source, const std::string& target);

/**
 * The mesh with every node of `data`: `data` itself for an unstructured grid, the block named
 * internalMesh of a reader's multiblock; null if none.
 */
vtkUnstructuredGrid* VolumeOf(vtkDataObject* data);

/**
 * The grid to write as a .vtu or .vtk for `data`: VolumeOf(data), and for a composite `data` (a
 * reader's blocks) a shallow copy of it with the composite's numeric field data added (the
 * quality summary and the method's results, which the filter puts on the composite output, and
 * the reader's own, such as the OpenFOAM reader's CasePath); null if there is no volume.
 */
vtkSmartPointer<vtkUnstructuredGrid> VolumeToWrite(vtkDataObject* data);

/// Reads a .vtu (XML) or .vtk (legacy) unstructured grid; null or empty when it cannot.
vtkSmartPointer<vtkUnstructuredGrid> ReadMeshFile(const std::string& path);

/// How a .vtu is encoded (dgmf-deform --vtu-mode, --compression).
struct VTUEncoding
{
  bool Appended = true; ///< appended raw data; false: inline binary (base64)
  /// lz4, zlib, lzma or none; empty: none when appended (the fastest write: the whole command on
  /// an 8.26M-node mesh ~0.3 s shorter than with LZ4, files 1.7 times larger; speed.md), LZ4
  /// when inline (base64 of raw data: larger and slower still)
  std::string Compression;
};

/// True for the compressions a .vtu may have.
bool IsCompression(const std::string& name);

/// True for the mesh files WriteMeshFile writes: .vtu and .vtk.
bool IsMeshFileName(const std::string& path);

/**
 * Writes `mesh` to `path`: an XML unstructured grid (`encoding`; DGMFVTUWriter) for .vtu, a legacy
 * VTK file (binary) for .vtk. The filter's `Method` string field is left out (meshio 7 and older
 * VTK readers cannot read string arrays); the input's arrays, string arrays included, are
 * written. The file is written beside `path` under a temporary name and renamed over it, so
 * `path` never holds half a file. False, with the reason printed, when it cannot.
 */
bool WriteMeshFile(
  vtkUnstructuredGrid* mesh, const std::string& path, const VTUEncoding& encoding = VTUEncoding());

/**
 * A reader of the OpenFOAM case `path` (its directory or a .foam file): the internal mesh and
 * every patch, polyhedra kept as polyhedra unless `decomposePolyhedra`, no fields. Updated;
 * null when the case cannot be read (an error is printed).
 */
vtkSmartPointer<vtkAlgorithm> ReadOpenFOAMCase(const std::string& path, bool decomposePolyhedra);

/// The names of the patches of the OpenFOAM case `path` (its boundary file), separated by ", ".
std::string ListPatchNames(const std::string& path);

/**
 * Writes the points of the deformed output of `deformer` (whose input comes from the OpenFOAM
 * reader ReadOpenFOAMCase made) into the case `outputCase` at `time` (vtkDGMFOpenFOAMWriter);
 * returns the file written, or "" on failure (the error is printed). `seriesTimes`: the time
 * directories of the series this write is a frame of (vtkDGMFOpenFOAMWriter::SetSeriesTimes).
 */
std::string WriteOpenFOAMPoints(vtkAlgorithm* deformer, const std::string& outputCase,
  const std::string& time, const std::vector<std::string>& seriesTimes = {});
} // namespace dgmf_cli

#endif
