#include "core/tet_intersection.hpp"

#include <algorithm>
#include <cmath>

namespace tetcut::detail {
namespace {

// A convex polygon, in either orientation, and a convex polyhedron as its faces: fixed capacity
// (the header says why it suffices; a point or a face beyond it would be dropped, which four
// clips of a tet never reach).
struct Polygon {
  // A face: at most 3 + 4 vertices. A cap collects every crossing twice (once from each face of
  // the edge) and every vertex on the plane once per face through it: at most 2 x 8 + 8.
  static constexpr int kMax = 24;
  std::array<Vec3, kMax> p{};
  int n = 0;
  void add(const Vec3& x) {
    if (n < kMax) p[static_cast<std::size_t>(n++)] = x;
  }
};
struct Polyhedron {
  static constexpr int kMax = 8;  // 4 faces and one cap per clip
  std::array<Polygon, kMax> face{};
  int n = 0;
};

// The part of `in` on the side n.x <= offset, closed by a cap on the plane. A point within
// `tolerance` of the plane is on it: a face of one tet often lies in a face plane of the other
// (a split child in its parent), and a face found to be on the plane is the cap already.
void clip(const Polyhedron& in, const Vec3& n, double offset, double tolerance, Polyhedron& out) {
  auto side = [&](const Vec3& x) {
    const double d = dot(n, x) - offset;
    return std::abs(d) <= tolerance ? 0.0 : d;
  };
  out.n = 0;
  Polygon cap;
  bool face_on_plane = false;
  for (int f = 0; f < in.n; ++f) {
    const Polygon& face = in.face[static_cast<std::size_t>(f)];
    Polygon kept;
    bool on_plane = true;
    for (int i = 0; i < face.n; ++i) {
      const Vec3& a = face.p[static_cast<std::size_t>(i)];
      const Vec3& b = face.p[static_cast<std::size_t>((i + 1) % face.n)];
      const double da = side(a), db = side(b);
      on_plane = on_plane && da == 0;
      if (da <= 0) kept.add(a);
      if ((da < 0 && db > 0) || (da > 0 && db < 0)) {
        const Vec3 x = a + (da / (da - db)) * (b - a);
        kept.add(x);
        cap.add(x);
      } else if (da == 0) {
        cap.add(a);
      }
    }
    if (kept.n >= 3 && out.n < Polyhedron::kMax) {
      face_on_plane = face_on_plane || on_plane;
      out.face[static_cast<std::size_t>(out.n++)] = kept;
    }
  }
  if (cap.n >= 3 && !face_on_plane && out.n < Polyhedron::kMax) {
    // The cap's points in angular order about their mean, in a basis of the plane.
    Vec3 mean{0, 0, 0};
    for (int i = 0; i < cap.n; ++i) mean = mean + cap.p[static_cast<std::size_t>(i)];
    mean = (1.0 / cap.n) * mean;
    const Vec3 helper = std::abs(n.x) < 0.6 * norm(n) ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
    const Vec3 u = cross(n, helper), v = cross(n, u);
    std::sort(cap.p.begin(), cap.p.begin() + cap.n, [&](const Vec3& p, const Vec3& q) {
      return std::atan2(dot(p - mean, v), dot(p - mean, u)) < std::atan2(dot(q - mean, v), dot(q - mean, u));
    });
    out.face[static_cast<std::size_t>(out.n++)] = cap;
  }
}

double volume(const Polyhedron& poly) {
  int count = 0;
  Vec3 inner{0, 0, 0};
  for (int f = 0; f < poly.n; ++f)
    for (int i = 0; i < poly.face[static_cast<std::size_t>(f)].n; ++i) {
      inner = inner + poly.face[static_cast<std::size_t>(f)].p[static_cast<std::size_t>(i)];
      ++count;
    }
  if (count == 0) return 0.0;
  inner = (1.0 / count) * inner;
  double six = 0.0;
  for (int f = 0; f < poly.n; ++f) {
    const Polygon& face = poly.face[static_cast<std::size_t>(f)];
    for (int i = 1; i + 1 < face.n; ++i)
      six += std::abs(dot(face.p[0] - inner, cross(face.p[static_cast<std::size_t>(i)] - inner,
                                                   face.p[static_cast<std::size_t>(i + 1)] - inner)));
  }
  return six / 6.0;
}

}  // namespace

double tet_intersection_volume(const std::array<Vec3, 4>& p, const std::array<Vec3, 4>& q) {
  std::array<Polyhedron, 2> buffers{};
  Polyhedron* poly = &buffers[0];
  Polyhedron* next = &buffers[1];
  const std::array<std::array<int, 3>, 4> faces{{{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}}};
  for (const auto& f : faces) {
    Polygon g;
    for (int i : f) g.add(p[static_cast<std::size_t>(i)]);
    poly->face[static_cast<std::size_t>(poly->n++)] = g;
  }
  // The clip's tolerance: a relative 1e-12 of the distances across the two tets.
  double extent = 0.0;
  for (const Vec3& x : p)
    for (const Vec3& y : q) extent = std::max(extent, norm(x - y));
  for (int i = 0; i < 4 && poly->n > 0; ++i) {
    // q's face opposite corner i, its normal turned away from that corner.
    const Vec3 &a = q[static_cast<std::size_t>((i + 1) % 4)], &b = q[static_cast<std::size_t>((i + 2) % 4)],
               &c = q[static_cast<std::size_t>((i + 3) % 4)];
    Vec3 n = cross(b - a, c - a);
    if (dot(n, q[static_cast<std::size_t>(i)] - a) > 0) n = -1.0 * n;
    clip(*poly, n, dot(n, a), 1e-12 * norm(n) * extent, *next);
    std::swap(poly, next);
  }
  return volume(*poly);
}

}  // namespace tetcut::detail
