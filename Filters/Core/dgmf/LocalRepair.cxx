// The quality guard (Documentation/repair.md): cells a deformation step left inverted or below a
// SizeSkew threshold are repaired by moving nearby interior nodes, one node at a time, with
// Knupp's untangling objective (Engineering with Computers 17, 2001) where a cell is inverted and
// max-min SizeSkew smoothing (Freitag's smart Laplacian with an optimisation step) elsewhere.
#include "dgmf/LocalRepair.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>

namespace dgmf
{
namespace
{

/// Cells per block of the quality evaluation (fixed, so the result does not depend on threads).
constexpr std::size_t kCellsPerBlock = 2048;
/// Untangling target beta: this fraction of the original cell's mean corner Jacobian.
constexpr double kUntangleFraction = 0.1;
/// Smallest rise of a node's minimum SizeSkew that counts as an improvement.
constexpr double kMinimumGain = 1e-12;
/// Smallest relative decrease of a node's untangling objective that counts as an improvement.
constexpr double kMinimumRelativeDecrease = 1e-12;
/// 2D cells around a node are coplanar if the sines between their normals are below this.
constexpr double kCoplanarTolerance = 1e-8;
/// Weight exp(-sharpness (q - q_min)) of a cell in the smoothing ascent direction.
constexpr double kSoftMinimumSharpness = 40.0;
/// Finite-difference step of the SizeSkew gradient, relative to the node's mean edge length.
constexpr double kGradientStep = 1e-6;
/// Most untangling steps of one node in one pass.
constexpr int kUntangleStepsPerPass = 4;
/**
 * Nodes whose cells all score at least this times the threshold are not smoothed: they move only
 * once a neighbour's move has brought one of their cells below it (to make room).
 */
constexpr double kComfortFactor = 1.5;
/// Largest number of corners of a covered shape (the hexahedron).
constexpr int kMaximumCorners = 8;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// Step lengths, in units of the node's mean edge length.
constexpr double kUntangleSteps[] = { 2.0, 1.0, 0.5, 0.25, 0.125, 0.0625, 0.03125 };
constexpr double kLaplacianFractions[] = { 1.0, 0.5, 0.25, 0.125 };
constexpr double kAscentSteps[] = { 0.5, 0.25, 0.125, 0.0625, 0.03125, 0.015625 };
constexpr double kPatternSteps[] = { 0.125, 0.03125 };

struct Vec3
{
  double X, Y, Z;
};

inline Vec3 Load(const double* points, std::int64_t i)
{
  return { points[3 * i], points[3 * i + 1], points[3 * i + 2] };
}

inline void Store(const Vec3& v, double* points, std::int64_t i)
{
  points[3 * i] = v.X;
  points[3 * i + 1] = v.Y;
  points[3 * i + 2] = v.Z;
}

inline Vec3 operator+(const Vec3& a, const Vec3& b)
{
  return { a.X + b.X, a.Y + b.Y, a.Z + b.Z };
}

inline Vec3 operator-(const Vec3& a, const Vec3& b)
{
  return { a.X - b.X, a.Y - b.Y, a.Z - b.Z };
}

inline Vec3 operator*(double s, const Vec3& a)
{
  return { s * a.X, s * a.Y, s * a.Z };
}

inline double Dot(const Vec3& a, const Vec3& b)
{
  return a.X * b.X + a.Y * b.Y + a.Z * b.Z;
}

inline Vec3 Cross(const Vec3& a, const Vec3& b)
{
  return { a.Y * b.Z - a.Z * b.Y, a.Z * b.X - a.X * b.Z, a.X * b.Y - a.Y * b.X };
}

inline double Norm(const Vec3& a)
{
  return std::sqrt(Dot(a, a));
}

inline bool IsFinite(const Vec3& a)
{
  return std::isfinite(a.X) && std::isfinite(a.Y) && std::isfinite(a.Z);
}

/**
 * Edge vectors leaving one corner: Origin -> A, Origin -> B (and Origin -> C in 3D, C < 0 in 2D),
 * the same corners and order as SizeSkewQuality.cxx, so that alpha > 0 in a valid cell.
 */
struct Corner
{
  int Origin, A, B, C;
};

constexpr Corner kTriangleCorners[] = { { 0, 1, 2, -1 } };
constexpr Corner kQuadCorners[] = { { 0, 1, 3, -1 }, { 1, 2, 0, -1 }, { 2, 3, 1, -1 },
  { 3, 0, 2, -1 } };
constexpr Corner kTetraCorners[] = { { 0, 1, 2, 3 } };
constexpr Corner kHexCorners[] = { { 0, 1, 3, 4 }, { 1, 2, 0, 5 }, { 2, 3, 1, 6 }, { 3, 0, 2, 7 },
  { 4, 7, 5, 0 }, { 5, 4, 6, 1 }, { 6, 5, 7, 2 }, { 7, 6, 4, 3 } };
constexpr Corner kWedgeCorners[] = { { 0, 2, 1, 3 }, { 1, 0, 2, 4 }, { 2, 1, 0, 5 }, { 3, 4, 5, 0 },
  { 4, 5, 3, 1 }, { 5, 3, 4, 2 } };
constexpr Corner kPyramidCorners[] = { { 0, 1, 3, 4 }, { 1, 2, 0, 4 }, { 2, 3, 1, 4 },
  { 3, 0, 2, 4 } };

constexpr int kTriangleEdges[][2] = { { 0, 1 }, { 1, 2 }, { 2, 0 } };
constexpr int kQuadEdges[][2] = { { 0, 1 }, { 1, 2 }, { 2, 3 }, { 3, 0 } };
constexpr int kTetraEdges[][2] = { { 0, 1 }, { 1, 2 }, { 2, 0 }, { 0, 3 }, { 1, 3 }, { 2, 3 } };
constexpr int kHexEdges[][2] = { { 0, 1 }, { 1, 2 }, { 2, 3 }, { 3, 0 }, { 4, 5 }, { 5, 6 },
  { 6, 7 }, { 7, 4 }, { 0, 4 }, { 1, 5 }, { 2, 6 }, { 3, 7 } };
constexpr int kWedgeEdges[][2] = { { 0, 1 }, { 1, 2 }, { 2, 0 }, { 3, 4 }, { 4, 5 }, { 5, 3 },
  { 0, 3 }, { 1, 4 }, { 2, 5 } };
constexpr int kPyramidEdges[][2] = { { 0, 1 }, { 1, 2 }, { 2, 3 }, { 3, 0 }, { 0, 4 }, { 1, 4 },
  { 2, 4 }, { 3, 4 } };

/// Corner and edge tables of a shape.
struct ShapeTables
{
  const Corner* Corners;
  int NumberOfCorners;
  const int (*Edges)[2];
  int NumberOfEdges;
  int Dimension;
};

template <std::size_t C, std::size_t E>
constexpr ShapeTables MakeTables(
  const Corner (&corners)[C], const int (&edges)[E][2], int dimension)
{
  return { corners, static_cast<int>(C), edges, static_cast<int>(E), dimension };
}

ShapeTables GetTables(CellShape shape)
{
  switch (shape)
  {
    case CellShape::Triangle:
      return MakeTables(kTriangleCorners, kTriangleEdges, 2);
    case CellShape::Quad:
      return MakeTables(kQuadCorners, kQuadEdges, 2);
    case CellShape::Tetra:
      return MakeTables(kTetraCorners, kTetraEdges, 3);
    case CellShape::Hexahedron:
      return MakeTables(kHexCorners, kHexEdges, 3);
    case CellShape::Wedge:
      return MakeTables(kWedgeCorners, kWedgeEdges, 3);
    case CellShape::Pyramid:
      return MakeTables(kPyramidCorners, kPyramidEdges, 3);
  }
  return { nullptr, 0, nullptr, 0, 0 };
}

/// A cell incident to a free node, with what the node steps need about its original shape.
struct ActiveCell
{
  std::size_t Cell = 0;
  CellShape Shape = CellShape::Triangle;
  ShapeTables Tables{ nullptr, 0, nullptr, 0, 0 };
  int NumberOfNodes = 0;
  const std::int64_t* Nodes = nullptr;       ///< into the mesh connectivity
  double Original[3 * kMaximumCorners] = {}; ///< original corner coordinates
  Vec3 Normal0{ 0.0, 0.0, 0.0 };             ///< 2D: unit normal of the original cell
  double Orientation = 1.0;                  ///< 3D: sign of the original cell's size
  double Beta = 0.0;                         ///< untangling target of every corner Jacobian
  bool Degenerate = false;                   ///< degenerate original cell: always 0, ignored
  double Quality = 0.0;                      ///< current SizeSkew
  bool Inverted = false;                     ///< currently inverted
  int FreeNodeCount = 0;                     ///< free nodes among its corners
};

/// A node the repair may move.
struct FreeNode
{
  std::int64_t Id = 0;
  std::size_t CellBegin = 0; ///< its cells are Incident[CellBegin, CellEnd)
  std::size_t CellEnd = 0;
  int Dimension = 3; ///< 2: moves in Basis[0], Basis[1]; 3: in all directions
  Vec3 Basis[3] = { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
  Vec3 Normal{ 0.0, 0.0, 0.0 }; ///< 2D: unit normal of the plane of its cells
  bool Enabled = true;
};

/// Cell `cell`'s corners in `points`, written to out (3 per corner).
void GatherCorners(const CellMesh& mesh, std::size_t cell, const double* points, double* out)
{
  const std::int64_t begin = mesh.Offsets[cell];
  const std::int64_t count = mesh.Offsets[cell + 1] - begin;
  for (std::int64_t k = 0; k < count; ++k)
  {
    const std::int64_t node = mesh.Connectivity[static_cast<std::size_t>(begin + k)];
    out[3 * k] = points[3 * node];
    out[3 * k + 1] = points[3 * node + 1];
    out[3 * k + 2] = points[3 * node + 2];
  }
}

bool IsCovered(const CellMesh& mesh, std::size_t cell)
{
  return mesh.Covered.empty() || mesh.Covered[cell] != 0;
}

void Validate(const CellMesh& mesh, const double* originalPoints, const double* points,
  const NodeKind* kinds, const RepairParameters& parameters)
{
  if (!(parameters.Threshold >= 0.0 && parameters.Threshold <= 1.0))
  {
    throw std::invalid_argument("RepairCells: the threshold must be a number in [0, 1]");
  }
  if (parameters.Layers < 0 || parameters.MaximumPasses < 0)
  {
    throw std::invalid_argument("RepairCells: Layers and MaximumPasses must be >= 0");
  }
  const std::size_t cells = mesh.GetNumberOfCells();
  if (cells == 0)
  {
    return;
  }
  if (mesh.Shapes.size() != cells || (!mesh.Covered.empty() && mesh.Covered.size() != cells))
  {
    throw std::invalid_argument(
      "RepairCells: Shapes (and Covered, if given) need one entry per cell");
  }
  if (originalPoints == nullptr || points == nullptr || kinds == nullptr)
  {
    throw std::invalid_argument("RepairCells: points, original points and node kinds are required");
  }
  if (mesh.Offsets[0] < 0 ||
    static_cast<std::size_t>(mesh.Offsets[cells]) > mesh.Connectivity.size())
  {
    throw std::invalid_argument("RepairCells: the offsets do not fit the connectivity");
  }
  const auto numberOfPoints = static_cast<std::int64_t>(mesh.NumberOfPoints);
  for (std::size_t c = 0; c < cells; ++c)
  {
    const std::int64_t begin = mesh.Offsets[c];
    const std::int64_t end = mesh.Offsets[c + 1];
    if (end < begin)
    {
      throw std::invalid_argument("RepairCells: the offsets must not decrease");
    }
    if (IsCovered(mesh, c) && end - begin != GetNumberOfCorners(mesh.Shapes[c]))
    {
      throw std::invalid_argument("RepairCells: a cell's corner count does not match its shape");
    }
    for (std::int64_t k = begin; k < end; ++k)
    {
      const std::int64_t node = mesh.Connectivity[static_cast<std::size_t>(k)];
      if (node < 0 || node >= numberOfPoints)
      {
        throw std::invalid_argument("RepairCells: a node index is out of range");
      }
    }
  }
}

/// Newell normal (twice the vector area) of a triangle or quad given by its corners.
Vec3 PolygonNormal(CellShape shape, const double* corners)
{
  const Vec3 p0 = Load(corners, 0);
  if (shape == CellShape::Triangle)
  {
    return Cross(Load(corners, 1) - p0, Load(corners, 2) - p0);
  }
  return Cross(Load(corners, 2) - p0, Load(corners, 3) - Load(corners, 1));
}

/// Runs the node steps over the free region.
class Repairer
{
public:
  Repairer(const CellMesh& mesh, const double* originalPoints, double* points,
    const std::vector<std::int64_t>& freeIndex)
    : Mesh(mesh)
    , OriginalPoints(originalPoints)
    , Points(points)
    , FreeIndex(freeIndex)
  {
  }

