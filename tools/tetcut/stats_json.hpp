// The JSON form of `tetcut stats`: keys table1 and table2 (one row per mesh, each with the
// paper's figures and the difference), strategies (one row per strategy), resection.
#pragma once

#include "json_output.hpp"
#include "tetcut/stats/paper_stats.hpp"

namespace tetcut::cli {

Json stats_json(const stats::StatsReport& report);

}  // namespace tetcut::cli
