#include "cut/tissue_rule_veto.hpp"

#include <algorithm>
#include <cmath>

#include "tetcut/detail/local_tables.hpp"

namespace tetcut::detail {

Refusal TissueRuleVeto::operator()(const TetMesh& mesh, const Plan& plan) const {
  const Tool* tool = selection_.tool();
  if (!tool || plan.added.empty()) return Refusal::kNone;
  const bool uncuttable = uncuttable_.any_of(mesh_, plan.removed);
  for (const TetMesh::TetVerts& tet : plan.added) {
    const std::array<Vec3, 4> p = plan.corners(mesh, tet);
    if (!intersects(*tool, p[0], p[1], p[2], p[3])) continue;
    double longest2 = 0.0;
    for (int e = 0; e < 6; ++e) {
      const Vec3 edge = p[kEdgeVerts[e][1]] - p[kEdgeVerts[e][0]];
      longest2 = std::max(longest2, dot(edge, edge));
    }
    // As the audit and the selection measure (the root of the largest square is the largest norm).
    const double longest = std::sqrt(longest2);
    if (uncuttable) continue;
    if (longest > d_ref_) return Refusal::kVetoed;
    if (selection_.within_d_ref(longest) && selection_.centroid_in_tool(p)) return Refusal::kVetoed;
  }
  return Refusal::kNone;
}

}  // namespace tetcut::detail
