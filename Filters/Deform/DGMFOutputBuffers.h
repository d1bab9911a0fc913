/**
 * @file DGMFOutputBuffers.h
 * @brief The memory of the filter's outputs, reused from one execution to the next when nobody
 * else holds it: the deformed points, and r and f as the core's FieldStore (private to the
 * DGMF::Filters module).
 *
 * A repeated deformation of a large mesh then writes into memory that is already mapped: the
 * first touch of new pages costs about as much as the mapping itself. Memory that an earlier
 * output, a downstream filter or user code still holds is never written: a new buffer is made.
 */
#ifndef DGMFOutputBuffers_h
#define DGMFOutputBuffers_h

#include "dgmf/DeformationMethod.h"

#include "vtkSmartPointer.h"

#include <cstddef>
#include <vector>

class vtkDoubleArray;
class vtkPoints;
class vtkUnsignedCharArray;
class vtkUnstructuredGrid;

namespace dgmf_vtk
{

/**
 * The output points for `n` nodes: the last output's points when only the cache and `output`
 * hold them, otherwise new ones (kept in `last` for the next execution).
 */
vtkSmartPointer<vtkPoints> ReuseOutputPoints(vtkSmartPointer<vtkPoints>& last,
  vtkUnstructuredGrid* input, vtkUnstructuredGrid* output, std::size_t n);

/**
 * The quality's cell arrays (SizeSkew, Inverted, InputInvalid), kept from one execution to the
 * next: Reuse() gives the kept array when only this object holds it (its memory already mapped),
 * else a new one, kept in its place.
 */
struct QualityArrays
{
  vtkSmartPointer<vtkDoubleArray> SizeSkew;
  vtkSmartPointer<vtkUnsignedCharArray> Inverted, InputInvalid;

  /// `kept` when only `kept` holds it, else a new array (then kept).
  template <typename T>
  static vtkSmartPointer<T> Reuse(vtkSmartPointer<T>& kept)
  {
    if (!kept || kept->GetReferenceCount() != 1)
    {
      kept = vtkSmartPointer<T>::New();
    }
    return kept;
  }
};

/**
 * r and f as vtkDoubleArrays shared with the output: dgmf::FieldStore for the DGMF method. Store()
 * gives the kept array when only this object holds it, else a new one.
 */
class FieldArrays : public dgmf::FieldStore
{
public:
  /// Sets the number of nodes; forgets every key (a new mapping: r and f must be recomputed).
  void Reset(std::size_t numberOfNodes);
  const double* Find(const char* field, const dgmf::FieldKey& key) override;
  double* Store(const char* field, const dgmf::FieldKey& key) override;
  /// The array of `field` (names::R or names::F), or null.
  vtkDoubleArray* GetArray(const char* field);
  /// Makes sure the arrays of the fields asked for exist and are writable (their values are not
  /// kept), and returns them: their memory is touched while the graph is built.
  std::vector<vtkDoubleArray*> Prepare(bool r, bool f);

private:
  struct Field
  {
    vtkSmartPointer<vtkDoubleArray> Array;
    dgmf::FieldKey Key;
  };
  Field R, F;
  std::size_t Size = 0;
  Field& Select(const char* field);
};

} // namespace dgmf_vtk

#endif
