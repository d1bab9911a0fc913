/**
 * @class   vtkSizeSkewQualityFilter
 * @brief   Knupp's size-skew quality of a deformed mesh relative to the same mesh before
 * deformation.
 *
 * Input 0 is the mesh to measure; input 1 (the reference, SetReferenceData or
 * SetReferenceConnection) is the same mesh before deformation: the same number of points and the
 * same cells, only the point coordinates may differ. Both are unstructured grids, or both
 * composite datasets of the same structure (multiblock, partitioned dataset collection: the
 * output of DGMF Deform on a CFD reader's blocks), measured block by block.
 *
 * The output is input 0 with every array passed through, plus the cell arrays `SizeSkew` (1 =
 * ideal shape and unchanged size, 0 = degenerate or inverted; NaN for cell types the metric does
 * not cover), `Inverted` and `InputInvalid`, and the field data `SizeSkewMean`,
 * `SizeSkewMinimum`, `InvertedCellCount`, `InputInvalidCellCount` and `SizeSkewEvaluatedCells`
 * (over all blocks), and with ComputeNonOrthogonality the cell array `NonOrthogonality` and the
 * field data `MaximumNonOrthogonality` and `InputMaximumNonOrthogonality`: the same names and
 * values vtkDGMFDeformFilter writes for its own output.
 *
 * This is the metric vtkDGMFDeformFilter computes, available for any pair of meshes, e.g. to
 * compare deformations made by other tools. The definition for every cell type is in
 * Documentation/quality.md.
 *
 * @warning Threaded with vtkSMPTools.
 * @sa vtkDGMFDeformFilter vtkMeshQuality
 */
#ifndef vtkSizeSkewQualityFilter_h
#define vtkSizeSkewQualityFilter_h

#include "DGMFFiltersModule.h" // for export macro
#include "vtkPassInputTypeAlgorithm.h"

#include <memory> // for std::unique_ptr

class vtkUnstructuredGrid;

class DGMFFILTERS_EXPORT vtkSizeSkewQualityFilter : public vtkPassInputTypeAlgorithm
{
public:
  static vtkSizeSkewQualityFilter* New();
  vtkTypeMacro(vtkSizeSkewQualityFilter, vtkPassInputTypeAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The reference (undeformed) mesh, input port 1.
  void SetReferenceData(vtkDataObject* reference) { this->SetInputData(1, reference); }
  void SetReferenceConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(1, output); }
  ///@}

  ///@{
  /// The output for unstructured-grid input (null for composite input: GetOutputDataObject(0)).
  vtkUnstructuredGrid* GetOutput();
  vtkUnstructuredGrid* GetOutput(int port);
  ///@}

  ///@{
  /**
   * Number of threads; 0 uses all hardware threads (see vtkDGMFDeformFilter). Default: 0.
   */
  vtkSetClampMacro(NumberOfThreads, int, 0, VTK_INT_MAX);
  vtkGetMacro(NumberOfThreads, int);
  ///@}

  ///@{
  /**
   * Also compute the face non-orthogonality as OpenFOAM's checkMesh defines it (see
   * vtkDGMFDeformFilter::SetComputeNonOrthogonality). Default: off.
   */
  vtkSetMacro(ComputeNonOrthogonality, bool);
  vtkGetMacro(ComputeNonOrthogonality, bool);
  vtkBooleanMacro(ComputeNonOrthogonality, bool);
  ///@}

protected:
  vtkSizeSkewQualityFilter();
  ~vtkSizeSkewQualityFilter() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int NumberOfThreads = 0;
  bool ComputeNonOrthogonality = false;

  struct Internals;
  std::unique_ptr<Internals> Internal;

private:
  vtkSizeSkewQualityFilter(const vtkSizeSkewQualityFilter&) = delete;
  void operator=(const vtkSizeSkewQualityFilter&) = delete;
};

#endif
