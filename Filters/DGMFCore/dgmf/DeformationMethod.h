/**
 * @file DeformationMethod.h
 * @brief The one interface of every deformation method (DGMF, DGM, DGRBF, RBF, IDW): what it needs,
 * and the deformation itself.
 *
 * A caller (the VTK filter, a test, a command-line tool) does the same for every method:
 *
 *     auto method = dgmf::CreateMethod(dgmf::Method::DGMF, parameters); // checks the parameters
 *     const dgmf::MethodNeeds needs = method->GetNeeds(problem);
 *     // provide what it needs: a DelaunayMapping, cells, boundary weights, r and f buffers
 *     dgmf::DeformationReport report = method->Deform(problem, mapping, outputs, parallelFor);
 *
 * The method checks the problem (ValidateProblem) before it computes anything.
 */
#ifndef dgmf_DeformationMethod_h
#define dgmf_DeformationMethod_h

#include "dgmf/DGMFDeformation.h"
#include "dgmf/DampingFunction.h"
#include "dgmf/DeformationProblem.h"
#include "dgmf/IDWDeformation.h"
#include "dgmf/Methods.h"
#include "dgmf/ParallelFor.h"
#include "dgmf/RBFDeformation.h"

#include <memory>
#include <string>
#include <vector>

namespace dgmf
{
class DelaunayMapping;

/// The settings of every method (each reads its own); defaults are the filter's.
struct MethodParameters
{
  // DGMF
  DampingFunction Damping = DampingFunction::U1; ///< u(r)
  double StaticR0 = 1.0;                         ///< r0s >= 1
  DeformationMode Mode = DeformationMode::DGMF2; ///< where the shape deformation comes from
  int SubSteps = 1;             ///< large motions: steps (0 automatic, 1 the paper's single step)
  double RepairThreshold = 0.0; ///< the quality guard's SizeSkew threshold (0: off)
  int RepairLayers = 2;         ///< layers of nodes around bad cells that may move
  int RepairPasses = 20;        ///< most repair passes per step
  // DGRBF and RBF
  double SupportRadius = 0.0; ///< Wendland C2 support radius, mesh units (0: automatic)
  // RBF
  bool RBFGreedy = false;
  double RBFGreedyTolerance = 1e-3;
  std::size_t RBFGreedyMaximumPoints = 2000;
  // IDW
  double IDWAlpha = 5.0;
  double IDWReferenceLength = 0.0; ///< 0: automatic

  /// True when DGMF splits the motion into sub-steps or runs the quality guard.
  bool UsesSubSteps() const { return this->SubSteps != 1 || this->RepairThreshold > 0.0; }
};

/// What a method needs from its caller for a given problem.
struct MethodNeeds
{
  bool Graph = false;           ///< a DelaunayMapping of the problem's nodes and kinds
  bool Cells = false;           ///< DeformationProblem::Cells (sub-steps, quality guard)
  bool BoundaryWeights = false; ///< DeformationProblem::BoundaryWeights (IDW's A_i)
  bool R = false;               ///< the method writes r (DeformationOutputs::R)
  bool F = false;               ///< the method writes the damping factor f
  /// Every node's displacement is read (DGMF1: a known field), not only the moving nodes'.
  bool DisplacementEverywhere = false;
};

/// What a stored per-node field was computed with: r depends on r0s, f on r0s and u.
struct FieldKey
{
  double StaticR0 = -1.0; ///< r0s (-1: matches nothing)
  int Damping = 0;        ///< the damping function of f (0 for r)

