#include "tetcut/removal_report.hpp"

namespace tetcut {

const char* to_string(EdgeCandidateVerdict verdict) {
  switch (verdict) {
    case EdgeCandidateVerdict::kRemovable: return "removable";
    case EdgeCandidateVerdict::kSkipped: return "skipped";
    case EdgeCandidateVerdict::kTooLarge: return "too large";
    case EdgeCandidateVerdict::kVertexAtEnd: return "vertex at an end of e";
    case EdgeCandidateVerdict::kVertexOfT: return "vertex of T off e";
    case EdgeCandidateVerdict::kVertexOfSide: return "vertex of the side";
    case EdgeCandidateVerdict::kEdgeAtEnd: return "edge through an end of e";
    case EdgeCandidateVerdict::kEdgeElsewhere: return "edge elsewhere";
  }
  return "?";
}

std::uint64_t EdgeSearchTally::total() const {
  std::uint64_t n = 0;
  for (std::uint64_t c : counts) n += c;
  return n;
}

double RemovalReport::mean_cardinality() const {
  const std::uint64_t n = direct + resolved_by_neighbours;
  if (n == 0) return 0.0;
  return static_cast<double>(direct + neighbour_set_tets) / static_cast<double>(n);
}

double RemovalReport::cardinality_per_selected() const {
  if (selected_in_sets == 0) return 0.0;
  return static_cast<double>(direct + neighbour_set_tets) / static_cast<double>(selected_in_sets);
}

RemovalReport& RemovalReport::operator+=(const RemovalReport& o) {
  requested += o.requested;
  repeated_requests += o.repeated_requests;
  removed += o.removed;
  unresolved += o.unresolved;
  stopped_by_budget += o.stopped_by_budget;
  direct += o.direct;
  vertex_singularities += o.vertex_singularities;
  edge_singularities += o.edge_singularities;
  resolved_by_neighbours += o.resolved_by_neighbours;
  vertex_resolved_by_neighbours += o.vertex_resolved_by_neighbours;
  edge_resolved_by_neighbours += o.edge_resolved_by_neighbours;
  resolved_by_refinement += o.resolved_by_refinement;
  resolved_by_optimized_refinement += o.resolved_by_optimized_refinement;
  resolved_by_fallback += o.resolved_by_fallback;
  neighbour_set_tets += o.neighbour_set_tets;
  vertex_neighbour_set_tets += o.vertex_neighbour_set_tets;
  edge_neighbour_set_tets += o.edge_neighbour_set_tets;
  selected_in_sets += o.selected_in_sets;
  tets_removed += o.tets_removed;
  tets_created += o.tets_created;
  edges_split += o.edges_split;
  attempts_undone += o.attempts_undone;
  fallback_refused += o.fallback_refused;
  surface_requested += o.surface_requested;
  surface_direct += o.surface_direct;
  surface_vertex_singularities += o.surface_vertex_singularities;
  surface_edge_singularities += o.surface_edge_singularities;
  for (std::size_t i = 0; i < edge_search.counts.size(); ++i) edge_search.counts[i] += o.edge_search.counts[i];
  return *this;
}

}  // namespace tetcut
