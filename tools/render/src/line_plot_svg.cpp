#include "tetcut/render/line_plot_svg.hpp"

#include <algorithm>
#include <cmath>

#include "chart_axes.hpp"
#include "tetcut/render/colour.hpp"
#include "tetcut/render/svg_writer.hpp"

namespace tetcut::render {
namespace {

constexpr const char* kReferenceColour = "#888888";

int clamp_size(int s) { return std::clamp(s, 120, 8192); }

}  // namespace

std::string line_plot_svg(std::span<const double> values, const LinePlotOptions& options) {
  const int width = clamp_size(options.width), height = clamp_size(options.height);
  const std::string colour = parse_colour(options.colour) ? options.colour : LinePlotOptions{}.colour;
  const auto drawable = [&](double v) { return std::isfinite(v) && (!options.log_y || v > 0.0); };

  double lo = HUGE_VAL, hi = -HUGE_VAL;
  for (double v : values)
    if (drawable(v)) lo = std::min(lo, v), hi = std::max(hi, v);
  for (const auto& [label, v] : options.reference_lines)
    if (drawable(v)) lo = std::min(lo, v), hi = std::max(hi, v);
  if (lo > hi) lo = hi = options.log_y ? 1.0 : 0.0;  // nothing drawable: an empty, sane frame
  // A linear axis of non-negative data starts at zero, so heights compare honestly.
  const detail::Axis y_axis = options.log_y ? detail::log_axis(lo, hi) : detail::linear_axis(std::min(lo, 0.0), hi);
  const detail::Axis x_axis = detail::linear_axis(0.0, values.size() > 1 ? static_cast<double>(values.size() - 1) : 1.0, 6, false);
  const detail::PlotArea area = detail::plot_area(width, height, !options.title.empty());

  SvgWriter svg(width, height, options.id, options.title);
  detail::draw_frame(svg, area, y_axis, width, options.title, options.x_label, options.y_label);
  for (double t : x_axis.ticks)
    if (t == std::floor(t)) detail::x_tick(svg, area, area.x(x_axis, t), format_significant(t, 6));  // cut numbers are whole

  // The series, broken where a value cannot be drawn.
  bool open = false;
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (!drawable(values[i])) {
      if (open) svg.raw("\"/>");
      open = false;
      continue;
    }
    if (!open) {
      svg.raw("<polyline class=\"series\" fill=\"none\" stroke=\"" + colour + "\" stroke-width=\"1.2\" points=\"");
      open = true;
    } else {
      svg.raw(" ");
    }
    svg.number(area.x(x_axis, static_cast<double>(i)));
    svg.raw(",");
    svg.number(area.y(y_axis, values[i]));
  }
  if (open) svg.raw("\"/>");

  for (const auto& [label, v] : options.reference_lines) {
    if (!drawable(v)) continue;
    const double y = area.y(y_axis, v);
    svg.line(area.left, y, area.right, y, kReferenceColour, 1.0, true);
    // A white halo (stroke painted under the fill) keeps the label legible over the series.
    svg.text(area.right - 2.0, y - 3.0, label + " " + format_significant(v, 3), TextAnchor::kEnd, 11,
             "class=\"reference\" fill=\"#555555\" stroke=\"#ffffff\" stroke-width=\"3\" paint-order=\"stroke\"");
  }
  return svg.finish();
}

}  // namespace tetcut::render