  std::vector<ActiveCell> Cells;
  std::vector<std::size_t> Incident; ///< active-cell indices, grouped by free node
  std::vector<FreeNode> Nodes;

  /// Fills the original-shape data and the current quality of an active cell.
  void InitializeCell(ActiveCell& cell, std::size_t c, double quality, bool inverted) const
  {
    cell.Cell = c;
    cell.Shape = this->Mesh.Shapes[c];
    cell.Tables = GetTables(cell.Shape);
    cell.NumberOfNodes = GetNumberOfCorners(cell.Shape);
    cell.Nodes = this->Mesh.Connectivity.data() + this->Mesh.Offsets[c];
    GatherCorners(this->Mesh, c, this->OriginalPoints, cell.Original);
    const CellQuality self = ComputeSizeSkew(cell.Shape, cell.Original, cell.Original);
    cell.Degenerate = self.SizeSkew == 0.0 && !self.Inverted;
    cell.Quality = quality;
    cell.Inverted = inverted;
    if (cell.Tables.Dimension == 2)
    {
      const Vec3 n0 = PolygonNormal(cell.Shape, cell.Original);
      const double length = Norm(n0);
      if (length > 0.0 && std::isfinite(length))
      {
        cell.Normal0 = (1.0 / length) * n0;
        // Mean corner Jacobian: 2 x area (triangle), area (quad); |n0| = 2 x area.
        cell.Beta = kUntangleFraction * (cell.Shape == CellShape::Triangle ? length : 0.5 * length);
      }
      else
      {
        cell.Degenerate = true;
      }
    }
    else
    {
      double sum = 0.0;
      for (int k = 0; k < cell.Tables.NumberOfCorners; ++k)
      {
        sum += this->Alpha3(cell.Tables.Corners[k], cell.Original);
      }
      cell.Orientation = sum < 0.0 ? -1.0 : 1.0;
      cell.Beta = kUntangleFraction * std::abs(sum) / cell.Tables.NumberOfCorners;
      if (!std::isfinite(cell.Beta))
      {
        cell.Degenerate = true;
      }
    }
  }

