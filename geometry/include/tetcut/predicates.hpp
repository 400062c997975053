// Exact geometric predicates. We use Shewchuk's adaptive-precision orient3d as exported by
// TetGen's libtet (exact sign for every double input; also well behaved under valgrind), behind
// its first stage written out inline here: the determinant in plain doubles and Shewchuk's
// error bound on it (o3derrboundA times the permanent, "Adaptive Precision Floating-Point
// Arithmetic and Fast Robust Geometric Predicates", 1997, section 4.3). When the determinant
// clears the bound its sign is exact, and only the rest go through the library's call. Inline,
// because the cut's tests and the checker ask it tens of times per cut: the call, the copying
// into arrays and the one-time initialization cost more than the filter itself.
// Semi-static (the bound scales with the operands), not static: a static bound needs a box that
// holds every coordinate, which moving vertices and callers' arbitrary meshes do not give.
#pragma once

#include "tetcut/vec3.hpp"

namespace tetcut {

namespace detail {
// The exact sign by Shewchuk's adaptive stages: what the inline filter falls back on.
int orientation_exact(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);
}  // namespace detail

// Sign of det(b - a, c - a, d - a): +1 when (a, b, c, d) is a positively oriented tet (tetcut's
// convention), -1 when inverted, 0 when flat. Exact.
inline int orientation(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
#if defined(__FP_FAST_FMA) && !defined(TETCUT_FP_CONTRACT_OFF)
  // The bound holds for operations rounded one by one; a build that may fuse them into
  // multiply-adds (FMA hardware and no -ffp-contract=off, which tetcut's own build passes and
  // announces with TETCUT_FP_CONTRACT_OFF) takes the library's path for every call.
  return detail::orientation_exact(a, b, c, d);
#else
  // Shewchuk's orient3d(pa, pb, pc, pd) with pa = b, pb = a (his sign is ours with a and b
  // swapped), pc = c, pd = d, term for term, so that the bound is his.
  const double adx = b.x - d.x, bdx = a.x - d.x, cdx = c.x - d.x;
  const double ady = b.y - d.y, bdy = a.y - d.y, cdy = c.y - d.y;
  const double adz = b.z - d.z, bdz = a.z - d.z, cdz = c.z - d.z;
  const double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
  const double cdxady = cdx * ady, adxcdy = adx * cdy;
  const double adxbdy = adx * bdy, bdxady = bdx * ady;
  const double det = adz * (bdxcdy - cdxbdy) + bdz * (cdxady - adxcdy) + cdz * (adxbdy - bdxady);
  auto magnitude = [](double v) { return v < 0.0 ? -v : v; };
  const double permanent = (magnitude(bdxcdy) + magnitude(cdxbdy)) * magnitude(adz) +
                           (magnitude(cdxady) + magnitude(adxcdy)) * magnitude(bdz) +
                           (magnitude(adxbdy) + magnitude(bdxady)) * magnitude(cdz);
  // o3derrboundA = (7 + 56 epsilon) epsilon, epsilon = 2^-53 (Shewchuk's exactinit()).
  constexpr double kEpsilon = 1.1102230246251565e-16;
  constexpr double kBound = (7.0 + 56.0 * kEpsilon) * kEpsilon;
  const double bound = kBound * permanent;
  if (det > bound) return 1;
  if (-det > bound) return -1;
  return detail::orientation_exact(a, b, c, d);
#endif
}

// det(b - a, c - a, d - a) / 6 in plain floating point: the signed volume, for measurements only.
double signed_volume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

}  // namespace tetcut
