/**
 * @file SizeSkewQuality.h
 * @brief Knupp's size-skew quality of a deformed cell relative to the same cell before deformation.
 */
#ifndef dgmf_SizeSkewQuality_h
#define dgmf_SizeSkewQuality_h

#include <cstddef>
#include <cstdint>

namespace dgmf
{

/// Cell shapes the size-skew metric covers. Corner order is VTK's for the same cell type.
enum class CellShape : std::uint8_t
{
  Triangle,
  Quad,
  Tetra,
  Hexahedron,
  Wedge,
  Pyramid
};

/// Number of corners of a shape (3, 4, 4, 8, 6, 5).
int GetNumberOfCorners(CellShape shape);

/// Quality of one cell.
struct CellQuality
{
  double SizeSkew = 0.0; ///< in [0, 1]; 1 = same shape quality as ideal and unchanged size
  bool Inverted = false; ///< a corner's Jacobian is <= 0 in the input cell's orientation
  /// The input cell has no corner metric: degenerate, or a corner's Jacobian <= 0 in its own
  /// orientation (non-convex or inverted before the motion). SizeSkew is then 0 and Inverted
  /// false: judge it through its faces (DecomposedSizeSkew.h, ComputeCellSizeSkew).
  bool InputInvalid = false;
};

/**
 * Size-skew metric (Knupp 2003) of a cell: f_size * f_skew (quads, hexahedra), f_size * f_shape
 * (triangles, tetrahedra), and the corner-based extension documented in
 * Documentation/quality.md for wedges and pyramids. The reference size is the same cell in the
 * original mesh. An inverted cell scores 0.
 *
 * Orientation is taken from the original cell (either handedness is accepted); a corner whose
 * Jacobian is <= 0 in that orientation makes the deformed cell inverted (0, Inverted = true). A
 * degenerate original cell (zero size relative to its edges, or non-finite coordinates), or one
 * with a corner whose Jacobian is <= 0 in its own orientation (non-convex), has no corner metric:
 * it scores 0, is not flagged inverted, and is flagged InputInvalid. 2D cells may lie in any plane
 * of 3D space. No allocation; safe to call concurrently.
 * @param original 3 coordinates per corner, before deformation (GetNumberOfCorners(shape) corners)
 * @param deformed 3 coordinates per corner, after deformation
 * @return SizeSkew in [0, 1]; NaN only for a value outside CellShape
 */
CellQuality ComputeSizeSkew(CellShape shape, const double* original, const double* deformed);

/**
 * The size-shape metric of a tetrahedron from three numbers: its deformed corner Jacobian
 * `alpha` (six times its volume, signed in the original cell's orientation), the sum of its six
 * squared edge lengths, and the original cell's corner Jacobian `originalAlpha` (> 0, the same
 * orientation). Equal to ComputeSizeSkew for a non-degenerate tetrahedron up to round-off (a
 * tetrahedron's four corners have the same Jacobian and the same Frobenius term, half the sum of
 * the squared edges); for callers that keep these numbers as affine and quadratic functions of
 * one moving corner (the quality guard). Inverted when `alpha` <= 0 or NaN.
 */
CellQuality TetraSizeSkew(double alpha, double edgeSquares, double originalAlpha);

/**
 * The original half of a hexahedron's size-skew metric, which a new motion of the same mesh does
 * not change (callers keep it between motions): the signed sum of the original corner Jacobians
 * (its sign is the cell's orientation), or NaN when the original cell has no corner metric
 * (degenerate or non-convex: ComputeSizeSkew's InputInvalid).
 * @param original 3 coordinates per corner, in VTK's order
 */
double ComputeHexReferenceSize(const double* original);

/**
 * ComputeSizeSkew of a hexahedron from its reference size (ComputeHexReferenceSize of its
 * original corners) and its deformed corners: the same operations, so the same bits.
 */
CellQuality ComputeHexSizeSkew(double referenceSize, const double* deformed);

/**
 * ComputeHexReferenceSize of `count` hexahedra, four at a time in four-lane vectors (AVX2 where
 * the processor has it): the same bits as one at a time.
 * @param original `count` pointers, each to the 8 x 3 original coordinates of a cell
 * @param referenceSizes `count` values written
 */
void ComputeHexReferenceSizes(
  std::size_t count, const double* const* original, double* referenceSizes);

/**
 * ComputeHexSizeSkew of `count` hexahedra, four at a time in four-lane vectors (AVX2 where the
 * processor has it; the most common cell of large structured meshes): the same bits as one at a
 * time, at about a third of the cost.
 * @param referenceSizes `count` reference sizes (ComputeHexReferenceSize)
 * @param deformed `count` pointers, each to the 8 x 3 deformed coordinates of a cell
 * @param quality `count` values written
 */
void ComputeHexSizeSkew(std::size_t count, const double* referenceSizes,
  const double* const* deformed, CellQuality* quality);

/**
 * Hexahedra four at a time in the layout of the four-lane vectors ("groups"): group g holds cells
 * 4g .. 4g + 3, and coordinate `c` of corner `k` of the group's cell `lane` is at
 * g * kHexGroupDoubles + HexGroupIndex(k, c, lane). Callers that gather corners (the filter) write
 * them there directly, so that the metric loads each coordinate of four cells as one vector
 * instead of inserting four values (31 instead of 39 - 40 ns per hexahedron in cache: speed.md).
 */
constexpr std::size_t kHexGroupDoubles = 96;

/// Where coordinate `coordinate` of corner `corner` of lane `lane` is in its group.
constexpr std::size_t HexGroupIndex(int corner, int coordinate, std::size_t lane)
{
  return static_cast<std::size_t>(3 * corner + coordinate) * 4 + lane;
}

/// Stores the 3 coordinates `point` as corner `corner` of cell `cell` of `groups`.
inline void StoreHexGroupCorner(double* groups, std::size_t cell, int corner, const double* point)
{
  double* group = groups + cell / 4 * kHexGroupDoubles;
  for (int c = 0; c < 3; ++c)
  {
    group[HexGroupIndex(corner, c, cell % 4)] = point[c];
  }
}

/// Cell `cell` of `groups` as one cell's 8 x 3 coordinates.
inline void LoadHexGroupCell(const double* groups, std::size_t cell, double* corners)
{
  const double* group = groups + cell / 4 * kHexGroupDoubles;
  for (int k = 0; k < 8; ++k)
  {
    for (int c = 0; c < 3; ++c)
    {
      corners[3 * k + c] = group[HexGroupIndex(k, c, cell % 4)];
    }
  }
}

/**
 * ComputeHexReferenceSizes of `count` hexahedra given in groups: the same bits.
 * @param originalGroups (count + 3) / 4 groups; the last group's lanes past `count` are not read
 * @param referenceSizes `count` values written
 */
void ComputeHexReferenceSizesInGroups(
  std::size_t count, const double* originalGroups, double* referenceSizes);

/**
 * ComputeHexSizeSkew of `count` hexahedra given in groups: the same bits.
 * @param referenceSizes `count` reference sizes (ComputeHexReferenceSize)
 * @param deformedGroups (count + 3) / 4 groups; the last group's lanes past `count` are not read
 * @param quality `count` values written
 */
void ComputeHexSizeSkewInGroups(std::size_t count, const double* referenceSizes,
  const double* deformedGroups, CellQuality* quality);

/// Mean, minimum and inverted count over a set of cells.
struct QualitySummary
{
  double Mean = 0.0;            ///< mean SizeSkew over the evaluated cells (0 if none)
  double Minimum = 0.0;         ///< minimum SizeSkew over the evaluated cells (0 if none)
  std::size_t Inverted = 0;     ///< number of cells the deformation inverted
  std::size_t InputInvalid = 0; ///< cells already non-convex, inverted or degenerate in the input
  std::size_t Evaluated = 0;    ///< cells with a supported shape
  std::size_t NotComputed = 0;  ///< cells of other types (their value is NaN)
  double Sum = 0.0;             ///< sum of SizeSkew over the evaluated cells (to combine summaries)
};

/**
 * Summary of per-cell values; NaN values are counted as not computed. `inverted` (may be null)
 * flags inverted cells, `inputInvalid` (may be null) cells invalid in the input. Cells with a
 * non-zero `skip` flag (may be null; e.g. ghost cells, counted by another process) are left out.
 * The sum is taken in a fixed order, so the result is reproducible.
 */
QualitySummary SummarizeQuality(const double* sizeSkew, const std::uint8_t* inverted,
  std::size_t count, const std::uint8_t* skip = nullptr,
  const std::uint8_t* inputInvalid = nullptr);

/// The summary of two disjoint sets of cells (e.g. two blocks of a composite mesh).
QualitySummary MergeQualitySummaries(const QualitySummary& a, const QualitySummary& b);

} // namespace dgmf

#endif
