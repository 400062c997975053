// The statistics as one self-contained HTML page (no script, no network, no external file):
// Tables 1 and 2 beside the paper's, the strategy comparison, the per-cut latency along the
// liver resection as an SVG plot, radius-ratio histograms before and after, and pictures of the
// liver's surface before and after the resection (our own SVG projection, tools/render), cut
// surfaces in another colour.
//
// The pictures' <svg> elements have the ids "latency-plot", "quality-histogram",
// "liver-before" and "liver-after" (tests look for them).
#pragma once

#include <string>

#include "tetcut/stats/paper_stats.hpp"

namespace tetcut::stats {

// `command` is printed as the way to reproduce the page.
std::string html_report(const StatsReport& report, const std::string& command);

}  // namespace tetcut::stats
