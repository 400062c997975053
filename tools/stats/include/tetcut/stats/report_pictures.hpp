// The report's pictures of the liver resection, as standalone SVG elements: the per-cut latency
// along the sweep, radius-ratio histograms before and after, and the liver's surface before and
// after (flat-shaded, depth-sorted, cut surfaces in another colour, the resected piece pulled
// away). `tetcut stats --html` inlines them; `--pictures DIR` writes them as ID.svg files.
#pragma once

#include <string>
#include <vector>

#include "tetcut/stats/paper_stats.hpp"

namespace tetcut::stats {

struct Picture {
  std::string id;       // "latency-plot", "quality-histogram", "liver-before", "liver-after"
  std::string svg;      // a complete <svg> element with that id
  std::string caption;  // one sentence for a figure caption
};

// The surfaces need the run's meshes (CauteryRun::mesh_before/after); without them only the
// plot and the histogram are made.
std::vector<Picture> resection_pictures(const ResectionStats& resection);

}  // namespace tetcut::stats