  bool operator==(const FieldKey& other) const
  {
    return this->StaticR0 == other.StaticR0 && this->Damping == other.Damping;
  }
};

/**
 * The caller's storage for the per-node fields r and f (names::R, names::F), which DGMF keeps
 * between deformations of the same mesh: a new motion reuses them. The caller forgets every key
 * when the mapping is rebuilt (new points or node kinds).
 */
class FieldStore
{
public:
  virtual ~FieldStore() = default;
  /// The stored values of `field` if they were stored with `key`, else null.
  virtual const double* Find(const char* field, const FieldKey& key) = 0;
  /// Memory for one value per node of `field`, to be stored with `key` (a buffer nobody else
  /// reads: the caller gives a new one when an earlier result still holds the old one).
  virtual double* Store(const char* field, const FieldKey& key) = 0;
};

/// A FieldStore in std::vectors (tests, programs without VTK).
class VectorFieldStore : public FieldStore
{
public:
  explicit VectorFieldStore(std::size_t numberOfNodes)
    : Size(numberOfNodes)
  {
  }
  const double* Find(const char* field, const FieldKey& key) override;
  double* Store(const char* field, const FieldKey& key) override;
  /// The values of `field` (empty if never stored).
  const std::vector<double>& Get(const char* field) const;

private:
  struct Field
  {
    FieldKey Key;
    std::vector<double> Values;
  };
  std::size_t Size;
  Field R, F;
  Field& Select(const char* field);
};

/// Where a method writes its results, in the caller's memory.
struct DeformationOutputs
{
  double* Points = nullptr;     ///< 3 per node: the deformed positions (required; not the input's)
  FieldStore* Fields = nullptr; ///< r and f, when MethodNeeds::R or MethodNeeds::F
};

/// A value a method reports (the VTK filter's field data): a name of ResultNames.h.
struct ReportedValue
{
  std::string Name;
  bool IsCount = false;       ///< an integer count (else a real value)
  int Components = 1;         ///< values per tuple (3 for vectors)
  std::vector<double> Values; ///< tuples, one per body for per-body values
};

/// What a deformation did.
struct DeformationReport
{
  std::vector<ReportedValue> Values;
  std::vector<std::string> Warnings; ///< for the user (the filter's vtkWarningMacro)
  double GraphSeconds = 0.0;         ///< graphs built during the deformation (sub-steps)
  double LocationSeconds = 0.0;      ///< and their node location

  void AddCount(const char* name, double value)
  {
    this->Values.push_back({ name, true, 1, { value } });
  }
  void AddValue(const char* name, double value)
  {
    this->Values.push_back({ name, false, 1, { value } });
  }
};

/**
 * @class DeformationMethod
 * @brief A deformation method: what it needs, and the deformation of every node.
 */
class DeformationMethod
{
public:
  virtual ~DeformationMethod() = default;

  /// The method's entry in the method table.
  virtual const MethodInfo& GetInfo() const = 0;

  /// What the method needs to deform `problem`.
  virtual MethodNeeds GetNeeds(const DeformationProblem& problem) const = 0;

  /**
   * Checks `problem` (ValidateProblem), moves every node (DeformNodes): `outputs.Points` receives
   * the new positions; then keeps the slip nodes in their planes (DeformationProblem::Slip).
   * `mapping` is the DelaunayMapping of the problem's points and kinds when GetNeeds().Graph
   * (else ignored). Throws std::invalid_argument for a bad problem and std::runtime_error when
   * the method fails (e.g. an RBF system that cannot be solved).
   */
  DeformationReport Deform(const DeformationProblem& problem, const DelaunayMapping* mapping,
    const DeformationOutputs& outputs, const ParallelFor& parallelFor) const;

protected:
  /// The method's own deformation of every node, of a checked problem.
  virtual DeformationReport DeformNodes(const DeformationProblem& problem,
    const DelaunayMapping* mapping, const DeformationOutputs& outputs,
    const ParallelFor& parallelFor) const = 0;
};

/**
 * The method `method` with `parameters`. Throws std::invalid_argument for parameters out of range
 * (r0s < 1, an unknown damping function or mode, negative support radius, sub-steps, layers or
 * passes, thresholds outside [0, 1]).
 */
std::unique_ptr<DeformationMethod> CreateMethod(Method method, const MethodParameters& parameters);

} // namespace dgmf

#endif
