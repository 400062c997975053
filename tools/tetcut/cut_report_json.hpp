// The JSON report of a sequence of cuts, shared by `tetcut cut` and `tetcut run`: a `cuts`
// array (one record per cut, its time in microseconds and its counts) and a `summary` with
// cuts, p50_us, p90_us, p99_us, max_us, tets_removed, tets_created, unresolved,
// min_radius_ratio and hash.
#pragma once

#include <string>
#include <vector>

#include "tetcut/scenario/scenario.hpp"

namespace tetcut::cli {

// Nearest-rank percentile (q in [0, 1]) of the cuts' total times; 0 when there are none.
double percentile_us(const std::vector<scenario::CutRecord>& cuts, double q);

std::string cut_report_json(const std::vector<scenario::CutRecord>& cuts, const std::string& hash, bool valid);

}  // namespace tetcut::cli
