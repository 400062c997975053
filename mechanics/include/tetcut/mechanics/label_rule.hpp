// Which label a tet a cut creates takes, by three steps on its centroid (tet_centroid) and the
// closed rest shapes before the cut (tet_contains, the exact orientation predicate):
//   1. the lowest-id parent that contains the centroid (change_log.hpp: a split's child has one
//      parent, a flip's or a smoothing's several);
//   2. else the lowest-id tet the cut removed that contains it;
//   3. else the lowest-id parent's.
// A child of a split or a flip lies inside the union of its parents, so step 1 decides; so does
// a smoothing's away from the surface. Steps 2 and 3 exist because smoothing may move a vertex
// off the surface (improve/smoothing.hpp: within 1e-9 of its planes, and on the cut's own surface
// within 5 % of an edge): a child may then poke into a tet the tool removed (step 2), or out of
// the mesh altogether (step 3, where the geometry names no tet and the parents decide).
// Steps 1 and 2 are a function of the geometry alone, the lowest-id removed tet that contains the
// centroid (they differ only when the centroid lies on a face a parent shares with a lower-id
// removed tet), which is what lets a differential test recompute them without the log.
#pragma once

#include "tetcut/vec3.hpp"

namespace tetcut::mechanics {

// ((a + b) + (c + d)) / 4, in this order, so that every caller gets the same bits.
[[nodiscard]] Vec3 tet_centroid(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);
// p in the closed tet (a, b, c, d), positively oriented: exact (orientation(), predicates.hpp).
[[nodiscard]] bool tet_contains(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Vec3& p);

}  // namespace tetcut::mechanics
