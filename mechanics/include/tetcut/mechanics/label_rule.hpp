// Which label a tet a cut creates takes: its parent's, and for a child with several parents (a
// flip's, a smoothing's: change_log.hpp) the label of the lowest-id parent whose closed rest
// shape contains the child's centroid, by the exact orientation predicate. A child lies inside
// the union of its parents, so some parent contains its centroid; the rule is a function of the
// geometry alone, which is what lets a differential test recompute it without the log (the
// parent that contains the centroid is also the pre-cut tet that contains it).
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
// of the created tet whose `parents` (sorted by id) a ChangeLog lists. `known(p)`: the consumer
// has parent p; `label_of(p)`: its label; `contains(p)`: p's closed rest shape contains the
// child's centroid (asked only when there are several parents). A parent the consumer does not
// know is passed over; none known: kNoLabel; none containing: the first known one's.
template <class Known, class LabelOf, class Contains>
[[nodiscard]] std::uint32_t inherited_label(std::span<const TetId> parents, Known known, LabelOf label_of,
                                            Contains contains) {
  if (parents.size() == 1) return known(parents[0]) ? label_of(parents[0]) : kNoLabel;
  std::uint32_t fallback = kNoLabel;
  for (TetId p : parents) {  // sorted by id: the lowest containing parent wins
    if (!known(p)) continue;
    if (contains(p)) return label_of(p);
    if (fallback == kNoLabel) fallback = label_of(p);
  }
  return fallback;
}

}  // namespace tetcut::mechanics
