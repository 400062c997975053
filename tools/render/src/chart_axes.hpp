// Axes shared by the line plot and the histogram (private to the library): a value range with
// round-numbered ticks, linear or logarithmic, and the frame that draws them.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "tetcut/render/svg_writer.hpp"

namespace tetcut::render::detail {

struct Axis {
  double lo = 0.0, hi = 1.0;  // the values at the two ends (log axes: both > 0)
  bool log = false;
  std::vector<double> ticks;  // increasing, inside [lo, hi]

  // 0 at lo, 1 at hi.
  [[nodiscard]] double fraction(double value) const;
};

// Ticks at 1, 2 or 5 x 10^k, about `target` of them. With `widen` the range grows to the outer
// ticks (a value axis); without, it stays [lo, hi] and keeps the ticks inside (an index axis
// should end at the last index). A range of zero width is widened around its value; `lo` > `hi`
// is swapped.
Axis linear_axis(double lo, double hi, int target = 5, bool widen = true);

// Range widened to whole decades (both ends > 0, the caller drops non-positive values); ticks
// at every decade, and at 2 and 5 times each when the range spans at most two decades.
Axis log_axis(double lo, double hi);

// The rectangle inside which data is drawn, in viewBox pixels.
struct PlotArea {
  double left, top, right, bottom;
  [[nodiscard]] double x(const Axis& axis, double value) const { return left + axis.fraction(value) * (right - left); }
  [[nodiscard]] double y(const Axis& axis, double value) const { return bottom - axis.fraction(value) * (bottom - top); }
};

// Margins for tick labels and titles around a width x height picture.
// `top_rows`: lines of legend above the plot.
PlotArea plot_area(int width, int height, bool has_title, int top_rows = 0);

// Title, frame lines, y ticks with labels and light grid lines, the axis titles. X ticks are
// drawn by the caller (positions differ: a value axis or bin edges) with x_tick().
void draw_frame(SvgWriter& svg, const PlotArea& area, const Axis& y_axis, int width, std::string_view title,
                std::string_view x_label, std::string_view y_label);
void x_tick(SvgWriter& svg, const PlotArea& area, double x, std::string_view label);

}  // namespace tetcut::render::detail
