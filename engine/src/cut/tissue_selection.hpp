// Paper 3.3's selection, and how it follows the tets a cut makes. T_removal is the refined
// region's tets inside the tool (centroid in the closed ball) with no edge longer than D_ref.
// Selection is decided once, on the refined region: a piece a later split (3.4, 3.7, the
// fallback) makes of selected tissue is selected tissue, and joins T_removal when it passes the
// same test; a piece of a kept tet stays kept wherever its centroid falls (else every split at
// the ball's edge would select finer and finer pieces of kept tissue, and 3.4, which splits around
// every singularity, would run away). Such a piece left in the tool is requested once by the
// removal stage (removal_loop.hpp) and, if it stays, counted as left.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "core/tool.hpp"
#include "core/uncuttable_tets.hpp"
#include "remove/selection.hpp"
#include "tetcut/cut.hpp"
#include "tetcut/detail/stamped_property.hpp"
#include "tetcut/mesh.hpp"

namespace tetcut::detail {

class TissueSelection {
 public:
  // D_ref is read from `params` when asked (the Cutter's own, which set_params() updates).
  explicit TissueSelection(const CutParams& params) : params_(params) {}
  void reserve(std::uint32_t tets);

  // A new transaction: the cut's tool, or none (a removal request); nothing selected.
  void begin(const Tool* tool);
  // Paper 3.3: inside the tool (centroid in the closed ball) and no edge longer than D_ref.
  // False without a tool.
  [[nodiscard]] bool selectable(const TetMesh& mesh, TetId t) const;
  // Its two halves, for a caller that has read the tet's corners and measured its longest edge
  // (the same test).
  [[nodiscard]] bool centroid_in_tool(const std::array<Vec3, 4>& corners) const;
  [[nodiscard]] bool within_d_ref(double longest_edge) const { return !(longest_edge > params_.d_ref()); }
  // Selects the region's selectable tets (region: live, distinct, the refinement's children
  // included), but not the uncuttable ones, which it counts.
  void select(TetMesh& mesh, std::span<const TetId> region, const UncuttableTets& uncuttable,
              std::uint32_t& uncuttable_in_tool);
  // A removal request's one tet, selected whatever the tool.
  void select_request(TetId t);
  // What a step made since `point` (the journal's record): pieces of selected tissue become
  // tissue, and those inside the tool join T_removal.
  void follow(const TetMesh& mesh, const TetMesh::Savepoint& point);
  // A tet the transaction made, live, not tissue, selectable and cuttable: a piece of a kept tet
  // in the tool.
  [[nodiscard]] bool piece_in_tool(TetMesh& mesh, TetId t, const UncuttableTets& uncuttable) const;

  [[nodiscard]] const Selection& selected() const { return selected_; }
  // T_removal in the order it was selected; it grows as follow() adds pieces.
  [[nodiscard]] const std::vector<TetId>& removal() const { return removal_; }
  [[nodiscard]] const Tool* tool() const { return tool_ ? &*tool_ : nullptr; }

 private:
  const CutParams& params_;
  std::optional<Tool> tool_;
  // Selected; selected tissue (a selected tet or a piece of one, inside the tool or not).
  Selection selected_;
  StampedSet<TetId> tissue_;
  std::vector<TetId> removal_;
};

}  // namespace tetcut::detail
