// The cautery tool. The paper models it as a ball of given diameter at the tool's tip (3.1); as
// the tip moves between two haptic samples it sweeps a capsule, every point within `radius` of
// the segment a-b, and a cut by the capsule removes what the stroke passed through whatever the
// sampling (Cutter::cut_segment). A ball is the capsule with a == b: every test below computes
// for it, operation for operation, what it computed for the ball alone, so ball cuts keep their
// bits (the pinned hashes).
#pragma once

#include <cmath>

#include "tetcut/ids.hpp"
#include "tetcut/mesh.hpp"
#include "tetcut/vec3.hpp"

namespace tetcut {

struct Tool {
  Vec3 a;  // the segment's ends: the tip at two samples of a stroke (the same point for a ball)
  Vec3 b;
  double radius = 0.0;

  // Constructors, not an aggregate: `{centre, radius}` is a ball, as it was before capsules,
  // never a capsule whose second end is brace-elided from the radius.
  Tool() = default;
  Tool(const Vec3& centre, double r) : a(centre), b(centre), radius(r) {}
  Tool(const Vec3& from, const Vec3& to, double r) : a(from), b(to), radius(r) {}
  static Tool ball(const Vec3& centre, double radius) { return Tool{centre, radius}; }
  static Tool capsule(const Vec3& a, const Vec3& b, double radius) { return Tool{a, b, radius}; }
  [[nodiscard]] bool is_ball() const { return a == b; }
  // The same axis, the radius grown: the cut's reach (the tool grown by D_ref).
  [[nodiscard]] Tool grown(double by) const { return Tool{a, b, radius + by}; }
};

// The point of the segment a-b closest to p (a itself for a ball).
Vec3 closest_on_segment(const Tool& tool, const Vec3& p);
inline Vec3 closest_on_axis(const Tool& tool, const Vec3& p) { return tool.is_ball() ? tool.a : closest_on_segment(tool, p); }
// |p - closest_on_axis(p)|^2 and its square root: for a ball, |p - centre|^2 and |p - centre|.
// Inline: the selection, the reach and the pass ask it of every tet and vertex they judge.
inline double squared_distance_to_axis(const Tool& tool, const Vec3& p) {
  const Vec3 d = p - closest_on_axis(tool, p);
  return dot(d, d);
}
inline double distance_to_axis(const Tool& tool, const Vec3& p) { return std::sqrt(squared_distance_to_axis(tool, p)); }

// Distance from p to the closed tetrahedron (a, b, c, d): 0 inside, else the distance to the
// closest point on its boundary (closest point on each face triangle, Ericson's method).
double distance_to_tet(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

// Whether the tool and the closed tetrahedron share a point. The exact closest-point test runs
// behind two cheap ones: most candidates are rejected by their bounding box, and a tet with a
// vertex in the tool is accepted at once.
bool intersects(const Tool& tool, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

// The share of the tet (a, b, c, d)'s volume that lies in the closed tool, estimated: exact (1 or
// 0) for a tet wholly inside (its four corners in the tool: both are convex) or wholly outside
// (it does not meet the tool), otherwise the midpoint rule on the tet's regular refinement into
// 8 children of equal volume (Bey's red refinement: 4 corner tets and 4 about the diagonal
// between the midpoints of edges 02 and 13), i.e. the share of the 8 children's centroids in the
// tool. What a cut reports as tissue left in its tool and removed beyond it: a figure for people,
// not a decision, so a coarse estimate at a fixed small cost serves.
double share_in_tool(const Tool& tool, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);
// The same for a tet known to meet the tool (intersects() true): the test is not made again.
double share_in_tool_meeting(const Tool& tool, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

// Whether the live tet t meets the tool: intersects() on its corners. What the locator asks of
// the tets its walk reaches, and the refinement loop of the tets it made (its focus).
bool tet_meets_tool(const TetMesh& mesh, TetId t, const Tool& tool);

}  // namespace tetcut
