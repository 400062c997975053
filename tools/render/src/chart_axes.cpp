#include "chart_axes.hpp"

#include <algorithm>
#include <cmath>

namespace tetcut::render::detail {
namespace {

constexpr const char* kAxisColour = "#444444";
constexpr const char* kGridColour = "#e4e4e4";

// The round step (1, 2 or 5 x 10^k) nearest above span / target.
double nice_step(double span, int target) {
  const double raw = span / std::max(1, target);
  const double decade = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0})
    if (m * decade >= raw * (1.0 - 1e-12)) return m * decade;
  return 10.0 * decade;
}

}  // namespace

double Axis::fraction(double value) const {
  if (log) return (std::log10(value) - std::log10(lo)) / (std::log10(hi) - std::log10(lo));
  return (value - lo) / (hi - lo);
}

Axis linear_axis(double lo, double hi, int target, bool widen) {
  if (!std::isfinite(lo) || !std::isfinite(hi)) lo = 0.0, hi = 1.0;
  if (lo > hi) std::swap(lo, hi);
  if (hi - lo <= 1e-12 * std::max(std::fabs(lo), std::fabs(hi))) {
    const double pad = lo == 0.0 ? 1.0 : 0.5 * std::fabs(lo);
    lo -= pad;
    hi += pad;
    if (lo < 0.0 && lo + pad >= 0.0) lo = 0.0;  // keep a non-negative value's axis at zero
  }
  Axis axis;
  const double step = nice_step(hi - lo, target);
  // Integer tick indices: values computed as i * step, so no accumulated drift in the labels.
  const double first = widen ? std::floor(lo / step + 1e-9) : std::ceil(lo / step - 1e-9);
  const double last = widen ? std::ceil(hi / step - 1e-9) : std::floor(hi / step + 1e-9);
  axis.lo = widen ? first * step : lo;
  axis.hi = widen ? last * step : hi;
  for (double i = first; i <= last; i += 1.0) axis.ticks.push_back(i * step);
  return axis;
}

Axis log_axis(double lo, double hi) {
  if (!(lo > 0.0) || !std::isfinite(lo)) lo = 1.0;
  if (!(hi > 0.0) || !std::isfinite(hi)) hi = lo;
  if (lo > hi) std::swap(lo, hi);
  Axis axis;
  axis.log = true;
  int a = static_cast<int>(std::floor(std::log10(lo) + 1e-9));
  int b = static_cast<int>(std::ceil(std::log10(hi) - 1e-9));
  if (b <= a) b = a + 1;
  axis.lo = std::pow(10.0, a);
  axis.hi = std::pow(10.0, b);
  const bool fine = b - a <= 2;
  for (int k = a; k <= b; ++k) {
    const double decade = std::pow(10.0, k);
    axis.ticks.push_back(decade);
    if (fine && k < b) {
      axis.ticks.push_back(2.0 * decade);
      axis.ticks.push_back(5.0 * decade);
    }
  }
  return axis;
}

PlotArea plot_area(int width, int height, bool has_title, int top_rows) {
  return {60.0, (has_title ? 32.0 : 12.0) + 16.0 * top_rows, width - 16.0, height - 44.0};
}

void draw_frame(SvgWriter& svg, const PlotArea& area, const Axis& y_axis, int width, std::string_view title,
                std::string_view x_label, std::string_view y_label) {
  if (!title.empty()) svg.text(0.5 * width, 20.0, title, TextAnchor::kMiddle, 14);
  for (double t : y_axis.ticks) {
    const double y = area.y(y_axis, t);
    if (t != y_axis.lo) svg.line(area.left, y, area.right, y, kGridColour);
    svg.line(area.left - 4.0, y, area.left, y, kAxisColour);
    svg.text(area.left - 6.0, y + 4.0, format_significant(t, 3), TextAnchor::kEnd, 11);
  }
  svg.line(area.left, area.top, area.left, area.bottom, kAxisColour);
  svg.line(area.left, area.bottom, area.right, area.bottom, kAxisColour);
  if (!x_label.empty()) svg.text(0.5 * (area.left + area.right), area.bottom + 36.0, x_label, TextAnchor::kMiddle, 12);
  if (!y_label.empty()) {
    const double cx = 14.0, cy = 0.5 * (area.top + area.bottom);
    svg.text(cx, cy, y_label, TextAnchor::kMiddle, 12,
             "transform=\"rotate(-90 " + format_fixed(cx, 1) + ' ' + format_fixed(cy, 1) + ")\"");
  }
}

void x_tick(SvgWriter& svg, const PlotArea& area, double x, std::string_view label) {
  svg.line(x, area.bottom, x, area.bottom + 4.0, kAxisColour);
  svg.text(x, area.bottom + 16.0, label, TextAnchor::kMiddle, 11);
}

}  // namespace tetcut::render::detail