  /// Runs at most `maximumPasses` passes; returns the number run.
  std::size_t Run(int maximumPasses, double threshold)
  {
    this->Threshold = threshold;
    std::size_t passes = 0;
    this->Dirty.assign(this->Nodes.size(), 1);
    for (int pass = 0; pass < maximumPasses; ++pass)
    {
      if (this->CountRepairableBadCells(threshold) == 0)
      {
        break;
      }
      std::size_t moved = 0;
      for (std::size_t i = 0; i < this->Nodes.size(); ++i)
      {
        if (this->Nodes[i].Enabled && this->Dirty[i] != 0)
        {
          this->Dirty[i] = 0;
          if (this->StepNode(this->Nodes[i]))
          {
            ++moved;
          }
        }
      }
      ++passes;
      if (moved == 0)
      {
        break;
      }
    }
    return passes;
  }

private:
  const CellMesh& Mesh;
  const double* OriginalPoints;
  double* Points;
  const std::vector<std::int64_t>& FreeIndex; ///< index in Nodes of each mesh node, or -1
  /// Per free node: its neighbourhood changed since its last step (a step of a node whose
  /// neighbourhood did not change would fail again, so skipping it does not change the result).
  std::vector<std::uint8_t> Dirty;
  double Threshold = 0.0;
  // Scratch buffers, reused by every node step.
  std::vector<double> Margins0;
  std::vector<double> Targets0;
  std::vector<double> Margins;
  std::vector<Vec3> CornerGradients;
  std::vector<double> Qualities0;
  std::vector<Vec3> QualityGradients;
  std::vector<Vec3> Directions;

  static double Alpha3(const Corner& corner, const double* corners)
  {
    const Vec3 o = Load(corners, corner.Origin);
    return Dot(
      Cross(Load(corners, corner.A) - o, Load(corners, corner.B) - o), Load(corners, corner.C) - o);
  }

  /// The cell's deformed corners with `node` at `position`.
  void GatherWith(
    const ActiveCell& cell, std::int64_t node, const Vec3& position, double* out) const
  {
    for (int k = 0; k < cell.NumberOfNodes; ++k)
    {
      const Vec3 p = cell.Nodes[k] == node ? position : Load(this->Points, cell.Nodes[k]);
      Store(p, out, k);
    }
  }

