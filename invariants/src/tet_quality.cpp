#include "tet_quality.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "tet_tables.hpp"

namespace tetcut::invariants::detail {

double tet_radius_ratio(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const Vec3 u = b - a, v = c - a, w = d - a;
  const double six_volume = dot(u, cross(v, w));
  if (six_volume == 0.0) return 0.0;
  // Circumcentre relative to a: o is as far from 0 as from u, v and w, so o.u = |u|^2 / 2,
  // o.v = |v|^2 / 2, o.w = |w|^2 / 2; by Cramer's rule
  // o = (|u|^2 (v x w) + |v|^2 (w x u) + |w|^2 (u x v)) / (2 u.(v x w)).
  const Vec3 o = (1.0 / (2.0 * six_volume)) *
                 (dot(u, u) * cross(v, w) + dot(v, v) * cross(w, u) + dot(w, w) * cross(u, v));
  const double circumradius = norm(o);
  const double twice_area = norm(cross(u, v)) + norm(cross(v, w)) + norm(cross(w, u)) + norm(cross(c - b, d - b));
  const double inradius = std::abs(six_volume) / twice_area;  // 3V / A with V = |6V| / 6, A = twice_area / 2
  return std::min(3.0 * inradius / circumradius, 1.0);
}

double tet_min_dihedral_deg(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const std::array<Vec3, 4> p = {a, b, c, d};
  double smallest = 180.0;
  for (const auto& e : kTetEdges) {
    const Vec3 along = p[e[1]] - p[e[0]];
    const Vec3 n0 = cross(along, p[e[2]] - p[e[0]]);
    const Vec3 n1 = cross(along, p[e[3]] - p[e[0]]);
    const double angle = std::atan2(norm(cross(n0, n1)), dot(n0, n1)) * (180.0 / std::numbers::pi);
    smallest = std::min(smallest, angle);
  }
  return smallest;
}

}  // namespace tetcut::invariants::detail
