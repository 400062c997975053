// The checker's own shape measures of a tet (invariant I7), written from their definitions,
// not shared with the engine's quality.cpp (tests/invariants compares the two on random tets).
#pragma once

#include "tetcut/vec3.hpp"

namespace tetcut::invariants::detail {

// 3 r / R: inradius r from V = r A / 3 (A the total face area), circumradius R the distance
// from a to the circumcentre, solved in closed form. 1 for the regular tet, 0 for a flat one,
// never above 1 (Euler's R >= 3r; rounding can only overshoot). An inverted tet measures as its
// mirror image.
double tet_radius_ratio(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

// The smallest of the six dihedral angles, in degrees: at edge (p, q) with r and s off it, the
// angle between the half-planes (p, q, r) and (p, q, s), measured between their normals
// (q - p) x (r - p) and (q - p) x (s - p) with atan2 (accurate near 0 and 180 degrees). 0 when
// a face is degenerate; 70.53 for the regular tet.
double tet_min_dihedral_deg(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

}  // namespace tetcut::invariants::detail
