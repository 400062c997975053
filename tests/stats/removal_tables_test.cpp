// Tables 1 and 2 computed from a RemovalReport, as the paper defines them (section 3.6).
#include <gtest/gtest.h>

#include <cmath>

#include "tetcut/stats/removal_tables.hpp"
#include "tetcut/stats/text_report.hpp"

namespace tetcut::stats {
namespace {

RemovalReport sample() {
  RemovalReport r;
  r.requested = 200;
  r.direct = 150;
  r.vertex_singularities = 40;
  r.edge_singularities = 10;
  r.vertex_resolved_by_neighbours = 36;  // 4 left to the refinement
  r.vertex_neighbour_set_tets = 108;     // 3 tets per set
  r.edge_resolved_by_neighbours = 5;
  r.edge_neighbour_set_tets = 20;
  r.resolved_by_neighbours = 41;
  r.neighbour_set_tets = 128;
  r.resolved_by_refinement = 9;
  r.removed = 200;
  r.selected_in_sets = 150 + 41 + 48;    // the 41 sets swallowed 48 selected tets besides their own
  // Of the 200, 160 had a face on the surface when requested (Table 1's population).
  r.surface_requested = 160;
  r.surface_direct = 120;
  r.surface_vertex_singularities = 32;
  r.surface_edge_singularities = 8;
  return r;
}

TEST(Table1, GivesTheSharesOfDirectRemovalsAndOfVertexAndEdgeSingularities) {
  // Over the tets with a face on the surface, as the paper's title says; all requests beside.
  const Table1Row row = table1_row(sample());
  EXPECT_EQ(row.operations, 160u);
  EXPECT_EQ(row.all_operations, 200u);
  EXPECT_DOUBLE_EQ(row.removable_pct, 75.0);
  EXPECT_DOUBLE_EQ(row.vertex_pct, 20.0);
  EXPECT_DOUBLE_EQ(row.edge_pct, 5.0);
}

TEST(Table2, GivesWhatTheNeighboursLeftAndTheMeanSizeOfTheirSets) {
  const Table2Row row = table2_row(sample());
  EXPECT_DOUBLE_EQ(row.vertex_unresolved_pct, 10.0);
  EXPECT_DOUBLE_EQ(row.vertex_cardinality, 3.0);
  EXPECT_DOUBLE_EQ(row.edge_unresolved_pct, 50.0);
  EXPECT_DOUBLE_EQ(row.edge_cardinality, 4.0);
  // Globally: 9 of 200 needed more than neighbours; 150 direct (1 each) and 128 in 41 sets.
  EXPECT_DOUBLE_EQ(row.global_unresolved_pct, 4.5);
  // Per operation resolved (the paper's column: its mesh 2 reconstructs as 1.623 / 0.929).
  EXPECT_DOUBLE_EQ(row.global_cardinality, (150.0 + 128.0) / 191.0);
  // Per selected tet taken (ours, beside it): the same tets over 239 selected ones.
  EXPECT_DOUBLE_EQ(row.global_cardinality_per_selected, (150.0 + 128.0) / 239.0);
  EXPECT_DOUBLE_EQ(row.combined_unresolved_pct, 0.0);
}

TEST(Table2, ReportsWhatTheWholeStrategyLeftInPlace) {
  RemovalReport r = sample();
  r.unresolved = 2;
  EXPECT_DOUBLE_EQ(table2_row(r).combined_unresolved_pct, 1.0);
}

TEST(Tables, AShareOfNothingIsNotANumberAndPrintsAsADash) {
  RemovalReport r;
  r.requested = 10;
  r.direct = 10;
  r.selected_in_sets = 10;
  const Table2Row row = table2_row(r);
  EXPECT_TRUE(std::isnan(row.vertex_unresolved_pct));
  EXPECT_TRUE(std::isnan(row.edge_cardinality));
  EXPECT_DOUBLE_EQ(row.global_cardinality, 1.0);
  EXPECT_TRUE(std::isnan(table1_row(RemovalReport{}).removable_pct));
  EXPECT_EQ(fixed(row.vertex_unresolved_pct, 1), "-");
  EXPECT_EQ(difference(row.vertex_unresolved_pct, 8.3, 1), "-");
  EXPECT_EQ(difference(10.0, 8.25, 2), "+1.75");
  EXPECT_EQ(difference(1.0, 1.5, 1), "-0.5");
}

}  // namespace
}  // namespace tetcut::stats
