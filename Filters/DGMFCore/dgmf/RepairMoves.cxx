// The quality guard's two node moves (Documentation/repair.md): Knupp's untangling where a cell
// of the node is inverted, max-min SizeSkew smoothing elsewhere.
#include "dgmf/NodeRepairer.h"

#include <algorithm>
#include <cmath>

namespace dgmf
{
namespace repair
{

bool NodeRepairer::UntangleNode(FreeNode& node)
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

bool NodeRepairer::SmoothNode(FreeNode& node, double minimum0)
{
  const Vec3 x = Load(this->Points, node.Id);
  Vec3 laplacian;
  double h;
  this->Neighbourhood(node, x, laplacian, h);
  if (!IsFinite(x) || !(h > 0.0 && std::isfinite(h)) || !std::isfinite(minimum0))
  {
    return false;
  }
  this->PrepareForms(node);
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
  this->PrepareFormGroups(node, worst);
  // Trial points are compared by the cubes of their minima (no cube root per cell).
  const double threshold = minimum0 + kMinimumGain;
  double bestCube = threshold * threshold * threshold;
  Vec3 bestPosition = x;
  bool found = false;
  const auto tryPosition = [&](const Vec3& y)
  {
    if (!IsFinite(y))
    {
      return;
    }
    bool yInverted;
    const double cube = this->TrialMinimumCube(node, y, yInverted, bestCube, worst);
    if (!yInverted && cube > bestCube)
    {
      bestCube = cube;
      bestPosition = y;
      found = true;
    }
  };
  const Vec3 towardLaplacian = InPlane(node, laplacian - x);
  for (double fraction : kLaplacianFractions)
  {
    tryPosition(x + fraction * towardLaplacian);
  }

  // SizeSkew gradients: the tetrahedra's from their forms, the other cells' by forward
  // differences from the cached values.
  const std::size_t count = node.CellEnd - node.CellBegin;
  this->Qualities0.resize(count);
  this->Margins.resize(count);
  this->QualityGradients.assign(count, Vec3{ 0.0, 0.0, 0.0 });
  bool differences = false;
  for (std::size_t i = 0; i < count; ++i)
  {
    const ActiveCell& cell = this->Cells[this->Incident[node.CellBegin + i]];
    this->Qualities0[i] = cell.Quality;
    differences = differences || (!cell.Degenerate && !this->Forms[i].Usable);
  }
  const double delta = kGradientStep * h;
  for (int d = 0; differences && d < node.Dimension; ++d)
  {
    this->IncidentQualities(node, x + delta * node.Basis[d], this->Margins.data());
    for (std::size_t i = 0; i < count; ++i)
    {
      const double slope = (this->Margins[i] - this->Qualities0[i]) / delta;
      this->QualityGradients[i] = this->QualityGradients[i] + slope * node.Basis[d];
    }
  }
  for (std::size_t i = 0; i < count; ++i)
  {
    if (this->Forms[i].Usable)
    {
      this->QualityGradients[i] = InPlane(node, this->Forms[i].Gradient(x, this->Qualities0[i]));
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
  // The forms hold the other corners' positions of this visit: once a neighbour moves they are
  // stale, so no later step of this node (an untangling's Accept) may read them.
  this->FormsNode = -1;
  return found;
}

} // namespace repair
} // namespace dgmf