  std::size_t CountRepairableBadCells(double threshold) const
  {
    std::size_t count = 0;
    for (const ActiveCell& cell : this->Cells)
    {
      if (cell.FreeNodeCount > 0 && !cell.Degenerate &&
        IsBadCell(CellQuality{ cell.Quality, cell.Inverted }, threshold))
      {
        ++count;
      }
    }
    return count;
  }

  /**
   * Minimum SizeSkew over the node's cells (0 if one is inverted) with the node at `position`;
   * per-cell values to `qualities` if not null; `inverted` tells if one is inverted. Without
   * `qualities`, stops at the first cell at or below `cutoff` (the caller rejects such a point
   * anyway), starting with the cell at offset `first` (the worst one, most likely to stop it).
   */
  double IncidentMinimum(const FreeNode& node, const Vec3& position, bool& inverted,
    double* qualities, double cutoff = -kInfinity, std::size_t first = 0) const
  {
    double corners[3 * kMaximumCorners];
    double minimum = kInfinity;
    inverted = false;
    const std::size_t count = node.CellEnd - node.CellBegin;
    for (std::size_t j = 0; j < count; ++j)
    {
      const std::size_t offset = (first + j) % count;
      const ActiveCell& cell = this->Cells[this->Incident[node.CellBegin + offset]];
      if (cell.Degenerate)
      {
        continue;
      }
      this->GatherWith(cell, node.Id, position, corners);
      const CellQuality quality = ComputeSizeSkew(cell.Shape, cell.Original, corners);
      inverted = inverted || quality.Inverted;
      minimum = std::min(minimum, quality.SizeSkew);
      if (qualities != nullptr)
      {
        qualities[offset] = quality.SizeSkew;
      }
      else if (minimum <= cutoff)
      {
        break;
      }
    }
    return minimum;
  }

  /**
   * alpha_k - beta for every corner of the node's cells with the node at `position`, appended to
   * `margins` in a fixed order (and beta to `targets`). Returns Knupp's objective
   * sum_k max(0, beta - alpha_k), half of sum_k |alpha_k - beta| - (alpha_k - beta), or infinity
   * if a Jacobian is not finite. Without `margins`, stops as soon as the objective reaches
   * `cutoff`.
   */
  double CornerMargins(const FreeNode& node, const Vec3& position, std::vector<double>* margins,
    std::vector<double>* targets = nullptr, double cutoff = kInfinity) const
  {
    double corners[3 * kMaximumCorners];
    double objective = 0.0;
    if (margins != nullptr)
    {
      margins->clear();
    }
    if (targets != nullptr)
    {
      targets->clear();
    }
    for (std::size_t i = node.CellBegin; i < node.CellEnd; ++i)
    {
      const ActiveCell& cell = this->Cells[this->Incident[i]];
      if (cell.Degenerate)
      {
        continue;
      }
      this->GatherWith(cell, node.Id, position, corners);
      for (int k = 0; k < cell.Tables.NumberOfCorners; ++k)
      {
        const Corner& corner = cell.Tables.Corners[k];
        double alpha;
        if (cell.Tables.Dimension == 2)
        {
          const Vec3 o = Load(corners, corner.Origin);
          alpha =
            Dot(Cross(Load(corners, corner.A) - o, Load(corners, corner.B) - o), cell.Normal0);
        }
        else
        {
          alpha = cell.Orientation * Alpha3(corner, corners);
        }
        const double margin = alpha - cell.Beta;
        if (!std::isfinite(margin))
        {
          objective = kInfinity;
        }
        else if (margin < 0.0)
        {
          objective -= margin;
        }
        if (margins != nullptr)
        {
          margins->push_back(margin);
        }
        if (targets != nullptr)
        {
          targets->push_back(cell.Beta);
        }
      }
      if (margins == nullptr && objective >= cutoff)
      {
        break;
      }
    }
    return objective;
  }

  /**
   * The mean of the node's edge neighbours (Laplacian position) and the mean edge length. The
   * mean is taken relative to the first neighbour, so that a coordinate all neighbours share (z
   * in a 2D mesh) is reproduced exactly.
   */
  void Neighbourhood(const FreeNode& node, const Vec3& x, Vec3& laplacian, double& length) const
  {
    Vec3 reference{ 0.0, 0.0, 0.0 };
    Vec3 sum{ 0.0, 0.0, 0.0 };
    double deformedLength = 0.0;
    double originalLength = 0.0;
    int count = 0;
    const Vec3 x0 = Load(this->OriginalPoints, node.Id);
    for (std::size_t i = node.CellBegin; i < node.CellEnd; ++i)
    {
      const ActiveCell& cell = this->Cells[this->Incident[i]];
      for (int e = 0; e < cell.Tables.NumberOfEdges; ++e)
      {
        const std::int64_t a = cell.Nodes[cell.Tables.Edges[e][0]];
        const std::int64_t b = cell.Nodes[cell.Tables.Edges[e][1]];
        if ((a == node.Id) == (b == node.Id))
        {
          continue; // not an edge of the node (or a collapsed edge in the connectivity)
        }
        const std::int64_t other = a == node.Id ? b : a;
        const Vec3 p = Load(this->Points, other);
        if (count == 0)
        {
          reference = p;
        }
        sum = sum + (p - reference);
        deformedLength += Norm(p - x);
        originalLength += Norm(Load(this->OriginalPoints, other) - x0);
        ++count;
      }
    }
    if (count == 0)
    {
      laplacian = x;
      length = 0.0;
      return;
    }
    laplacian = reference + (1.0 / count) * sum;
    length = deformedLength / count;
    if (!(length > 0.0 && std::isfinite(length)))
    {
      length = originalLength / count;
    }
  }

  /// `v` restricted to the node's plane (2D), or `v` (3D).
  static Vec3 InPlane(const FreeNode& node, const Vec3& v)
  {
    if (node.Dimension == 3)
    {
      return v;
    }
    return Dot(v, node.Basis[0]) * node.Basis[0] + Dot(v, node.Basis[1]) * node.Basis[1];
  }

