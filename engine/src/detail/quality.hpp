// Shape quality of a tetrahedron (design invariant I7).
#pragma once

#include "tetcut/vec3.hpp"

namespace tetcut {

// Radius ratio 3 * inradius / circumradius: 1 for the regular tet, 0 for a flat one, negative
// values are never returned (inverted tets measure by their absolute volume).
double radius_ratio(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

// Smallest of the six dihedral angles, in degrees (70.53 for the regular tet).
double min_dihedral_angle_deg(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

}  // namespace tetcut
