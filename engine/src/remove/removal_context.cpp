#include "remove/removal_context.hpp"

namespace tetcut::detail {

RemovalContext::Mark RemovalContext::mark() {
  return {mesh.savepoint(), log.removed.size(), log.created.size(), log.vertices.size(), tets_created, edges_split};
}

void RemovalContext::rollback_to(const Mark& m) {
  mesh.rollback_to(m.mesh);
  log.removed.resize(m.removed);
  log.created.resize(m.created);
  log.vertices.resize(m.vertices);
  tets_created = m.tets_created;
  edges_split = m.edges_split;
}

bool RemovalContext::split(std::span<const Edge> edges, ChangeLog& split_log) {
  split_log.clear();
  const std::uint32_t allowed = budget > tets_created ? budget - tets_created : 0;
  const SplitResult r = splitter.split(mesh, edges, SplitMethod::kTemplates, nullptr, &split_log, allowed);
  if (r.refusal == SplitRefusal::kOverBudget) over_budget = true;
  if (!r.ok()) return false;
  log.removed.insert(log.removed.end(), split_log.removed.begin(), split_log.removed.end());
  log.created.insert(log.created.end(), split_log.created.begin(), split_log.created.end());
  log.vertices.insert(log.vertices.end(), split_log.vertices.begin(), split_log.vertices.end());
  tets_created += r.tets_created;
  edges_split += r.edges_split;
  return true;
}

void RemovalContext::remove_set(std::span<const TetId> set) {
  ws.mark(mesh, set);
  for (TetId u : set)
    for (int f = 0; f < 4; ++f) {
      const FaceRef n = mesh.neighbour(u, f);
      if (n.valid() && !ws.marked(n.tet)) exposed.push_back(n.tet);
    }
  log.removed.insert(log.removed.end(), set.begin(), set.end());
  mesh.remove_tets(set);
}

bool RemovalContext::with_selected_children(std::span<const TetId> set, const ChangeLog& split_log,
                                            std::vector<TetId>& out) {
  if (!selection) return false;
  out.assign(set.begin(), set.end());
  ws.mark(mesh, set);
  for (const CreatedTet& c : split_log.created)
    if (selection->contains(c.parent) && mesh.is_live(c.tet) && !ws.marked(c.tet)) out.push_back(c.tet);
  return out.size() > set.size();
}

}  // namespace tetcut::detail
