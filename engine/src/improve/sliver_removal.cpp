#include "improve/sliver_removal.hpp"

#include "core/quality.hpp"
#include "remove/removability.hpp"

namespace tetcut::detail {

Refusal plan_sliver_removal(const TetMesh& mesh, TetId t, const Tool* reach, TissueRemoval& tissue, Plan& plan) {
  plan.start(Operator::kSliverRemoval);
  // Inside the organ it would open a cavity: only a tet with a face on the surface goes.
  if (mesh.boundary_face_count(t) == 0) return Refusal::kNotRemovable;
  const TetMesh::TetVerts c = mesh.tet(t);
  // Within the cut's reach, as every removal is (tissue_removal.hpp).
  if (reach && !tissue.within_reach(mesh, std::span<const TetId>(&t, 1))) return Refusal::kOutOfReach;
  if (!removability(mesh, t).removable()) return Refusal::kNotRemovable;
  plan.removed.push_back(t);
  plan.tissue = &tissue;
  plan.worst_before = quality(mesh, c);
  return Refusal::kNone;
}

}  // namespace tetcut::detail
