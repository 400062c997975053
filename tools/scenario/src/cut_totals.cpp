#include "tetcut/scenario/cut_totals.hpp"

#include <algorithm>

namespace tetcut::scenario {

CutTotals cut_totals(const std::vector<CutRecord>& cuts) {
  CutTotals t;
  for (const CutRecord& c : cuts) {
    const CutReport& r = c.report;
    if (!r.ok) {
      ++t.refused;
      ++t.refusals[static_cast<std::size_t>(r.refusal)];
      continue;
    }
    t.removed += r.tets_removed + r.tets_removed_by_improvement;
    t.created += r.tets_created;
    t.unresolved += r.unresolved;
    t.worst_created = std::min(t.worst_created, r.min_radius_ratio);
    t.left_in_tool += r.left_in_tool;
    t.cuts_leaving_tissue += r.left_in_tool > 0 ? 1 : 0;
    t.removed_beyond_tool += r.tets_removed_beyond_tool;
    t.removed_beyond_reach += r.tets_removed_beyond_reach;
    t.removed_by_improvement += r.tets_removed_by_improvement;
    t.flips += r.improvement_flips;
    t.collapses += r.improvement_collapses;
    t.moves += r.improvement_moves;
    t.insertions += r.improvement_insertions;
    t.vertices_moved += r.vertices_moved;
    t.mesh_rule_retries += r.mesh_rule_retries;
    t.volume_removed += r.volume_removed;
    t.volume_removed_beyond_tool += r.volume_removed_beyond_tool;
    t.fragments += r.fragments;
    t.cuts_detaching += r.fragments > 0 ? 1 : 0;
    t.debris_pieces += r.debris_pieces_removed;
    t.debris_tets += r.debris_tets_removed;
    t.debris_volume += r.debris_volume_removed;
    t.fragment_searches_bounded += r.fragment_search_bounded ? 1 : 0;
    if (r.tets_hit > 0) {
      t.volume_left.push_back(r.volume_left_in_tool);
      t.volume_beyond.push_back(r.volume_removed_beyond_tool);
    }
  }
  return t;
}

}  // namespace tetcut::scenario
