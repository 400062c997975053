// A line plot of one series against its index: per-cut latency along a sweep.
#pragma once

#include <span>
#include <string>
#include <utility>
#include <vector>

namespace tetcut::render {

struct LinePlotOptions {
  int width = 480;  // viewBox size, pixels (clamped to 120..8192)
  int height = 300;
  std::string title;
  std::string x_label = "cut";
  std::string y_label;
  // Logarithmic y (latencies span two decades): decade ticks; values <= 0 are not drawn.
  bool log_y = false;
  std::string colour = "#3a6ea5";  // the series ("#rrggbb"; anything else gives this default)
  // Horizontal dashed lines labelled at their right end with the name and the value: {"p50",
  // 12.5} reads "p50 12.5". Values that cannot be drawn (log axis: <= 0) are left out.
  std::vector<std::pair<std::string, double>> reference_lines;
  std::string id;  // the <svg> element's id attribute, none when empty
};

// x = index (0 .. n-1), y = value. The series is drawn as <polyline class="series"> elements,
// one per run of drawable values (non-finite values, and non-positive ones on a log axis,
// break the line). The y range covers the values and the reference lines, widened to round
// ticks. The same input gives the same bytes.
std::string line_plot_svg(std::span<const double> values, const LinePlotOptions& options = {});

}  // namespace tetcut::render
