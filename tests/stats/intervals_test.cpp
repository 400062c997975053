// The intervals of Tables 1 and 2: the Wilson score interval's properties
// (its values are compared with scipy's on every cell by stats.report_renders_in_chromium), and
// the seeded bootstrap's determinism and range.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "tetcut/stats/intervals.hpp"
#include "tetcut/stats/removal_tables.hpp"

namespace tetcut::stats {
namespace {

TEST(Intervals, WilsonContainsTheRateAndStaysInTheUnitInterval) {
  for (std::uint64_t n : {1u, 2u, 7u, 25u, 4466u})
    for (std::uint64_t k = 0; k <= n; k += (n > 30 ? 97 : 1)) {
      const Interval w = wilson_interval(k, n);
      const double p = static_cast<double>(k) / static_cast<double>(n);
      EXPECT_LE(0.0, w.lo);
      EXPECT_LE(w.lo, p);
      EXPECT_LE(p, w.hi);
      EXPECT_LE(w.hi, 1.0);
      // Symmetric: k of n and n - k of n mirror each other.
      const Interval m = wilson_interval(n - k, n);
      EXPECT_NEAR(w.lo, 1.0 - m.hi, 1e-12);
      EXPECT_NEAR(w.hi, 1.0 - m.lo, 1e-12);
    }
}

TEST(Intervals, WilsonAtNoEventsIsNotAPoint) {
  // The Wald interval of 0 of 20 is [0, 0]; the Wilson interval still allows a few %.
  const Interval w = wilson_interval(0, 20);
  EXPECT_EQ(w.lo, 0.0);
  EXPECT_GT(w.hi, 0.1);
  EXPECT_LT(w.hi, 0.2);
  EXPECT_TRUE(std::isnan(wilson_interval(0, 0).lo));
}

TEST(Intervals, WilsonNarrowsWithMoreTrials) {
  const Interval few = wilson_interval(5, 10), many = wilson_interval(500, 1000);
  EXPECT_LT(many.hi - many.lo, (few.hi - few.lo) / 5);
}

TEST(Intervals, TheBootstrapIsSeededAndStaysBetweenTheClustersRatios) {
  const std::vector<std::uint64_t> num{3, 0, 7, 2, 5, 9, 4, 0, 6, 3}, den{1, 0, 2, 1, 2, 3, 1, 0, 2, 1};
  const Interval a = bootstrap_ratio_interval(num, den), b = bootstrap_ratio_interval(num, den);
  EXPECT_EQ(a.lo, b.lo);  // bit for bit
  EXPECT_EQ(a.hi, b.hi);
  EXPECT_LT(a.lo, a.hi);
  EXPECT_GE(a.lo, 2.0);  // the smallest ratio of a cluster with sets (2 / 1)
  EXPECT_LE(a.hi, 4.0);  // the largest (4 / 1)
  const double pooled = 39.0 / 13.0;
  EXPECT_LE(a.lo, pooled);
  EXPECT_GE(a.hi, pooled);
  // Another seed moves the bounds a little, not the range.
  const Interval c = bootstrap_ratio_interval(num, den, {.resamples = 2000, .seed = 7});
  EXPECT_NEAR(c.lo, a.lo, 0.2);
  EXPECT_NEAR(c.hi, a.hi, 0.2);
}

TEST(Intervals, TheBootstrapOfOneClusterIsItsRatioAndOfNoSetsNaN) {
  const std::uint64_t num[1] = {7}, den[1] = {2};
  const Interval one = bootstrap_ratio_interval(num, den);
  EXPECT_EQ(one.lo, 3.5);
  EXPECT_EQ(one.hi, 3.5);
  const std::uint64_t none[3] = {0, 0, 0};
  EXPECT_TRUE(std::isnan(bootstrap_ratio_interval(none, none).lo));
}

TEST(Intervals, TableCellsPoolTheSweepsCounts) {
  RemovalReport a, b;
  a.surface_requested = 10;
  a.surface_direct = 9;
  a.surface_edge_singularities = 1;
  a.edge_singularities = 1;
  b.surface_requested = 30;
  b.surface_direct = 27;
  b.surface_vertex_singularities = 3;
  b.vertex_singularities = 3;
  b.vertex_resolved_by_neighbours = 2;
  b.vertex_neighbour_set_tets = 7;
  const RemovalReport sweeps[2] = {a, b};
  const Table1Intervals t1 = table1_intervals(sweeps);
  EXPECT_EQ(t1.removable.count, 36u);
  EXPECT_EQ(t1.removable.of, 40u);
  EXPECT_DOUBLE_EQ(t1.removable.value, 90.0);
  EXPECT_DOUBLE_EQ(t1.edge.ci.lo, 100.0 * wilson_interval(1, 40).lo);
  const Table2Intervals t2 = table2_intervals(sweeps);
  EXPECT_EQ(t2.edge_unresolved.count, 1u);  // the edge singularity, not resolved by neighbours
  EXPECT_EQ(t2.edge_unresolved.of, 1u);
  EXPECT_TRUE(std::isnan(t2.edge_cardinality.value));
  EXPECT_DOUBLE_EQ(t2.vertex_cardinality.value, 3.5);
  // Only sweep b has vertex sets: every resample that has any gives its ratio.
  EXPECT_DOUBLE_EQ(t2.vertex_cardinality.ci.lo, 3.5);
  EXPECT_DOUBLE_EQ(t2.vertex_cardinality.ci.hi, 3.5);
}

}  // namespace
}  // namespace tetcut::stats
