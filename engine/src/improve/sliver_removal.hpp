// Sliver removal: a tet at the cut's surface that nothing lifts goes with the tissue, the least
// tissue there is to remove (the last resort of CGAL Tetrahedral_remeshing's sliver removal is
// likewise to take the sliver out of the complex). Only where removing it alone keeps the mesh a
// manifold (paper 3.3: removable on its own) and lying within the cut's reach: the tool's ball grown by
// D_ref, where the cut's surface is.
//
// Planned on the const mesh as any operation (Operator::kSliverRemoval): the tet removed,
// nothing added; applied through the transaction's removal path (remove/tissue_removal.hpp), the
// one way tissue leaves the mesh.
#pragma once

#include "core/tool.hpp"
#include "improve/operation.hpp"
#include "remove/tissue_removal.hpp"
#include "tetcut/mesh.hpp"

namespace tetcut::detail {

// `reach`: the cut's (none for a removal request, where any surface tet may go). `tissue`: the
// removal path apply() goes through.
[[nodiscard]] Refusal plan_sliver_removal(const TetMesh& mesh, TetId t, const Tool* reach, TissueRemoval& tissue,
                                          Plan& plan);

}  // namespace tetcut::detail
