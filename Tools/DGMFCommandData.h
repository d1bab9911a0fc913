/**
 * @file DGMFCommandData.h
 * @brief What dgmf-deform reads and writes: a mesh file (.vtu, .vtk) or an OpenFOAM case, read
 * through VTK's readers; the deformed mesh written as .vtu or back into a case.
 */
#ifndef DGMFCommandData_h
#define DGMFCommandData_h

#include "vtkSmartPointer.h"

#include <string>

class vtkAlgorithm;
class vtkDataObject;
class vtkUnstructuredGrid;

namespace dgmf_cli
{
/// True when `path` names an OpenFOAM case: its directory, its system/controlDict or a .foam file.
bool IsOpenFOAMCase(const std::string& path);

/// Reads a .vtu (XML) or .vtk (legacy) unstructured grid; null or empty when it cannot.
vtkSmartPointer<vtkUnstructuredGrid> ReadMeshFile(const std::string& path);

/// True for the mesh files WriteMeshFile writes: .vtu and .vtk.
bool IsMeshFileName(const std::string& path);

/**
 * Writes `mesh` to `path`: an XML unstructured grid (inline binary) for .vtu, a legacy VTK file
 * (binary) for .vtk. The file is written beside `path` under a temporary name and renamed over
 * it, so `path` never holds half a file. False, with the reason printed, when it cannot.
 */
bool WriteMeshFile(vtkUnstructuredGrid* mesh, const std::string& path);

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
 * returns the file written, or "" on failure (the error is printed).
 */
std::string WriteOpenFOAMPoints(
  vtkAlgorithm* deformer, const std::string& outputCase, const std::string& time);
} // namespace dgmf_cli

#endif
