/**
 * @file Wendland.h
 * @brief Wendland's C2 function, the basis of RBF and DGRBF and the damping function u2.
 */
#ifndef dgmf_Wendland_h
#define dgmf_Wendland_h

namespace dgmf
{

/**
 * phi(r) = (1 - r)^4 (4 r + 1) for 0 <= r < 1, and 0 for r >= 1 (Wendland 1995): positive
 * definite in up to three dimensions, phi(0) = 1, compact support of radius 1.
 * (RBFFit.cxx also evaluates it on whole tiles of centres with Eigen arrays, as the same formula.)
 */
inline double WendlandC2(double r)
{
  if (r >= 1.0)
  {
    return 0.0;
  }
  const double s = 1.0 - r;
  const double s2 = s * s;
  return s2 * s2 * (4.0 * r + 1.0);
}

} // namespace dgmf

#endif
