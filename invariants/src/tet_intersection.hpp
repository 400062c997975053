// The volume two tetrahedra share, for I7's mesh rule (no_degradation.hpp): how much of a removed
// tet's volume a created tet now covers.
//
// Hand-written rather than CGAL's corefinement (Polygon_mesh_processing::corefine_and_compute_
// intersection, or Nef polyhedra): the intersection of two tets is one convex polyhedron, four
// plane clips of the first by the second's faces (Sutherland and Hodgman, "Reentrant polygon
// clipping", CACM 17(1), 1974, applied face by face, the cut closed by a cap polygon), a few
// hundred floating-point operations where an exact corefinement builds two surface meshes for
// every pair the rule measures. The rule compares volumes to a relative tolerance, so the clip's
// rounding (around 1e-15 of the tets' volume) is well within it.
#pragma once

#include <array>

#include "tetcut/vec3.hpp"

namespace tetcut::invariants::detail {

// The volume of the intersection of tets p and q (each given by its four corners, either
// orientation); 0 when they share no interior.
double tet_intersection_volume(const std::array<Vec3, 4>& p, const std::array<Vec3, 4>& q);

}  // namespace tetcut::invariants::detail
