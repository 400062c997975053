// Which label a tet a cut creates takes: its parent's, and for a child with several parents (a
// flip's, a smoothing's: change_log.hpp) the label of the lowest-id parent whose closed rest
// shape contains the child's centroid, by the exact orientation predicate. A child lies inside
// the union of its parents, so some parent contains its centroid; the rule is a function of the
// geometry alone, which is what lets a differential test recompute it without the log (the
// parent that contains the centroid is also the pre-cut tet that contains it).
#pragma once

#include "tetcut/vec3.hpp"

namespace tetcut::mechanics {

// ((a + b) + (c + d)) / 4, in this order, so that every caller gets the same bits.
[[nodiscard]] Vec3 tet_centroid(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);
// p in the closed tet (a, b, c, d), positively oriented: exact (orientation(), predicates.hpp).
[[nodiscard]] bool tet_contains(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Vec3& p);

}  // namespace tetcut::mechanics
