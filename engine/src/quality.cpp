#include "tetcut/quality.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "tetcut/local_tables.hpp"
#include "tetcut/predicates.hpp"

namespace tetcut {

double radius_ratio(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  // inradius r = 3V / (sum of face areas); circumradius R = |alpha| / (12 V) with the classic
  // closed form (product of opposite edge lengths, Heron-like), so 3r/R = 36 V^2 / (A * |alpha|).
  const double volume = std::abs(signed_volume(a, b, c, d));
  if (volume == 0.0) return 0.0;
  const double area = 0.5 * (norm(cross(b - a, c - a)) + norm(cross(b - a, d - a)) +
                             norm(cross(c - a, d - a)) + norm(cross(c - b, d - b)));
  // Products of opposite edge lengths.
  const double p = norm(b - a) * norm(d - c);
  const double q = norm(c - a) * norm(d - b);
  const double s = norm(d - a) * norm(c - b);
  const double heron = (p + q + s) * (-p + q + s) * (p - q + s) * (p + q - s);
  if (!(heron > 0.0)) return 0.0;
  const double six_v_r = std::sqrt(heron);  // = 24 V R
  const double inradius = 3.0 * volume / area;
  const double circumradius = six_v_r / (24.0 * volume);
  return std::clamp(3.0 * inradius / circumradius, 0.0, 1.0);
}

double min_dihedral_angle_deg(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const Vec3 p[4] = {a, b, c, d};
  // Outward face normals; the dihedral angle at edge e is pi minus the angle between the
  // normals of the two faces that contain e.
  Vec3 n[4];
  for (int f = 0; f < 4; ++f) {
    const Vec3& u = p[kFaceVerts[f][0]];
    const Vec3& v = p[kFaceVerts[f][1]];
    const Vec3& w = p[kFaceVerts[f][2]];
    n[f] = cross(v - u, w - u);
  }
  double smallest = 180.0;
  for (int e = 0; e < 6; ++e) {
    const Vec3& n0 = n[kEdgeFaces[e][0]];
    const Vec3& n1 = n[kEdgeFaces[e][1]];
    const double len = norm(n0) * norm(n1);
    if (len == 0.0) return 0.0;
    const double cosine = std::clamp(dot(n0, n1) / len, -1.0, 1.0);
    const double angle = 180.0 - std::acos(cosine) * 180.0 / std::numbers::pi;
    smallest = std::min(smallest, angle);
  }
  return smallest;
}

}  // namespace tetcut
