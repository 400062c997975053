#include "core/tool.hpp"

#include <algorithm>
#include <cmath>

#include "tetcut/detail/local_tables.hpp"
#include "tetcut/predicates.hpp"

namespace tetcut {
namespace {

// Closest point to p on triangle (a, b, c), by Voronoi regions (Ericson, Real-Time Collision
// Detection, 5.1.5).
Vec3 closest_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Vec3 bp = p - b;
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + (d1 / (d1 - d3)) * ab;
  const Vec3 cp = p - c;
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + (d2 / (d2 - d6)) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
  const double denom = 1.0 / (va + vb + vc);
  return a + (vb * denom) * ab + (vc * denom) * ac;
}

// Squared distance between the segments p1-q1 and p2-q2, by their closest points (Ericson,
// 5.1.9); a segment of zero length is its point.
double squared_distance_between_segments(const Vec3& p1, const Vec3& q1, const Vec3& p2, const Vec3& q2) {
  const Vec3 d1 = q1 - p1, d2 = q2 - p2, r = p1 - p2;
  const double a = dot(d1, d1), e = dot(d2, d2), f = dot(d2, r);
  double s = 0.0, t = 0.0;
  if (a <= 0.0 && e <= 0.0) return dot(r, r);
  if (a <= 0.0) {
    t = std::clamp(f / e, 0.0, 1.0);
  } else {
    const double c = dot(d1, r);
    if (e <= 0.0) {
      s = std::clamp(-c / a, 0.0, 1.0);
    } else {
      const double b = dot(d1, d2), denom = a * e - b * b;
      s = denom > 0.0 ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
      t = (b * s + f) / e;
      if (t < 0.0) {
        t = 0.0;
        s = std::clamp(-c / a, 0.0, 1.0);
      } else if (t > 1.0) {
        t = 1.0;
        s = std::clamp((b - c) / a, 0.0, 1.0);
      }
    }
  }
  const Vec3 gap = (p1 + s * d1) - (p2 + t * d2);
  return dot(gap, gap);
}

// Squared distance between the segment a-b and the triangle (p, q, r), for a segment that does
// not cross the triangle: the closest pair then has an end of the segment or a point of one of
// the triangle's edges.
double squared_distance_segment_triangle(const Vec3& a, const Vec3& b, const Vec3& p, const Vec3& q, const Vec3& r) {
  const Vec3 ca = closest_on_triangle(a, p, q, r) - a, cb = closest_on_triangle(b, p, q, r) - b;
  double best = std::min(dot(ca, ca), dot(cb, cb));
  best = std::min(best, squared_distance_between_segments(a, b, p, q));
  best = std::min(best, squared_distance_between_segments(a, b, q, r));
  return std::min(best, squared_distance_between_segments(a, b, r, p));
}

// intersects() for a capsule (a != b), past the bounding box and the corners: the segment
// clipped to the tet's four half-spaces (Cyrus-Beck) meets it, or one of the faces whose plane
// has a point of the segment in front lies within the radius of the segment (the closest point
// of the tet to the segment is on such a face). Plain floating point, as for the ball.
bool capsule_meets_tet(const Tool& tool, const Vec3 (&p)[4], double r2) {
  const double orient = dot(p[1] - p[0], cross(p[2] - p[0], p[3] - p[0])) < 0.0 ? -1.0 : 1.0;
  double enter = 0.0, leave = 1.0;
  bool in_front[4];
  for (int i = 0; i < 4; ++i) {
    const Vec3& f0 = p[kFaceVerts[i][0]];
    const Vec3 n = cross(p[kFaceVerts[i][1]] - f0, p[kFaceVerts[i][2]] - f0);
    const double sa = orient * dot(n, tool.a - f0), sb = orient * dot(n, tool.b - f0);
    in_front[i] = sa > 0.0 || sb > 0.0;
    if (sa > 0.0 && sb > 0.0) {
      const double nearest = std::min(sa, sb);
      if (nearest * nearest > r2 * dot(n, n)) return false;  // the whole segment beyond r of this plane
      leave = -1.0;                                           // and beyond the plane: it misses the tet
    } else if (sa > 0.0) {
      enter = std::max(enter, sa / (sa - sb));
    } else if (sb > 0.0) {
      leave = std::min(leave, sa / (sa - sb));
    }
  }
  if (enter <= leave) return true;
  for (int i = 0; i < 4; ++i)
    if (in_front[i] &&
        squared_distance_segment_triangle(tool.a, tool.b, p[kFaceVerts[i][0]], p[kFaceVerts[i][1]], p[kFaceVerts[i][2]]) <= r2)
      return true;
  return false;
}

}  // namespace

