#include "tetcut/stats/removal_tables.hpp"

#include <limits>

namespace tetcut::stats {

double percent(std::uint64_t part, std::uint64_t whole) {
  if (whole == 0) return std::numeric_limits<double>::quiet_NaN();
  return 100.0 * static_cast<double>(part) / static_cast<double>(whole);
}

double average(std::uint64_t sum, std::uint64_t count) {
  if (count == 0) return std::numeric_limits<double>::quiet_NaN();
  return static_cast<double>(sum) / static_cast<double>(count);
}

Table1Row table1_row(const RemovalReport& r) {
  Table1Row row;
  row.operations = r.surface_requested;
  row.all_operations = r.requested;
  row.removable_pct = percent(r.surface_direct, r.surface_requested);
  row.vertex_pct = percent(r.surface_vertex_singularities, r.surface_requested);
  row.edge_pct = percent(r.surface_edge_singularities, r.surface_requested);
  return row;
}

Table2Row table2_row(const RemovalReport& r) {
  Table2Row row;
  row.vertex_unresolved_pct = percent(r.vertex_singularities - r.vertex_resolved_by_neighbours, r.vertex_singularities);
  row.vertex_cardinality = average(r.vertex_neighbour_set_tets, r.vertex_resolved_by_neighbours);
  row.edge_unresolved_pct = percent(r.edge_singularities - r.edge_resolved_by_neighbours, r.edge_singularities);
  row.edge_cardinality = average(r.edge_neighbour_set_tets, r.edge_resolved_by_neighbours);
  const std::uint64_t by_neighbours_or_direct = r.direct + r.resolved_by_neighbours;
  row.global_unresolved_pct = percent(r.requested - by_neighbours_or_direct, r.requested);
  row.global_cardinality = average(r.direct + r.neighbour_set_tets, by_neighbours_or_direct);
  row.global_cardinality_per_selected = average(r.direct + r.neighbour_set_tets, r.selected_in_sets);
  row.combined_unresolved_pct = percent(r.unresolved, r.requested);
  return row;
}

}  // namespace tetcut::stats
