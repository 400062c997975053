// Fisher's exact test of our rate cells against the paper's (paper 3.6, Tables 1 and 2).
//
// Why a test of two proportions and not "the paper's figure outside our interval": the paper's
// figures rest on few events (2 edge singularities of 130 operations on its cylinder, 5 of 14
// unresolved on its locally refined liver), so a figure of the paper's can differ from ours by
// its own sampling error alone; an interval around ours only counts our own. Fisher's test
// counts both. Why hand-written: it is a sum of hypergeometric probabilities, a few lines over
// std::lgamma, and the stats tool then carries its p in `tetcut stats --json` without a Python
// dependency; tests/stats/fisher_exact_test.cpp checks it against scipy.stats.fisher_exact.
//
// The paper prints percentages, not counts. Its counts are rebuilt from them (paper_figures.hpp,
// kPaperTable1Counts): where its one-decimal figures admit two counts, both are kept and the
// larger p is reported (the least evidence of a difference).
#pragma once

#include <cstdint>

#include "tetcut/stats/paper_figures.hpp"
#include "tetcut/stats/removal_tables.hpp"

namespace tetcut::stats {

// Two-sided p of Fisher's exact test on the 2 x 2 table [k1, n1 - k1; k2, n2 - k2], as
// scipy.stats.fisher_exact(..., alternative="two-sided") computes it: the sum of the
// hypergeometric probabilities (margins fixed) of every table no more probable than the
// observed one (with scipy's relative tolerance 1e-7). NaN when n1 or n2 is 0; k <= n required.
double fisher_exact_p(std::uint64_t k1, std::uint64_t n1, std::uint64_t k2, std::uint64_t n2);

// Our cell (its pooled events `count` of `of`) against the paper's rebuilt count: the largest p
// over the counts the paper's printed figures admit. NaN when we have no trials.
double fisher_vs_paper(const CellEstimate& ours, const PaperCount& paper);

}  // namespace tetcut::stats
