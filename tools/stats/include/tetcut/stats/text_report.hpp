// The statistics as plain text tables for a terminal: Tables 1 and 2 with the paper's figures
// and the difference beside ours, then the strategy comparison.
#pragma once

#include <string>

#include "tetcut/stats/paper_figures.hpp"
#include "tetcut/stats/paper_stats.hpp"

namespace tetcut::stats {

std::string text_report(const StatsReport& report);

// "12.3", or "-" for NaN; `decimals` after the point.
std::string fixed(double value, int decimals);
// `value` with `digits` significant digits ("0.0145", "3.2e-06"), or "-" for NaN.
std::string significant(double value, int digits);
// "+1.2" / "-0.4", or "-" when either side is NaN.
std::string difference(double ours, double paper, int decimals);
// A cell's 95 % interval, "[91.6, 93.1]" with `decimals` after the point, or "-" when it has
// nothing to estimate from; its raw counts, "4127/4466".
std::string interval_text(const CellEstimate& e, int decimals);
std::string count_text(const CellEstimate& e);
// Fisher's exact p of our rate cell against the paper's rebuilt count (fisher_exact.hpp), two
// significant digits, "*" when below 0.05; "-" when we have no trials.
std::string fisher_text(const CellEstimate& ours, const PaperCount& paper);
// Of created tets: the worst radius ratio ("0.101") and the smallest dihedral angle in degrees
// ("7.6"), each "-" when none were created.
std::string created_worst(const invariants::QualityStats& q);
std::string created_dihedral(const invariants::QualityStats& q);

}  // namespace tetcut::stats
