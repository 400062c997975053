// The one way tissue leaves the mesh. Every tet a transaction removes as tissue goes through
// remove_tissue(): a request's set, whichever stage found it (removal_context.hpp), the whole mesh
// when the tool holds all of it, and a sliver the improvement pass lets go with the tissue
// (improve/improver.hpp). Splits and flips replace tets without removing tissue; only this
// removes. So the one place that knows what a cut took is here: how many tets, their volume, and
// how much of it lies beyond the tool and beyond the cut's reach (the tool's ball grown by D_ref,
// within which the cut may take more than the tool holds: paper 3.5's neighbours, the pieces of
// 3.4 and 3.7, the fallback's).
//
// What a cut takes beyond its tool stays within its reach: a set with a tet reaching beyond it is
// refused like one holding an uncuttable tet (within_reach(), asked by RemovalContext::may_remove
// and the improvement pass's sliver removal), and the request goes on to its next stage. The one
// exception is the fallback, proved to succeed with the pieces it builds (removal_context.hpp):
// what it takes beyond the reach is counted. The
// caller has decided that the set may go (plan, then apply): removable (set_removal.hpp, or
// paper 3.3's test for one tet), within reach and holding no uncuttable tet.
#pragma once

#include <cstdint>
#include <span>

#include "core/tool.hpp"
#include "tetcut/mesh.hpp"

namespace tetcut::detail {

// What one transaction removed as tissue.
struct RemovedTissue {
  std::uint32_t tets = 0;
  double volume = 0.0;
  // Of those, the tets whose centroid lies outside the tool's closed ball, the estimated volume
  // outside it (volume_in_tool()), and the tets with a corner beyond the cut's reach. A removal
  // request outside a cut has no tool: everything it takes is beyond, and the reach is not asked.
  std::uint32_t tets_beyond_tool = 0;
  double volume_beyond_tool = 0.0;
  std::uint32_t tets_beyond_reach = 0;
};

class TissueRemoval {
 public:
  // A new transaction: the cut's tool and reach (none: a removal request), nothing removed yet.
  void begin(const Tool* tool, double reach_radius);
  // The cut's reach (the tool grown to reach_radius), none for a removal request.
  [[nodiscard]] const Tool* reach() const { return has_tool_ ? &reach_ : nullptr; }
  // Whether every tet of `set` lies within the cut's reach (all its corners: it is convex).
  // Always true for a removal request, which has no tool.
  [[nodiscard]] bool within_reach(const TetMesh& mesh, std::span<const TetId> set) const;
  // Removes `set` (live, distinct) and tallies it.
  void remove(TetMesh& mesh, std::span<const TetId> set);
  [[nodiscard]] const RemovedTissue& removed() const { return removed_; }

 private:
  bool has_tool_ = false;
  Tool tool_{}, reach_{};
  RemovedTissue removed_;
};

}  // namespace tetcut::detail
