#include "tetcut/render/histogram_svg.hpp"

#include <algorithm>
#include <cmath>

#include "chart_axes.hpp"
#include "tetcut/render/colour.hpp"
#include "tetcut/render/svg_writer.hpp"

namespace tetcut::render {
namespace {

// Distinguishable on screen and in grey print: blue, orange, green, purple.
constexpr const char* kPalette[] = {"#3a6ea5", "#e08a2c", "#4f9a52", "#8a5aa8"};
constexpr double kGroupFill = 0.8;  // share of a bin's width its bars take
constexpr int kMaxEdgeLabels = 11;

int clamp_size(int s) { return std::clamp(s, 120, 8192); }

bool edges_ok(std::span<const double> edges) {
  if (edges.size() < 2) return false;
  for (std::size_t i = 0; i < edges.size(); ++i) {
    if (!std::isfinite(edges[i])) return false;
    if (i > 0 && !(edges[i] > edges[i - 1])) return false;
  }
  return true;
}

double bar_value(const HistogramSeries& s, std::size_t bin) {
  const double v = bin < s.values.size() ? s.values[bin] : 0.0;
  return std::isfinite(v) && v > 0.0 ? v : 0.0;
}

}  // namespace

std::optional<std::string> validate_histogram(std::span<const double> edges, std::span<const HistogramSeries> series) {
  if (edges.size() < 2) return "a histogram needs at least 2 bin edges";
  if (!edges_ok(edges)) return "histogram bin edges must be finite and strictly increasing";
  const std::size_t bins = edges.size() - 1;
  for (const HistogramSeries& s : series) {
    if (s.values.size() != bins)
      return "series '" + s.name + "' has " + std::to_string(s.values.size()) + " values for " + std::to_string(bins) + " bins";
    for (double v : s.values)
      if (!std::isfinite(v) || v < 0.0) return "series '" + s.name + "' has a negative or non-finite value";
  }
  return std::nullopt;
}

std::string histogram_svg(std::span<const double> edges, std::span<const HistogramSeries> series,
                          const HistogramOptions& options) {
  const int width = clamp_size(options.width), height = clamp_size(options.height);
  const std::size_t bins = edges.size() >= 2 ? edges.size() - 1 : 0;
  const bool by_value = edges_ok(edges);

  // Scale of each series: 1, or 1 / total when normalised (an all-zero series stays zero).
  std::vector<double> factor(series.size(), 1.0);
  double top = 0.0;
  for (std::size_t s = 0; s < series.size(); ++s) {
    double total = 0.0;
    for (std::size_t b = 0; b < bins; ++b) total += bar_value(series[s], b);
    if (options.normalise && total > 0.0) factor[s] = 1.0 / total;
    for (std::size_t b = 0; b < bins; ++b) top = std::max(top, factor[s] * bar_value(series[s], b));
  }
  const detail::Axis y_axis = detail::linear_axis(0.0, top > 0.0 ? top : 1.0);
  const detail::Axis x_axis = by_value ? detail::Axis{edges.front(), edges.back(), false, {}}
                                       : detail::Axis{0.0, static_cast<double>(std::max<std::size_t>(bins, 1)), false, {}};
  const auto edge_position = [&](std::size_t i) { return by_value ? edges[i] : static_cast<double>(i); };
  const detail::PlotArea area = detail::plot_area(width, height, !options.title.empty(), series.empty() ? 0 : 1);
  const std::string y_label = !options.y_label.empty() ? options.y_label : options.normalise ? "fraction" : "count";

  SvgWriter svg(width, height, options.id, options.title);
  detail::draw_frame(svg, area, y_axis, width, options.title, options.x_label, y_label);
  const std::size_t label_every = (edges.size() + kMaxEdgeLabels - 1) / kMaxEdgeLabels;
  for (std::size_t i = 0; i < edges.size(); i += std::max<std::size_t>(label_every, 1))
    detail::x_tick(svg, area, area.x(x_axis, edge_position(i)), format_significant(edges[i], 3));

  std::vector<std::string> colours;
  for (std::size_t s = 0; s < series.size(); ++s)
    colours.push_back(parse_colour(series[s].colour) ? series[s].colour : kPalette[s % std::size(kPalette)]);

  const double n = static_cast<double>(std::max<std::size_t>(series.size(), 1));
  for (std::size_t b = 0; b < bins; ++b) {
    const double x0 = area.x(x_axis, edge_position(b)), x1 = area.x(x_axis, edge_position(b + 1));
    const double group = kGroupFill * (x1 - x0);
    const double bar = group / n;
    const double start = x0 + 0.5 * (x1 - x0 - group);
    for (std::size_t s = 0; s < series.size(); ++s) {
      const double y = area.y(y_axis, factor[s] * bar_value(series[s], b));
      svg.raw("<rect class=\"bar\" x=\"");
      svg.number(start + static_cast<double>(s) * bar);
      svg.raw("\" y=\"");
      svg.number(y);
      svg.raw("\" width=\"");
      svg.number(bar);
      svg.raw("\" height=\"");
      svg.number(area.bottom - y);
      svg.raw("\" fill=\"" + colours[s] + "\"/>");
    }
  }

  // Legend: one row above the plot, right aligned, so it never hides a bar. Text width is
  // estimated (no font metrics in a static picture): about 0.6 em per character.
  const auto entry_width = [](const std::string& name) { return 14.0 + 6.6 * static_cast<double>(name.size()) + 12.0; };
  double total = 0.0;
  for (const HistogramSeries& s : series) total += entry_width(s.name);
  double x = std::max(area.left, area.right - total);
  const double y = area.top - 15.0;
  for (std::size_t s = 0; s < series.size(); ++s) {
    svg.raw("<rect class=\"key\" x=\"");
    svg.number(x);
    svg.raw("\" y=\"");
    svg.number(y);
    svg.raw("\" width=\"10\" height=\"10\" fill=\"" + colours[s] + "\"/>");
    svg.text(x + 14.0, y + 9.5, series[s].name, TextAnchor::kStart, 11);
    x += entry_width(series[s].name);
  }
  return svg.finish();
}

}  // namespace tetcut::render
