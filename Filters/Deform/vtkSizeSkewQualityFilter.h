/**
 * @class   vtkSizeSkewQualityFilter
 * @brief   Knupp's size-skew quality of a deformed mesh relative to the same mesh before
 * deformation.
 *
 * Input 0 is the mesh to measure; input 1 (the reference, SetReferenceData or
 * SetReferenceConnection) is the same mesh before deformation: the same number of points and the
 * same cells, only the point coordinates may differ. The output is input 0 with every array passed
 * through, plus the cell arrays `SizeSkew` (1 = ideal shape and unchanged size, 0 = degenerate or
 * inverted; NaN for cell types the metric does not cover) and `Inverted`, and the field data
 * `SizeSkewMean`, `SizeSkewMinimum` and `InvertedCellCount`.
 *
 * This is the metric vtkDGMFDeformFilter computes for its own output, available for any pair of
 * meshes, e.g. to compare deformations made by other tools. The definition for every cell type is
 * in Documentation/quality.md.
 *
 * @warning Threaded with vtkSMPTools.
 * @sa vtkDGMFDeformFilter vtkMeshQuality
 */
#ifndef vtkSizeSkewQualityFilter_h
#define vtkSizeSkewQualityFilter_h

#include "DGMFFiltersModule.h" // for export macro
#include "vtkUnstructuredGridAlgorithm.h"

class DGMFFILTERS_EXPORT vtkSizeSkewQualityFilter : public vtkUnstructuredGridAlgorithm
{
public:
  static vtkSizeSkewQualityFilter* New();
  vtkTypeMacro(vtkSizeSkewQualityFilter, vtkUnstructuredGridAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The reference (undeformed) mesh, input port 1.
  void SetReferenceData(vtkDataObject* reference) { this->SetInputData(1, reference); }
  void SetReferenceConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(1, output); }
  ///@}

  ///@{
  /**
   * Number of threads; 0 uses all hardware threads (see vtkDGMFDeformFilter). Default: 0.
   */
  vtkSetClampMacro(NumberOfThreads, int, 0, VTK_INT_MAX);
  vtkGetMacro(NumberOfThreads, int);
  ///@}

protected:
  vtkSizeSkewQualityFilter();
  ~vtkSizeSkewQualityFilter() override = default;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int NumberOfThreads = 0;

private:
  vtkSizeSkewQualityFilter(const vtkSizeSkewQualityFilter&) = delete;
  void operator=(const vtkSizeSkewQualityFilter&) = delete;
};

#endif
