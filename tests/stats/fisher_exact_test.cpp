// Fisher's exact test of our rates against the paper's (fisher_exact.hpp), and the paper's
// counts rebuilt from its percentages (paper_figures.hpp).
#include <gtest/gtest.h>

#include <cmath>

#include "tetcut/stats/fisher_exact.hpp"
#include "tetcut/stats/paper_figures.hpp"

namespace tetcut::stats {
namespace {

// The expected values are scipy 1.10.1's, computed once:
//   /usr/bin/python3 -c "from scipy.stats import fisher_exact as f; print(f([[k1, n1-k1], [k2, n2-k2]])[1])"
struct Known {
  std::uint64_t k1, n1, k2, n2;
  double p;
};
constexpr Known kScipy[] = {
    {113, 220, 5, 14, 0.28366354883582945},      // liver-local edge unresolved
    {120, 210, 9, 26, 0.036664304852825305},     // liver-refined edge unresolved
    {1, 2, 1, 2, 1.0},
    {3, 4, 1, 4, 0.48571428571428565},
    {0, 7, 16, 265, 1.0},
    {2, 130, 16, 265, 0.06863931262462569},
    {2656, 38407, 62, 460, 7.527733567316726e-07},
    {47, 302, 53, 3239, 2.830858251281942e-25},
    {0, 20, 5, 10, 0.0017683465959328025},
    {10, 10, 0, 10, 1.082508822446903e-05},
    {1, 1, 0, 1, 1.0},
};

TEST(FisherExact, MatchesScipyOnKnownTables) {
  for (const Known& c : kScipy) {
    SCOPED_TRACE(testing::Message() << c.k1 << "/" << c.n1 << " against " << c.k2 << "/" << c.n2);
    EXPECT_NEAR(fisher_exact_p(c.k1, c.n1, c.k2, c.n2), c.p, 1e-9 * c.p + 1e-15);
  }
}

TEST(FisherExact, IsSymmetricInItsTwoRowsAndInEventsAgainstNonEvents) {
  for (const Known& c : kScipy) {
    const double p = fisher_exact_p(c.k1, c.n1, c.k2, c.n2);
    EXPECT_NEAR(fisher_exact_p(c.k2, c.n2, c.k1, c.n1), p, 1e-9 * p + 1e-15);
    EXPECT_NEAR(fisher_exact_p(c.n1 - c.k1, c.n1, c.n2 - c.k2, c.n2), p, 1e-9 * p + 1e-15);
  }
}

TEST(FisherExact, IsNaNWithoutTrials) {
  EXPECT_TRUE(std::isnan(fisher_exact_p(0, 0, 3, 10)));
  EXPECT_TRUE(std::isnan(fisher_vs_paper(CellEstimate{}, exactly(3, 10))));
}

TEST(FisherExact, AgainstThePaperTakesTheLargestPOverItsAdmittedCounts) {
  CellEstimate ours;
  ours.count = 30;
  ours.of = 100;
  const double p20 = fisher_exact_p(30, 100, 20, 100), p21 = fisher_exact_p(30, 100, 21, 100);
  ASSERT_LT(p20, p21);
  EXPECT_EQ(fisher_vs_paper(ours, PaperCount{20, 21, 100, 100}), p21);
  EXPECT_EQ(fisher_vs_paper(ours, exactly(20, 100)), p20);
}

// Every rebuilt count reproduces the printed figure within 0.1 point (the paper's rounding is not
// uniform: paper_figures.hpp), whichever of its admitted values is taken. Returns how many
// admitted counts it compared.
int expect_reproduces(const PaperCount& c, double printed_pct) {
  int compared = 0;
  for (int k = c.k_lo; k <= c.k_hi; ++k)
    for (int n = c.n_lo; n <= c.n_hi; ++n, ++compared) EXPECT_NEAR(100.0 * k / n, printed_pct, 0.1) << k << "/" << n;
  return compared;
}

TEST(PaperCounts, ReproduceThePrintedPercentages) {
  for (std::size_t m = 0; m < 5; ++m) {
    SCOPED_TRACE(testing::Message() << "paper mesh " << m + 1);
    const PaperTable1Row& p1 = kPaperTable1[m];
    const PaperTable2Row& p2 = kPaperTable2[m];
    const PaperTable1Counts& c1 = kPaperTable1Counts[m];
    const PaperTable2Counts& c2 = kPaperTable2Counts[m];
    const int compared = expect_reproduces(c1.removable, p1.removable_pct) + expect_reproduces(c1.vertex, p1.vertex_pct) +
                         expect_reproduces(c1.edge, p1.edge_pct) +
                         expect_reproduces(c2.vertex_unresolved, p2.vertex_unresolved_pct) +
                         expect_reproduces(c2.edge_unresolved, p2.edge_unresolved_pct) +
                         expect_reproduces(c2.global_unresolved, p2.global_unresolved_pct);
    EXPECT_GE(compared, 6);  // each of the six figures has at least one admitted count
  }
}

TEST(PaperCounts, AddUpAcrossTheTables) {
  for (std::size_t m = 0; m < 5; ++m) {
    SCOPED_TRACE(testing::Message() << "paper mesh " << m + 1);
    const PaperTable1Counts& c1 = kPaperTable1Counts[m];
    const PaperTable2Counts& c2 = kPaperTable2Counts[m];
    const int ops = kPaperTable1[m].operations;
    // Table 1's three rates are of the operations, and some admitted counts add up to them.
    for (const PaperCount* c : {&c1.removable, &c1.vertex, &c1.edge}) {
      EXPECT_EQ(c->n_lo, ops);
      EXPECT_EQ(c->n_hi, ops);
    }
    EXPECT_LE(c1.removable.k_lo + c1.vertex.k_lo + c1.edge.k_lo, ops);
    EXPECT_GE(c1.removable.k_hi + c1.vertex.k_hi + c1.edge.k_hi, ops);
    // Table 2's singularities are Table 1's, and its global unresolved is their sum.
    EXPECT_EQ(c2.vertex_unresolved.n_lo, c1.vertex.k_lo);
    EXPECT_EQ(c2.vertex_unresolved.n_hi, c1.vertex.k_hi);
    EXPECT_EQ(c2.edge_unresolved.n_lo, c1.edge.k_lo);
    EXPECT_EQ(c2.edge_unresolved.n_hi, c1.edge.k_hi);
    EXPECT_EQ(c2.global_unresolved.k_lo, c2.vertex_unresolved.k_lo + c2.edge_unresolved.k_lo);
    EXPECT_EQ(c2.global_unresolved.n_lo, ops);
  }
}

}  // namespace
}  // namespace tetcut::stats