Vec3 closest_on_segment(const Tool& tool, const Vec3& p) {
  const Vec3 axis = tool.b - tool.a;
  const double t = dot(p - tool.a, axis) / dot(axis, axis);
  if (t <= 0.0) return tool.a;
  if (t >= 1.0) return tool.b;
  return tool.a + t * axis;
}

double distance_to_tet(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  // Inside (or on) a positively oriented tet: p is on the inner side of all four faces. The
  // exact predicate makes the answer for points on a face exact too.
  const int s0 = orientation(p, b, c, d), s1 = orientation(a, p, c, d), s2 = orientation(a, b, p, d),
            s3 = orientation(a, b, c, p);
  if (s0 >= 0 && s1 >= 0 && s2 >= 0 && s3 >= 0) return 0.0;
  const Vec3 q[4] = {closest_on_triangle(p, b, c, d), closest_on_triangle(p, a, c, d), closest_on_triangle(p, a, b, d),
                     closest_on_triangle(p, a, b, c)};
  double best = norm(q[0] - p);
  for (int i = 1; i < 4; ++i) best = std::min(best, norm(q[i] - p));
  return best;
}

namespace {

// intersects() for a capsule: the gap between the tet's box and the axis's box, axis by axis;
// then the corners; then the segment against the tet. Apart, so that the ball's test stays as
// small as it was.
[[gnu::noinline]] bool capsule_intersects(const Tool& tool, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const double r2 = tool.radius * tool.radius;
  // The gap between the tet's box and the axis's box [axis_lo, axis_hi], axis by axis.
  auto box_gap = [&](double end0, double end1, double p0, double p1, double p2, double p3) {
    const double lo = std::min(std::min(p0, p1), std::min(p2, p3)), hi = std::max(std::max(p0, p1), std::max(p2, p3));
    const double axis_lo = std::min(end0, end1), axis_hi = std::max(end0, end1);
    return axis_hi < lo ? lo - axis_hi : axis_lo > hi ? axis_lo - hi : 0.0;
  };
  const double gx = box_gap(tool.a.x, tool.b.x, a.x, b.x, c.x, d.x), gy = box_gap(tool.a.y, tool.b.y, a.y, b.y, c.y, d.y),
               gz = box_gap(tool.a.z, tool.b.z, a.z, b.z, c.z, d.z);
  if (gx * gx + gy * gy + gz * gz > r2) return false;
  for (const Vec3* q : {&a, &b, &c, &d})
    if (squared_distance_to_axis(tool, *q) <= r2) return true;
  const Vec3 p[4] = {a, b, c, d};
  return capsule_meets_tet(tool, p, r2);
}

}  // namespace

