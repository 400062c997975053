// Our Tables 1 and 2 (paper 3.6), computed from a run's RemovalReport.
//
// Counting follows the paper: an operation is a distinct tet requested for removal (a tet met
// again after being left unresolved counts once). Table 2 describes the neighbour strategy
// (paper 3.5) inside the combined one (3.7): "unresolved" there means "not resolved by removing
// neighbours", which the combined strategy then resolved by its optimized refinement; the share
// the combined strategy itself left is reported apart and must be zero. A percentage or an
// average over nothing (no edge singularity met, say) is NaN: printed "-", JSON null.
#pragma once

#include <cstdint>
#include <span>

#include "tetcut/removal_report.hpp"
#include "tetcut/stats/intervals.hpp"

namespace tetcut::stats {

// Table 1 is about "removing a tetrahedron on the mesh surface" (its title): its population is the
// distinct requested tets that had a face on the surface when requested; all_operations counts
// every distinct request (interior tets and pieces of removal-time splits included) beside it.
struct Table1Row {
  std::uint64_t operations = 0;      // distinct tets requested with a face on the surface
  std::uint64_t all_operations = 0;  // distinct tets requested
  double removable_pct = 0;      // removable on their own (paper 3.3)
  double vertex_pct = 0;         // removal would make a vertex singular (cases 1 and 2)
  double edge_pct = 0;           // removal would make an edge singular (case 3)
};

struct Table2Row {
  double vertex_unresolved_pct = 0;  // vertex singularities the neighbours did not resolve
  double vertex_cardinality = 0;     // mean size of the removed set when they did
  double edge_unresolved_pct = 0;
  double edge_cardinality = 0;
  double global_unresolved_pct = 0;  // over all operations
  // Tets removed by direct and neighbour removals per operation they resolved: the paper's
  // column (its figures reconstruct so: mesh 2, 1.623 / 0.929 = 1.75, printed 1.8; mesh 4, 1.33).
  double global_cardinality = 0;
  // The same tets per selected tet they took (a set that swallows selected tets that are then
  // never requested counts each): ours, smaller, beside it.
  double global_cardinality_per_selected = 0;
  double combined_unresolved_pct = 0;  // left in place by the whole strategy: must be 0
};

Table1Row table1_row(const RemovalReport& report);
Table2Row table2_row(const RemovalReport& report);

// One cell of Tables 1 and 2 over a mesh's sweeps: the pooled estimate (the
// same figure as the row's), its 95 % interval in the same unit, and the raw counts it is made
// of: events of trials for a rate (Wilson interval, x 100), tets of sets for a mean size
// (bootstrap over the sweeps). intervals.hpp says why each.
struct CellEstimate {
  double value = 0;
  Interval ci;
  std::uint64_t count = 0, of = 0;
};

struct Table1Intervals {
  CellEstimate removable, vertex, edge;
};

struct Table2Intervals {
  CellEstimate vertex_unresolved, vertex_cardinality, edge_unresolved, edge_cardinality, global_unresolved,
      global_cardinality, global_cardinality_per_selected, combined_unresolved;
};

// From each sweep's report (one run of the mesh's scenario at one seeded offset); the values
// are those of table1_row / table2_row on the reports' sum.
Table1Intervals table1_intervals(std::span<const RemovalReport> sweeps);
Table2Intervals table2_intervals(std::span<const RemovalReport> sweeps);

// part / whole x 100, NaN when whole is 0.
double percent(std::uint64_t part, std::uint64_t whole);
// sum / count, NaN when count is 0.
double average(std::uint64_t sum, std::uint64_t count);

}  // namespace tetcut::stats
