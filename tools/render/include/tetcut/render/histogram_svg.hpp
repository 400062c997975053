// A grouped bar chart: one bar per bin per series, e.g. radius ratios before and after a cut.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

namespace tetcut::render {

struct HistogramSeries {
  std::string name;    // in the legend
  std::string colour;  // "#rrggbb"; anything else gets a colour from a fixed palette
  std::vector<double> values;  // one per bin: counts (or any non-negative weights)
};

struct HistogramOptions {
  int width = 480;  // viewBox size, pixels (clamped to 120..8192)
  int height = 300;
  std::string title;
  std::string x_label;
  std::string y_label;  // when empty: "fraction" if normalise, else "count"
  // Each series divided by its own total, so meshes of different sizes compare.
  bool normalise = false;
  std::string id;  // the <svg> element's id attribute, none when empty
};

// A message when the bins cannot be drawn as given: fewer than 2 edges, edges not finite and
// strictly increasing, a series without one value per bin, a negative or non-finite value.
std::optional<std::string> validate_histogram(std::span<const double> edges, std::span<const HistogramSeries> series);

// Bins [edges[i], edges[i+1]) placed by value along x (by index when the edges are not finite
// and increasing), each split into one bar per series in series order: <rect class="bar">, one
// per bin per series, zero-height bars included so the count never depends on the data. A
// missing value counts as 0, extra values are ignored, negative or non-finite ones draw as 0.
// The legend (one <rect class="key"> and name per series) is one row above the plot, right
// aligned.
std::string histogram_svg(std::span<const double> edges, std::span<const HistogramSeries> series,
                          const HistogramOptions& options = {});

}  // namespace tetcut::render
