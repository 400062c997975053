#include "improve/operation.hpp"

#include <cassert>

#include "tetcut/detail/reserve_touched.hpp"

namespace tetcut::detail {

std::string_view to_string(Operator op) {
  switch (op) {
    case Operator::kEdgeRemoval: return "edge removal";
    case Operator::kFaceRemoval: return "face removal";
    case Operator::kCollapse: return "collapse";
    case Operator::kSmoothing: return "smoothing";
    case Operator::kInsertion: return "insertion";
    case Operator::kSliverRemoval: return "sliver removal";
  }
  return "?";
}

std::string_view to_string(Refusal refusal) {
  switch (refusal) {
    case Refusal::kNone: return "none";
    case Refusal::kNotFlippable: return "not flippable";
    case Refusal::kNotAnEdge: return "not an edge";
    case Refusal::kExistingSimplex: return "a new edge or face exists already";
    case Refusal::kLinkCondition: return "link condition";
    case Refusal::kInvertedChild: return "inverted child";
    case Refusal::kNotBetter: return "not better";
    case Refusal::kSpreadsBadVolume: return "would spread tets below theta over more volume";
    case Refusal::kSurfaceConstraint: return "surface constraint";
    case Refusal::kNotMadeByCut: return "a vertex the cut did not make";
    case Refusal::kUncuttable: return "uncuttable";
    case Refusal::kOutOfReach: return "out of the cut's reach";
    case Refusal::kNotRemovable: return "not removable";
    case Refusal::kVetoed: return "vetoed by the caller";
  }
  return "?";
}

void Plan::reserve(std::size_t tets) {
  reserve_touched(removed, tets);
  reserve_touched(added, tets);
}

void Plan::start(Operator operation) {
  op = operation;
  removed.clear();
  added.clear();
  placed = kNoVert;
  worst_before = worst_after = 1.0;
  splitter = nullptr;
  tissue = nullptr;
}

std::string_view Plan::name() const {
  if (op == Operator::kEdgeRemoval) {
    if (removed.size() == 2 && added.size() == 2) return "2-2 flip";
    if (removed.size() == 3 && added.size() == 2) return "3-2 flip";
    if (removed.size() == 4 && added.size() == 4) return "4-4 flip";
  }
  if (op == Operator::kFaceRemoval && removed.size() == 2) return "2-3 flip";
  return to_string(op);
}

void Plan::apply(TetMesh& mesh, std::vector<TetId>& created) const {
  switch (op) {
    case Operator::kEdgeRemoval:
    case Operator::kFaceRemoval:
    case Operator::kCollapse:
      // Every added tet gets every removed one as parent: they fill the same polytope together.
      mesh.replace_tets(removed, added, &created);
      break;
    case Operator::kSmoothing:
      // The star is made anew around the vertex's new position (the journal records where it
      // moved from).
      mesh.move_vertex(placed, placed_at, &created);
      break;
    case Operator::kInsertion: {
      // The splitter halves the tets around the edge at its midpoint, the point the plan placed,
      // and records the new vertex on its edge. The plan checked every half positive by the
      // exact predicate the splitter applies, so the split goes through.
      [[maybe_unused]] const SplitResult split =
          splitter->split(mesh, std::span<const Edge>(&split_edge, 1), SplitMethod::kTemplates, &created);
      assert(split.ok() && "a planned insertion's halves are positive");
      break;
    }
    case Operator::kSliverRemoval:
      tissue->remove(mesh, removed);
      break;
  }
}

}  // namespace tetcut::detail
