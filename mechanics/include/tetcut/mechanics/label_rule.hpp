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

#include <cstdint>
#include <span>

#include "tetcut/ids.hpp"
#include "tetcut/vec3.hpp"

namespace tetcut::mechanics {

inline constexpr std::uint32_t kNoLabel = 0xFFFFFFFFu;

// ((a + b) + (c + d)) / 4, in this order, so that every caller gets the same bits.
[[nodiscard]] Vec3 tet_centroid(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);
// p in the closed tet (a, b, c, d), positively oriented: exact (orientation(), predicates.hpp).
[[nodiscard]] bool tet_contains(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Vec3& p);

// The rule itself, for every consumer that keeps labels (the elastic model, TetLabels): the label
// of the created tet whose `parents` (sorted by id) a ChangeLog lists; `removed` is the log's
// removed tets (sorted), for step 2. `known(p)`: the consumer has tet p; `label_of(p)`: its
// label; `contains(p)`: p's closed rest shape contains the child's centroid. A tet the consumer
// does not know is passed over; no known parent: kNoLabel.
template <class Known, class LabelOf, class Contains>
[[nodiscard]] std::uint32_t inherited_label(std::span<const TetId> parents, std::span<const TetId> removed,
                                            Known known, LabelOf label_of, Contains contains) {
  for (TetId p : parents)  // 1: sorted by id, the lowest containing parent wins
    if (known(p) && contains(p)) return label_of(p);
  // 2: the child pokes out of its parents. Rare, so this scan of the log costs nothing in the
  // common case.
  for (TetId p : removed)
    if (known(p) && contains(p)) return label_of(p);
  for (TetId p : parents)  // 3: the centroid left the mesh
    if (known(p)) return label_of(p);
  return kNoLabel;
}

}  // namespace tetcut::mechanics
