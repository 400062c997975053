#include "tetcut/stats/removal_tables.hpp"

#include <functional>
#include <limits>
#include <vector>

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

namespace {

RemovalReport pooled(std::span<const RemovalReport> sweeps) {
  RemovalReport sum;
  for (const RemovalReport& r : sweeps) sum += r;
  return sum;
}

// A rate: events of trials, pooled over the sweeps, with its Wilson interval, in %.
CellEstimate rate(std::uint64_t events, std::uint64_t trials) {
  const Interval w = wilson_interval(events, trials);
  return {percent(events, trials), {100.0 * w.lo, 100.0 * w.hi}, events, trials};
}

// A mean size: tets of sets per sweep, the pooled ratio with its bootstrap interval.
using Count = std::function<std::uint64_t(const RemovalReport&)>;
CellEstimate mean_size(std::span<const RemovalReport> sweeps, const Count& tets, const Count& sets) {
  std::vector<std::uint64_t> num, den;
  for (const RemovalReport& r : sweeps) {
    num.push_back(tets(r));
    den.push_back(sets(r));
  }
  CellEstimate e;
  for (std::size_t i = 0; i < num.size(); ++i) {
    e.count += num[i];
    e.of += den[i];
  }
  e.value = average(e.count, e.of);
  e.ci = bootstrap_ratio_interval(num, den);
  return e;
}

}  // namespace

Table1Intervals table1_intervals(std::span<const RemovalReport> sweeps) {
  const RemovalReport r = pooled(sweeps);
  return {rate(r.surface_direct, r.surface_requested), rate(r.surface_vertex_singularities, r.surface_requested),
          rate(r.surface_edge_singularities, r.surface_requested)};
}

Table2Intervals table2_intervals(std::span<const RemovalReport> sweeps) {
  const RemovalReport r = pooled(sweeps);
  Table2Intervals t;
  t.vertex_unresolved = rate(r.vertex_singularities - r.vertex_resolved_by_neighbours, r.vertex_singularities);
  t.vertex_cardinality = mean_size(sweeps, [](const RemovalReport& s) { return s.vertex_neighbour_set_tets; },
                                   [](const RemovalReport& s) { return s.vertex_resolved_by_neighbours; });
  t.edge_unresolved = rate(r.edge_singularities - r.edge_resolved_by_neighbours, r.edge_singularities);
  t.edge_cardinality = mean_size(sweeps, [](const RemovalReport& s) { return s.edge_neighbour_set_tets; },
                                 [](const RemovalReport& s) { return s.edge_resolved_by_neighbours; });
  const std::uint64_t by_neighbours_or_direct = r.direct + r.resolved_by_neighbours;
  t.global_unresolved = rate(r.requested - by_neighbours_or_direct, r.requested);
  auto removed_by_sets = [](const RemovalReport& s) { return s.direct + s.neighbour_set_tets; };
  t.global_cardinality =
      mean_size(sweeps, removed_by_sets, [](const RemovalReport& s) { return s.direct + s.resolved_by_neighbours; });
  t.global_cardinality_per_selected =
      mean_size(sweeps, removed_by_sets, [](const RemovalReport& s) { return s.selected_in_sets; });
  t.combined_unresolved = rate(r.unresolved, r.requested);
  return t;
}

}  // namespace tetcut::stats