bool intersects(const Tool& tool, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  if (!tool.is_ball()) return capsule_intersects(tool, a, b, c, d);
  // A ball: the test it always had, operation for operation.
  const double r2 = tool.radius * tool.radius;
  const Vec3& centre = tool.a;
  auto axis_gap = [&](double q, double p0, double p1, double p2, double p3) {
    const double lo = std::min(std::min(p0, p1), std::min(p2, p3)), hi = std::max(std::max(p0, p1), std::max(p2, p3));
    return q < lo ? lo - q : q > hi ? q - hi : 0.0;
  };
  const double gx = axis_gap(centre.x, a.x, b.x, c.x, d.x), gy = axis_gap(centre.y, a.y, b.y, c.y, d.y),
               gz = axis_gap(centre.z, a.z, b.z, c.z, d.z);
  if (gx * gx + gy * gy + gz * gz > r2) return false;
  for (const Vec3* q : {&a, &b, &c, &d}) {
    const Vec3 delta = *q - centre;
    if (dot(delta, delta) <= r2) return true;
  }
  // A point (the locator's "which tets hold p"): exactness decides points on a face.
  if (tool.radius <= 0.0) return distance_to_tet(centre, a, b, c, d) <= 0.0;
  // Face by face (face i opposite vertex i, outward normal n_i for a positively oriented tet):
  // the ball misses the tet when its centre lies more than r beyond one face's plane, meets it
  // when the centre is behind every plane, and otherwise the nearest point is on one of the
  // faces the centre is in front of. Plain floating point, not the exact predicate: a ball that
  // grazes a tet within rounding may go either way, deterministically, and the point case above
  // keeps its exact answer. This is the common case of every query (most candidates near the
  // ball's surface), about a tenth of the cost of distance_to_tet().
  // (A negatively oriented tet, which the mesh never holds, has its normals flipped.)
  // The corners are copied only here, past the early answers that most candidates get.
  const Vec3 p[4] = {a, b, c, d};
  const double orient = dot(b - a, cross(c - a, d - a)) < 0.0 ? -1.0 : 1.0;
  bool in_front[4];
  bool inside = true;
  for (int i = 0; i < 4; ++i) {
    const Vec3& f0 = p[kFaceVerts[i][0]];
    const Vec3 n = cross(p[kFaceVerts[i][1]] - f0, p[kFaceVerts[i][2]] - f0);
    const double s = orient * dot(n, centre - f0);
    in_front[i] = s > 0.0;
    if (in_front[i]) {
      inside = false;
      if (s * s > r2 * dot(n, n)) return false;
    }
  }
  if (inside) return true;
  for (int i = 0; i < 4; ++i) {
    if (!in_front[i]) continue;
    const Vec3 q = closest_on_triangle(centre, p[kFaceVerts[i][0]], p[kFaceVerts[i][1]], p[kFaceVerts[i][2]]);
    const Vec3 delta = q - centre;
    if (dot(delta, delta) <= r2) return true;
  }
  return false;
}

namespace {

double share_in_tool(const Tool& tool, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, bool meeting) {
  // Corners relative to the axis's first end (a ball's centre): a point is in a ball when its
  // square norm is within r^2, in a capsule when its square distance to the axis is.
  const Vec3 q[4] = {a - tool.a, b - tool.a, c - tool.a, d - tool.a};
  const double r2 = tool.radius * tool.radius;
  const Vec3 axis = tool.b - tool.a;
  const double axis2 = dot(axis, axis);
  auto inside = [&](const Vec3& p) {
    if (!(axis2 > 0.0)) return dot(p, p) <= r2;
    const double t = std::clamp(dot(p, axis) / axis2, 0.0, 1.0);
    const Vec3 off = p - t * axis;
    return dot(off, off) <= r2;
  };
  if (inside(q[0]) && inside(q[1]) && inside(q[2]) && inside(q[3])) return 1.0;
  if (!meeting && !intersects(tool, a, b, c, d)) return 0.0;
  // The children's centroids, with S the sum of the corners: a corner child's is S/8 + v_i/2
  // (5/8 at its corner, 1/8 at the others); the octahedron's four about the 02-13 diagonal are
  // S/4 +- (v1 - v3)/8 and S/4 +- (v2 - v0)/8 (3/8 at one of the other four edges' vertices, 1/8
  // at the one opposite, 1/4 at the rest).
  const Vec3 sum = q[0] + q[1] + q[2] + q[3];
  const Vec3 eighth = 0.125 * sum, quarter = 0.25 * sum;
  const Vec3 d13 = 0.125 * (q[1] - q[3]), d20 = 0.125 * (q[2] - q[0]);
  int in = 0;
  for (const Vec3& v : q) in += inside(eighth + 0.5 * v) ? 1 : 0;
  in += inside(quarter + d13) ? 1 : 0;
  in += inside(quarter - d13) ? 1 : 0;
  in += inside(quarter + d20) ? 1 : 0;
  in += inside(quarter - d20) ? 1 : 0;
  return in / 8.0;
}

}  // namespace

double share_in_tool(const Tool& tool, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return share_in_tool(tool, a, b, c, d, false);
}

double share_in_tool_meeting(const Tool& tool, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return share_in_tool(tool, a, b, c, d, true);
}

bool tet_meets_tool(const TetMesh& mesh, TetId t, const Tool& tool) {
  const auto v = mesh.tet(t);
  return intersects(tool, mesh.position(v[0]), mesh.position(v[1]), mesh.position(v[2]), mesh.position(v[3]));
}

}  // namespace tetcut
