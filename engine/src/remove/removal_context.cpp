#include "remove/removal_context.hpp"

namespace tetcut::detail {

bool RemovalContext::split(std::span<const Edge> edges, SplitPoint point) {
  // Every tet the request made so far counts, children split again included, as they did when
  // the splits were planned.
  const std::uint32_t made = static_cast<std::uint32_t>(mesh.tets_made_since(start).size());
  const std::uint32_t allowed = budget > made ? budget - made : 0;
  const SplitResult r = splitter.split(mesh, edges, SplitMethod::kTemplates, nullptr, allowed, point);
  if (r.refusal == SplitRefusal::kOverBudget) over_budget = true;
  return r.ok();
}

void RemovalContext::remove_set(std::span<const TetId> set) {
  ws.mark(mesh, set);
  for (TetId u : set)
    for (int f = 0; f < 4; ++f) {
      const FaceRef n = mesh.neighbour(u, f);
      if (n.valid() && !ws.marked(n.tet)) exposed.push_back(n.tet);
    }
  tissue->remove(mesh, set);
}

bool RemovalContext::with_selected_children(std::span<const TetId> set, std::span<const TetMesh::TetBirth> children,
                                            std::vector<TetId>& out) {
  if (!selection) return false;
  out.assign(set.begin(), set.end());
  ws.mark(mesh, set);
  for (const TetMesh::TetBirth& c : children)
    if (selection->contains(mesh.parents(c)[0]) && mesh.is_live(c.tet) && !ws.marked(c.tet)) out.push_back(c.tet);
  return out.size() > set.size();
}

}  // namespace tetcut::detail
