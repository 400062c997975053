// The volume two tetrahedra share: what the improvement pass's mesh rule weighs (improve/
// improver.hpp: the volume below theta outside the tool does not grow over a transaction), how
// much of a tet that was there before the transaction a made tet now covers.
//
// The engine's own, apart from the checker's (invariants/src/tet_intersection.cpp: the checker
// owes the engine nothing), and allocation-free, since it runs inside a cut: the intersection of
// two tets is one convex polyhedron, four plane clips of the first by the second's faces
// (Sutherland and Hodgman, "Reentrant polygon clipping", CACM 17(1), 1974, applied face by face,
// the cut closed by a cap polygon), held in fixed arrays: each clip adds at most one face (the
// cap) and one vertex per face it crosses, so four clips of a tet stay within 8 faces of at most
// 8 vertices. Hand-written rather than CGAL's corefinement for the same reason as the checker's:
// a few hundred floating-point operations per pair, where the rule only compares volumes to a
// relative tolerance.
#pragma once

#include <array>

#include "tetcut/vec3.hpp"

namespace tetcut::detail {

// The volume of the intersection of tets p and q (each given by its four corners, either
// orientation); 0 when they share no interior.
double tet_intersection_volume(const std::array<Vec3, 4>& p, const std::array<Vec3, 4>& q);

}  // namespace tetcut::detail
