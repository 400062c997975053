#include "tet_intersection.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace tetcut::invariants::detail {
namespace {

// A convex polyhedron as its faces, each a convex polygon (in either orientation: the volume
// below takes each fan triangle's absolute volume about an interior point).
using Polygon = std::vector<Vec3>;
using Polyhedron = std::vector<Polygon>;

// The part of `in` on the side n.x <= offset, closed by a cap on the plane. A point within
// `tolerance` of the plane is on it: a face of one tet often lies in a face plane of the other
// (a split child in its parent), and a face found to be on the plane is the cap already.
Polyhedron clip(const Polyhedron& in, const Vec3& n, double offset, double tolerance) {
  auto side = [&](const Vec3& x) {
    const double d = dot(n, x) - offset;
    return std::abs(d) <= tolerance ? 0.0 : d;
  };
  Polyhedron out;
  Polygon cap;
  bool face_on_plane = false;
  for (const Polygon& face : in) {
    Polygon kept;
    bool on_plane = true;
    for (std::size_t i = 0; i < face.size(); ++i) {
      const Vec3& a = face[i];
      const Vec3& b = face[(i + 1) % face.size()];
      const double da = side(a), db = side(b);
      on_plane = on_plane && da == 0;
      if (da <= 0) kept.push_back(a);
      if ((da < 0 && db > 0) || (da > 0 && db < 0)) {
        const Vec3 x = a + (da / (da - db)) * (b - a);
        kept.push_back(x);
        cap.push_back(x);
      } else if (da == 0) {
        cap.push_back(a);
      }
    }
    if (kept.size() >= 3) {
      face_on_plane = face_on_plane || on_plane;
      out.push_back(std::move(kept));
    }
  }
  if (cap.size() >= 3 && !face_on_plane) {
    // The cap's points in angular order about their mean, in a basis of the plane.
    Vec3 mean{0, 0, 0};
    for (const Vec3& p : cap) mean = mean + p;
    mean = (1.0 / static_cast<double>(cap.size())) * mean;
    const Vec3 helper = std::abs(n.x) < 0.6 * norm(n) ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
    const Vec3 u = cross(n, helper), v = cross(n, u);
    std::sort(cap.begin(), cap.end(), [&](const Vec3& p, const Vec3& q) {
      return std::atan2(dot(p - mean, v), dot(p - mean, u)) < std::atan2(dot(q - mean, v), dot(q - mean, u));
    });
    out.push_back(std::move(cap));
  }
  return out;
}

double volume(const Polyhedron& poly) {
  std::size_t count = 0;
  Vec3 inner{0, 0, 0};
  for (const Polygon& face : poly)
    for (const Vec3& p : face) {
      inner = inner + p;
      ++count;
    }
  if (count == 0) return 0.0;
  inner = (1.0 / static_cast<double>(count)) * inner;
  double six = 0.0;
  for (const Polygon& face : poly)
    for (std::size_t i = 1; i + 1 < face.size(); ++i)
      six += std::abs(dot(face[0] - inner, cross(face[i] - inner, face[i + 1] - inner)));
  return six / 6.0;
}

}  // namespace

double tet_intersection_volume(const std::array<Vec3, 4>& p, const std::array<Vec3, 4>& q) {
  Polyhedron poly = {{p[1], p[2], p[3]}, {p[0], p[2], p[3]}, {p[0], p[1], p[3]}, {p[0], p[1], p[2]}};
  // The clip's tolerance: a relative 1e-12 of the distances across the two tets.
  double extent = 0.0;
  for (const Vec3& x : p)
    for (const Vec3& y : q) extent = std::max(extent, norm(x - y));
  for (int i = 0; i < 4 && !poly.empty(); ++i) {
    // q's face opposite corner i, its normal turned away from that corner.
    const Vec3 &a = q[(i + 1) % 4], &b = q[(i + 2) % 4], &c = q[(i + 3) % 4];
    Vec3 n = cross(b - a, c - a);
    if (dot(n, q[i] - a) > 0) n = -1.0 * n;
    poly = clip(poly, n, dot(n, a), 1e-12 * norm(n) * extent);
  }
  return volume(poly);
}

}  // namespace tetcut::invariants::detail