  /// Adds the unit vector along `v` to Directions (nothing for a zero or non-finite `v`).
  void AddDirection(const Vec3& v)
  {
    const double length = Norm(v);
    if (length > 0.0 && std::isfinite(length))
    {
      this->Directions.push_back((1.0 / length) * v);
    }
  }

  /// Adds the 26 (3D) or 8 (2D) directions to the neighbours of a cubic (square) lattice.
  void AddLatticeDirections(const FreeNode& node)
  {
    for (int a = -1; a <= 1; ++a)
    {
      for (int b = -1; b <= 1; ++b)
      {
        for (int c = -1; c <= 1; ++c)
        {
          if ((a == 0 && b == 0 && c == 0) || (node.Dimension == 2 && c != 0))
          {
            continue;
          }
          this->AddDirection(static_cast<double>(a) * node.Basis[0] +
            static_cast<double>(b) * node.Basis[1] + static_cast<double>(c) * node.Basis[2]);
        }
      }
    }
  }

  /// Moves the node to `position` and refreshes the cached quality of its cells.
  void Accept(FreeNode& node, const Vec3& position)
  {
    Store(position, this->Points, node.Id);
    double corners[3 * kMaximumCorners];
    for (std::size_t i = node.CellBegin; i < node.CellEnd; ++i)
    {
      ActiveCell& cell = this->Cells[this->Incident[i]];
      this->GatherWith(cell, node.Id, position, corners);
      const CellQuality quality = ComputeSizeSkew(cell.Shape, cell.Original, corners);
      cell.Quality = quality.SizeSkew;
      cell.Inverted = quality.Inverted;
      for (int k = 0; k < cell.NumberOfNodes; ++k)
      {
        const std::int64_t index = this->FreeIndex[static_cast<std::size_t>(cell.Nodes[k])];
        if (index >= 0)
        {
          this->Dirty[static_cast<std::size_t>(index)] = 1;
        }
      }
    }
  }

  /// One untangling or smoothing step of a node; true if it moved.
  bool StepNode(FreeNode& node)
  {
    bool inverted = false;
    double minimum = kInfinity;
    for (std::size_t i = node.CellBegin; i < node.CellEnd; ++i)
    {
      const ActiveCell& cell = this->Cells[this->Incident[i]];
      if (!cell.Degenerate)
      {
        inverted = inverted || cell.Inverted;
        minimum = std::min(minimum, cell.Quality);
      }
    }
    if (!inverted)
    {
      if (minimum >= std::min(1.0, kComfortFactor * this->Threshold))
      {
        return false; // every cell of the node is comfortably good: it need not make room
      }
      return this->SmoothNode(node, minimum);
    }
    bool moved = false;
    for (int step = 0; step < kUntangleStepsPerPass && inverted; ++step)
    {
      if (!this->UntangleNode(node))
      {
        break;
      }
      moved = true;
      inverted = false;
      for (std::size_t i = node.CellBegin; i < node.CellEnd; ++i)
      {
        const ActiveCell& cell = this->Cells[this->Incident[i]];
        inverted = inverted || (cell.Inverted && !cell.Degenerate);
      }
    }
    return moved;
  }

  /**
   * Knupp's untangling: decreases sum_k max(0, beta - alpha_k) over the corners of the node's
   * cells. Every alpha_k is an affine function of the node's position, so the objective is convex
   * and piecewise linear; its gradients are exact finite differences. A pattern search tries steps
   * of 2 to 1/32 edge lengths along the descent direction, each violated corner's own ascent
   * direction, a descent that includes the nearly violated corners, the Laplacian direction and
   * the 26 (2D: 8) lattice directions, and keeps the best point.
   */
  bool UntangleNode(FreeNode& node)
  {
    const Vec3 x = Load(this->Points, node.Id);
    Vec3 laplacian;
    double h;
    this->Neighbourhood(node, x, laplacian, h);
    if (!IsFinite(x))
    {
      // A lost node (non-finite coordinates): back to the mean of its neighbours if that helps.
      if (IsFinite(laplacian) && std::isfinite(this->CornerMargins(node, laplacian, nullptr)))
      {
        this->Accept(node, laplacian);
        return true;
      }
      return false;
    }
    if (!(h > 0.0 && std::isfinite(h)))
    {
      return false;
    }
    const double objective0 = this->CornerMargins(node, x, &this->Margins0, &this->Targets0);
    if (!(objective0 > 0.0) || !std::isfinite(objective0))
    {
      return false; // the inverted cells do not depend on this node's corners
    }

    // Gradient of every corner's margin along the basis vectors (exact: the margins are affine).
    const std::size_t corners = this->Margins0.size();
    this->CornerGradients.assign(corners, Vec3{ 0.0, 0.0, 0.0 });
    for (int d = 0; d < node.Dimension; ++d)
    {
      this->CornerMargins(node, x + h * node.Basis[d], &this->Margins);
      for (std::size_t k = 0; k < corners; ++k)
      {
        const double slope = (this->Margins[k] - this->Margins0[k]) / h;
        this->CornerGradients[k] = this->CornerGradients[k] + slope * node.Basis[d];
      }
    }
    this->Directions.clear();
    Vec3 descent{ 0.0, 0.0, 0.0 };
    for (std::size_t k = 0; k < corners; ++k)
    {
      if (this->Margins0[k] < 0.0)
      {
        descent = descent + this->CornerGradients[k];
      }
    }
    this->AddDirection(descent);
    for (std::size_t k = 0; k < corners; ++k)
    {
      if (this->Margins0[k] < 0.0)
      {
        this->AddDirection(this->CornerGradients[k]);
      }
    }
    // Descent that also pushes the nearly violated corners (alpha below 2 beta) away: steepest
    // descent alone stalls at the kinks of the objective.
    Vec3 wideDescent{ 0.0, 0.0, 0.0 };
    for (std::size_t k = 0; k < corners; ++k)
    {
      if (this->Margins0[k] < this->Targets0[k])
      {
        wideDescent = wideDescent + this->CornerGradients[k];
      }
    }
    this->AddDirection(wideDescent);
    this->AddDirection(InPlane(node, laplacian - x));
    this->AddLatticeDirections(node);

    double best = objective0 * (1.0 - kMinimumRelativeDecrease);
    Vec3 bestPosition = x;
    bool found = false;
    for (const Vec3& direction : this->Directions)
    {
      for (double step : kUntangleSteps)
      {
        const Vec3 y = x + (step * h) * direction;
        if (!IsFinite(y))
        {
          continue;
        }
        const double objective = this->CornerMargins(node, y, nullptr, nullptr, best);
        if (objective < best)
        {
          best = objective;
          bestPosition = y;
          found = true;
        }
      }
    }
    if (found)
    {
      this->Accept(node, bestPosition);
    }
    return found;
  }

