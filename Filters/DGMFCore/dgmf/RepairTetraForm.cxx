// A tetrahedron seen from one moving corner (RepairTetraForm.h).
#include "dgmf/RepairTetraForm.h"

#include <cmath>

namespace dgmf
{
namespace repair
{

TetraForm MakeTetraForm(const double* corners, int corner, double orientation, double originalAlpha)
{
  TetraForm form;
  int k = 0;
  for (int c = 0; c < 4; ++c)
  {
    if (c != corner)
    {
      form.Others[k++] = Load(corners, c);
    }
  }
  // The corner Jacobian det(p1 - p0, p2 - p0, p3 - p0) changes sign with each transposition:
  // with the moving corner taken from its place to the last, (-1)^(3 - corner) times
  // (o1 - o0) x (o2 - o0) . (y - o0), o the others in their order.
  const double sign = ((3 - corner) % 2 == 0 ? 1.0 : -1.0) * orientation;
  const Vec3 e01 = form.Others[1] - form.Others[0];
  const Vec3 e02 = form.Others[2] - form.Others[0];
  const Vec3 e12 = form.Others[2] - form.Others[1];
  form.Normal = sign * Cross(e01, e02);
  form.OppositeEdges = Dot(e01, e01) + Dot(e02, e02) + Dot(e12, e12);
  form.OriginalAlpha = originalAlpha;
  form.InverseOriginalAlpha = 1.0 / originalAlpha;
  form.Usable = originalAlpha > 0.0 && IsFinite(form.Normal) && std::isfinite(form.OppositeEdges);
  return form;
}

} // namespace repair
} // namespace dgmf
