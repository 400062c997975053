#include "tetcut/predicates.hpp"

#include <tetgen.h>

#include <mutex>

namespace tetcut {
namespace {

// Shewchuk's predicates need their machine epsilon and splitter computed once. We disable
// TetGen's static filter (nofilter = 1), whose bound depends on the bounding box passed here:
// the adaptive filter alone is exact for every input.
void init_predicates_once() {
  static std::once_flag once;
  std::call_once(once, [] { exactinit(/*verbose=*/0, /*noexact=*/0, /*nofilter=*/1, 1.0, 1.0, 1.0); });
}

}  // namespace

int detail::orientation_exact(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  init_predicates_once();
  double pa[3] = {a.x, a.y, a.z};
  double pb[3] = {b.x, b.y, b.z};
  double pc[3] = {c.x, c.y, c.z};
  double pd[3] = {d.x, d.y, d.z};
  // Shewchuk's orient3d is positive when d lies below the plane of (a, b, c) seen
  // counter-clockwise, i.e. for our negative tets: swap a and b to match tetcut's convention.
  const double det = orient3d(pb, pa, pc, pd);
  return (det > 0) - (det < 0);
}

double signed_volume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return dot(b - a, cross(c - a, d - a)) / 6.0;
}

}  // namespace tetcut
