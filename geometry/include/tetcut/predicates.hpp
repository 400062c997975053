// Exact geometric predicates. We use Shewchuk's adaptive-precision orient3d as exported by
// TetGen's libtet (exact sign for every double input; also well behaved under valgrind).
#pragma once

#include "tetcut/vec3.hpp"

namespace tetcut {

// Sign of det(b - a, c - a, d - a): +1 when (a, b, c, d) is a positively oriented tet (tetcut's
// convention), -1 when inverted, 0 when flat. Exact.
int orientation(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

// det(b - a, c - a, d - a) / 6 in plain floating point: the signed volume, for measurements only.
double signed_volume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

}  // namespace tetcut