  /**
   * Max-min smoothing: the best of the points on the segment toward the Laplacian position and
   * of steps along the ascent direction of a soft minimum of the cells' SizeSkew (and of the worst
   * cell's own), or if none of them improves, of short steps along the lattice directions;
   * accepted only if no cell is inverted there and the minimum rises.
   */
  bool SmoothNode(FreeNode& node, double minimum0)
  {
    const Vec3 x = Load(this->Points, node.Id);
    Vec3 laplacian;
    double h;
    this->Neighbourhood(node, x, laplacian, h);
    if (!IsFinite(x) || !(h > 0.0 && std::isfinite(h)) || !std::isfinite(minimum0))
    {
      return false;
    }
    std::size_t worst = 0;
    for (std::size_t i = node.CellBegin; i < node.CellEnd; ++i)
    {
      const ActiveCell& cell = this->Cells[this->Incident[i]];
      if (!cell.Degenerate && cell.Quality == minimum0)
      {
        worst = i - node.CellBegin;
        break;
      }
    }
    double best = minimum0 + kMinimumGain;
    Vec3 bestPosition = x;
    bool found = false;
    const auto tryPosition = [&](const Vec3& y)
    {
      if (!IsFinite(y))
      {
        return;
      }
      bool yInverted;
      const double value = this->IncidentMinimum(node, y, yInverted, nullptr, best, worst);
      if (!yInverted && value > best)
      {
        best = value;
        bestPosition = y;
        found = true;
      }
    };
    const Vec3 towardLaplacian = InPlane(node, laplacian - x);
    for (double fraction : kLaplacianFractions)
    {
      tryPosition(x + fraction * towardLaplacian);
    }

    // SizeSkew gradients by forward differences from the cached values.
    const std::size_t count = node.CellEnd - node.CellBegin;
    this->Qualities0.resize(count);
    this->Margins.resize(count);
    this->QualityGradients.assign(count, Vec3{ 0.0, 0.0, 0.0 });
    for (std::size_t i = 0; i < count; ++i)
    {
      this->Qualities0[i] = this->Cells[this->Incident[node.CellBegin + i]].Quality;
    }
    const double delta = kGradientStep * h;
    for (int d = 0; d < node.Dimension; ++d)
    {
      bool inverted;
      this->IncidentMinimum(node, x + delta * node.Basis[d], inverted, this->Margins.data());
      for (std::size_t i = 0; i < count; ++i)
      {
        const double slope = (this->Margins[i] - this->Qualities0[i]) / delta;
        this->QualityGradients[i] = this->QualityGradients[i] + slope * node.Basis[d];
      }
    }
    Vec3 softAscent{ 0.0, 0.0, 0.0 };
    Vec3 worstAscent{ 0.0, 0.0, 0.0 };
    bool worstFound = false;
    for (std::size_t i = 0; i < count; ++i)
    {
      if (this->Cells[this->Incident[node.CellBegin + i]].Degenerate)
      {
        continue;
      }
      const double weight = std::exp(-kSoftMinimumSharpness * (this->Qualities0[i] - minimum0));
      softAscent = softAscent + weight * this->QualityGradients[i];
      if (!worstFound && this->Qualities0[i] == minimum0)
      {
        worstAscent = this->QualityGradients[i];
        worstFound = true;
      }
    }
    this->Directions.clear();
    this->AddDirection(softAscent);
    this->AddDirection(worstAscent);
    for (const Vec3& direction : this->Directions)
    {
      for (double step : kAscentSteps)
      {
        tryPosition(x + (step * h) * direction);
      }
    }
    if (!found)
    {
      // At a kink of the minimum (several worst cells): a fixed pattern of directions.
      this->Directions.clear();
      this->AddLatticeDirections(node);
      for (const Vec3& direction : this->Directions)
      {
        for (double step : kPatternSteps)
        {
          tryPosition(x + (step * h) * direction);
        }
      }
    }
    if (found)
    {
      this->Accept(node, bestPosition);
    }
    return found;
  }
};

/// Unit normal of the plane the node's 2D cells share, or false if they are not coplanar.
bool FindPlane(const std::vector<ActiveCell>& cells, const std::size_t* incident, std::size_t count,
  const double* points, Vec3& normal)
{
  // The deformed cells' normals; the original ones if none is usable (a lost node).
  for (int configuration = 0; configuration < 2; ++configuration)
  {
    bool found = false;
    Vec3 reference{ 0.0, 0.0, 0.0 };
    double referenceLength = 0.0;
    for (std::size_t i = 0; i < count; ++i)
    {
      const ActiveCell& cell = cells[incident[i]];
      Vec3 n;
      if (configuration == 0)
      {
        double corners[3 * kMaximumCorners];
        for (int k = 0; k < cell.NumberOfNodes; ++k)
        {
          Store(Load(points, cell.Nodes[k]), corners, k);
        }
        n = PolygonNormal(cell.Shape, corners);
      }
      else
      {
        n = PolygonNormal(cell.Shape, cell.Original);
      }
      const double length = Norm(n);
      if (!(length > 0.0 && std::isfinite(length)))
      {
        continue;
      }
      if (!found)
      {
        reference = n;
        referenceLength = length;
        found = true;
      }
      else if (Norm(Cross(n, reference)) > kCoplanarTolerance * length * referenceLength)
      {
        return false;
      }
    }
    if (found)
    {
      normal = (1.0 / referenceLength) * reference;
      // Keep the axis exact for a plane normal to an axis (z kept bit for bit in x-y meshes).
      if (normal.X == 0.0 && normal.Y == 0.0)
      {
        normal.Z = normal.Z > 0.0 ? 1.0 : -1.0;
      }
      else if (normal.X == 0.0 && normal.Z == 0.0)
      {
        normal.Y = normal.Y > 0.0 ? 1.0 : -1.0;
      }
      else if (normal.Y == 0.0 && normal.Z == 0.0)
      {
        normal.X = normal.X > 0.0 ? 1.0 : -1.0;
      }
      return true;
    }
  }
  return false;
}

/// Two orthonormal vectors spanning the plane normal to the unit vector `n`: the projected
/// coordinate axis that is longest, then n x it (the x and y axes for n = +-z, exactly).
void PlaneBasis(const Vec3& n, Vec3& u, Vec3& v)
{
  const Vec3 axes[3] = { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
  Vec3 longest{ 0.0, 0.0, 0.0 };
  double longestLength = -1.0;
  for (const Vec3& axis : axes)
  {
    const Vec3 projected = axis - Dot(axis, n) * n;
    const double length = Norm(projected);
    if (length > longestLength)
    {
      longest = projected;
      longestLength = length;
    }
  }
  u = (1.0 / longestLength) * longest;
  v = Cross(n, u);
}

} // namespace

RepairReport RepairCells(const CellMesh& mesh, const double* originalPoints, double* points,
  const NodeKind* kinds, const RepairParameters& parameters, const ParallelFor& parallelFor)
{
  Validate(mesh, originalPoints, points, kinds, parameters);
  RepairReport report;
  const std::size_t numberOfCells = mesh.GetNumberOfCells();
  if (numberOfCells == 0)
  {
    return report;
  }

  // 1. Quality of every cell, in fixed blocks.
  std::vector<double> quality(numberOfCells, std::numeric_limits<double>::quiet_NaN());
  std::vector<std::uint8_t> inverted(numberOfCells, 0);
  const std::size_t blocks = (numberOfCells + kCellsPerBlock - 1) / kCellsPerBlock;
  ForEachBlock(parallelFor, blocks,
    [&](std::size_t block)
    {
      double original[3 * kMaximumCorners];
      double deformed[3 * kMaximumCorners];
      const std::size_t end = std::min(numberOfCells, (block + 1) * kCellsPerBlock);
      for (std::size_t c = block * kCellsPerBlock; c < end; ++c)
      {
        if (IsCovered(mesh, c))
        {
          GatherCorners(mesh, c, originalPoints, original);
          GatherCorners(mesh, c, points, deformed);
          const CellQuality q = ComputeSizeSkew(mesh.Shapes[c], original, deformed);
          quality[c] = q.SizeSkew;
          inverted[c] = q.Inverted ? 1 : 0;
        }
      }
    });
  const auto summarize = [&](std::size_t& bad, std::size_t& invertedCount, double& minimum)
  {
    bad = 0;
    invertedCount = 0;
    minimum = kInfinity;
    for (std::size_t c = 0; c < numberOfCells; ++c)
    {
      if (IsCovered(mesh, c))
      {
        bad += IsBadCell(CellQuality{ quality[c], inverted[c] != 0 }, parameters.Threshold) ? 1 : 0;
        invertedCount += inverted[c];
        minimum = std::min(minimum, quality[c]);
      }
    }
    if (minimum == kInfinity)
    {
      minimum = 0.0;
    }
  };
  summarize(report.BadCellsBefore, report.InvertedBefore, report.MinimumBefore);
  report.BadCellsAfter = report.BadCellsBefore;
  report.InvertedAfter = report.InvertedBefore;
  report.MinimumAfter = report.MinimumBefore;
  if (report.BadCellsBefore == 0 || parameters.MaximumPasses == 0)
  {
    return report;
  }

  // 2. Nodes that never move: boundary nodes, and the nodes of cells the metric does not cover.
  const std::size_t numberOfPoints = mesh.NumberOfPoints;
  std::vector<std::uint8_t> fixed(numberOfPoints, 0);
  for (std::size_t n = 0; n < numberOfPoints; ++n)
  {
    fixed[n] = kinds[n] != NodeKind::Interior ? 1 : 0;
  }
  for (std::size_t c = 0; c < numberOfCells; ++c)
  {
    if (!IsCovered(mesh, c))
    {
      for (std::int64_t k = mesh.Offsets[c]; k < mesh.Offsets[c + 1]; ++k)
      {
        fixed[static_cast<std::size_t>(mesh.Connectivity[static_cast<std::size_t>(k)])] = 1;
      }
    }
  }

  // 3. The region: seeds are the bad cells that can change (a movable node, not degenerate),
  // grown by `Layers` node-neighbour layers. slot[n] holds the layer of node n (-1: outside).
  std::vector<std::int64_t> slot(numberOfPoints, -1);
  const auto nodesOf = [&](std::size_t c)
  {
    return std::make_pair(
      mesh.Connectivity.data() + mesh.Offsets[c], mesh.Connectivity.data() + mesh.Offsets[c + 1]);
  };
  bool anySeed = false;
  for (std::size_t c = 0; c < numberOfCells; ++c)
  {
    if (!IsCovered(mesh, c) ||
      !IsBadCell(CellQuality{ quality[c], inverted[c] != 0 }, parameters.Threshold))
    {
      continue;
    }
    if (quality[c] == 0.0 && inverted[c] == 0)
    {
      continue; // degenerate original cell: no move changes its score
    }
    const auto range = nodesOf(c);
    const bool movable = std::any_of(range.first, range.second,
      [&](std::int64_t n) { return fixed[static_cast<std::size_t>(n)] == 0; });
    if (movable)
    {
      anySeed = true;
      for (const std::int64_t* n = range.first; n != range.second; ++n)
      {
        slot[static_cast<std::size_t>(*n)] = 0;
      }
    }
  }
  if (!anySeed)
  {
    return report;
  }
  for (int layer = 1; layer <= parameters.Layers; ++layer)
  {
    bool grew = false;
    for (std::size_t c = 0; c < numberOfCells; ++c)
    {
      const auto range = nodesOf(c);
      const bool touches = std::any_of(range.first, range.second,
        [&](std::int64_t n)
        {
          const std::int64_t level = slot[static_cast<std::size_t>(n)];
          return level >= 0 && level < layer;
        });
      if (touches)
      {
        for (const std::int64_t* n = range.first; n != range.second; ++n)
        {
          if (slot[static_cast<std::size_t>(*n)] < 0)
          {
            slot[static_cast<std::size_t>(*n)] = layer;
            grew = true;
          }
        }
      }
    }
    if (!grew)
    {
      break;
    }
  }

  // 4. Free nodes (slot becomes their index) and the cells around them.
  Repairer repairer(mesh, originalPoints, points, slot);
  std::vector<FreeNode>& nodes = repairer.Nodes;
  for (std::size_t n = 0; n < numberOfPoints; ++n)
  {
    if (slot[n] >= 0 && fixed[n] == 0)
    {
      slot[n] = static_cast<std::int64_t>(nodes.size());
      FreeNode node;
      node.Id = static_cast<std::int64_t>(n);
      nodes.push_back(node);
    }
    else
    {
      slot[n] = -1;
    }
  }
  std::vector<std::size_t> counts(nodes.size() + 1, 0);
  std::vector<ActiveCell>& cells = repairer.Cells;
  for (std::size_t c = 0; c < numberOfCells; ++c)
  {
    const auto range = nodesOf(c);
    bool active = false;
    for (const std::int64_t* n = range.first; n != range.second; ++n)
    {
      const std::int64_t index = slot[static_cast<std::size_t>(*n)];
      if (index >= 0 && std::find(range.first, n, *n) == n) // count a repeated node once
      {
        ++counts[static_cast<std::size_t>(index) + 1];
        active = true;
      }
    }
    if (active)
    {
      // Only covered cells: a free node has no uncovered cell (its nodes are fixed).
      cells.emplace_back();
      repairer.InitializeCell(cells.back(), c, quality[c], inverted[c] != 0);
    }
  }
  for (std::size_t i = 0; i < nodes.size(); ++i)
  {
    counts[i + 1] += counts[i];
    nodes[i].CellBegin = counts[i];
    nodes[i].CellEnd = counts[i];
  }
  repairer.Incident.resize(counts.back());
  for (std::size_t a = 0; a < cells.size(); ++a)
  {
    const ActiveCell& cell = cells[a];
    for (int k = 0; k < cell.NumberOfNodes; ++k)
    {
      const std::int64_t index = slot[static_cast<std::size_t>(cell.Nodes[k])];
      if (index >= 0 && std::find(cell.Nodes, cell.Nodes + k, cell.Nodes[k]) == cell.Nodes + k)
      {
        repairer.Incident[nodes[static_cast<std::size_t>(index)].CellEnd++] = a;
      }
    }
  }

  // 5. Move space of each node: all directions among 3D cells, the plane of its 2D cells.
  for (FreeNode& node : nodes)
  {
    int dimensions = 0; // bit 0: a 2D cell, bit 1: a 3D cell
    bool anyValid = false;
    for (std::size_t i = node.CellBegin; i < node.CellEnd; ++i)
    {
      const ActiveCell& cell = cells[repairer.Incident[i]];
      dimensions |= cell.Tables.Dimension == 2 ? 1 : 2;
      anyValid = anyValid || !cell.Degenerate;
    }
    if (!anyValid || dimensions == 3)
    {
      node.Enabled = false;
    }
    else if (dimensions == 1)
    {
      node.Dimension = 2;
      if (FindPlane(cells, repairer.Incident.data() + node.CellBegin, node.CellEnd - node.CellBegin,
            points, node.Normal))
      {
        PlaneBasis(node.Normal, node.Basis[0], node.Basis[1]);
      }
      else
      {
        node.Enabled = false;
      }
    }
    if (node.Enabled)
    {
      ++report.FreeNodes;
      for (std::size_t i = node.CellBegin; i < node.CellEnd; ++i)
      {
        ++cells[repairer.Incident[i]].FreeNodeCount;
      }
    }
  }

  // 6. The passes, then the report.
  std::vector<double> before(3 * nodes.size());
  for (std::size_t i = 0; i < nodes.size(); ++i)
  {
    std::copy(points + 3 * nodes[i].Id, points + 3 * nodes[i].Id + 3, before.begin() + 3 * i);
  }
  report.Passes = repairer.Run(parameters.MaximumPasses, parameters.Threshold);
  for (std::size_t i = 0; i < nodes.size(); ++i)
  {
    const double* p = points + 3 * nodes[i].Id;
    if (std::memcmp(p, before.data() + 3 * i, 3 * sizeof(double)) != 0)
    {
      ++report.MovedNodes;
    }
  }
  for (const ActiveCell& cell : cells)
  {
    quality[cell.Cell] = cell.Quality;
    inverted[cell.Cell] = cell.Inverted ? 1 : 0;
  }
  summarize(report.BadCellsAfter, report.InvertedAfter, report.MinimumAfter);
  return report;
}

} // namespace dgmf
