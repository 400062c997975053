#include "tetcut/mechanics/label_rule.hpp"

#include "tetcut/predicates.hpp"

namespace tetcut::mechanics {

Vec3 tet_centroid(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) { return 0.25 * ((a + b) + (c + d)); }

bool tet_contains(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Vec3& p) {
  // p replaces each vertex in turn: inside or on the boundary when no orientation turns negative.
  return orientation(p, b, c, d) >= 0 && orientation(a, p, c, d) >= 0 && orientation(a, b, p, d) >= 0 &&
         orientation(a, b, c, p) >= 0;
}

}  // namespace tetcut::mechanics
