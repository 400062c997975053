// The cautery tool as the paper models it (3.1): a ball of given diameter at the tool's tip.
#pragma once

#include "tetcut/ids.hpp"
#include "tetcut/mesh.hpp"
#include "tetcut/vec3.hpp"

namespace tetcut {

struct Ball {
  Vec3 centre;
  double radius = 0.0;
};

// Distance from p to the closed tetrahedron (a, b, c, d): 0 inside, else the distance to the
// closest point on its boundary (closest point on each face triangle, Ericson's method).
double distance_to_tet(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

// Whether the ball and the closed tetrahedron share a point. The exact closest-point test runs
// behind two cheap ones: most candidates are rejected by their bounding box, and a tet with a
// vertex in the ball is accepted at once.
bool intersects(const Ball& ball, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

// The share of the tet (a, b, c, d)'s volume that lies in the closed ball, estimated: exact (1 or
// 0) for a tet wholly inside (its four corners in the ball: it is convex) or wholly outside (it
// does not meet the ball), otherwise the midpoint rule on the tet's regular refinement into 8
// children of equal volume (Bey's red refinement: 4 corner tets and 4 about the diagonal between
// the midpoints of edges 02 and 13), i.e. the share of the 8 children's centroids in the ball.
// What a cut reports as tissue left in its tool and removed beyond it: a figure for people, not
// a decision, so a coarse estimate at a fixed small cost serves.
double share_in_ball(const Ball& ball, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);
// The same for a tet known to meet the ball (intersects() true): the test is not made again.
double share_in_ball_meeting(const Ball& ball, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

// Whether the live tet t meets the ball: intersects() on its corners. What the spatial index
// asks of the tets it cannot decide, and the refinement loop of the tets it made (its focus).
bool tet_meets_ball(const TetMesh& mesh, TetId t, const Ball& ball);

}  // namespace tetcut
