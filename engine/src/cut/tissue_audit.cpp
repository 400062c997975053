#include "cut/tissue_audit.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "tetcut/detail/local_tables.hpp"
#include "tetcut/detail/reserve_touched.hpp"

namespace tetcut::detail {

void TissueAudit::reserve(std::uint32_t tets) {
  reserve_touched(left_, 1024);
  removal_made_.reserve(tets);
}

std::optional<std::string> TissueAudit::audit(const Context& ctx, TetId t, bool meeting, CutReport& report) {
  TetMesh& mesh = ctx.mesh;
  const Tool& tool = *ctx.selection.tool();
  const TetMesh::TetVerts v = mesh.tet(t);
  const std::array<Vec3, 4> p = {mesh.position(v[0]), mesh.position(v[1]), mesh.position(v[2]), mesh.position(v[3])};
  if (!meeting && !intersects(tool, p[0], p[1], p[2], p[3])) return std::nullopt;
  if (ctx.uncuttable.contains(mesh, t)) return std::nullopt;
  // The longest edge, as norm() measures each (a square root is monotone: the root of the
  // largest square is the largest norm), so that it decides as the selection's test does.
  double longest2 = 0.0;
  for (int e = 0; e < 6; ++e) {
    const Vec3 edge = p[kEdgeVerts[e][1]] - p[kEdgeVerts[e][0]];
    longest2 = std::max(longest2, dot(edge, edge));
  }
  const double longest = std::sqrt(longest2);
  if (longest > ctx.d_ref) {
    char text[200];
    std::snprintf(text, sizeof text,
                  "the tissue rule: a tet meeting the tool would keep an edge of length %.4g, longer than D_ref = %.4g",
                  longest, ctx.d_ref);
    return std::string(text);
  }
  const double volume = std::abs(dot(p[1] - p[0], cross(p[2] - p[0], p[3] - p[0]))) / 6.0;
  report.volume_left_in_tool += volume * share_in_tool_meeting(tool, p[0], p[1], p[2], p[3]);
  if (!ctx.selection.within_d_ref(longest) || !ctx.selection.centroid_in_tool(p)) return std::nullopt;
  if (!ctx.removal.requested(t) && !removal_made_.contains(t))
    return std::string("the tissue rule: a tet inside the tool that the selection takes was never requested");
  left_.push_back(t);
  return std::nullopt;
}

std::optional<std::string> TissueAudit::run(const Context& ctx, CutReport& report) {
  left_.clear();
  removal_made_.clear();
  for (const TetMesh::TetBirth& birth : ctx.removal_births) removal_made_.insert(birth.tet);
  // T_hit is what the locator found meeting the tool (its test is exact); no id is reused
  // inside a transaction, so a live one was never replaced.
  for (TetId t : ctx.hit)
    if (ctx.mesh.is_live(t))
      if (auto why = audit(ctx, t, true, report)) return why;
  for (const TetMesh::TetBirth& birth : ctx.mesh.tets_made_since(ctx.start))
    if (ctx.mesh.is_live(birth.tet))
      if (auto why = audit(ctx, birth.tet, false, report)) return why;
  std::sort(left_.begin(), left_.end());
  report.left_in_tool = static_cast<std::uint32_t>(left_.size());
  return std::nullopt;
}

}  // namespace tetcut::detail
