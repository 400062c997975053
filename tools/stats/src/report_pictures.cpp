#include "tetcut/stats/report_pictures.hpp"

#include <algorithm>
#include <array>

#include "tetcut/percentile.hpp"
#include "tetcut/render/histogram_svg.hpp"
#include "tetcut/render/line_plot_svg.hpp"
#include "tetcut/render/surface.hpp"
#include "tetcut/render/surface_svg.hpp"
#include "tetcut/stats/exploded_view.hpp"

namespace tetcut::stats {

namespace {

// The pieces of the resected liver are drawn this far apart, in bounding box diagonals.
constexpr double kExplodeGap = 0.3;
// Seen from the -x side, where the resection plane's exposed face looks (x = 95 mm).
constexpr double kViewAzimuth = -130;
constexpr double kViewElevation = 25;

std::vector<double> histogram_values(const invariants::QualityStats& q) {
  return {q.radius_ratio_histogram.begin(), q.radius_ratio_histogram.end()};
}

double diagonal(const std::vector<render::SurfaceTriangle>& triangles) {
  if (triangles.empty()) return 0.0;
  Vec3 lo = triangles.front().a, hi = lo;
  for (const render::SurfaceTriangle& s : triangles)
    for (const Vec3& p : {s.a, s.b, s.c}) {
      lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
      hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
    }
  return norm(hi - lo);
}

}  // namespace

std::vector<Picture> resection_pictures(const ResectionStats& resection) {
  const CauteryRun& run = resection.run;
  std::vector<Picture> pictures;

  render::LinePlotOptions plot;
  plot.title = "Time per cut along the resection";
  plot.y_label = "microseconds";
  plot.log_y = true;
  plot.id = "latency-plot";
  plot.reference_lines = {{"p50", percentile(run.cut_us, 0.5)}, {"p99", percentile(run.cut_us, 0.99)}};
  pictures.push_back({plot.id, render::line_plot_svg(run.cut_us, plot),
                      "Each cut's total time (locate, refine, select, remove, commit), in the scenario's order; "
                      "times vary from run to run, everything else in the report does not."});

  std::array<double, invariants::kHistogramBins + 1> edges{};
  for (std::size_t i = 0; i < edges.size(); ++i) edges[i] = static_cast<double>(i) / invariants::kHistogramBins;
  const std::vector<render::HistogramSeries> series{
      {"before (" + std::to_string(run.quality_before.tets) + " tets)", "#8a9bb0", histogram_values(run.quality_before)},
      {"after (" + std::to_string(run.quality_after.tets) + " tets)", "#c0705a", histogram_values(run.quality_after)}};
  render::HistogramOptions hist;
  hist.title = "Radius ratio before and after";
  hist.x_label = "radius ratio (1 = regular)";
  hist.normalise = true;
  hist.id = "quality-histogram";
  pictures.push_back({hist.id, render::histogram_svg(edges, series, hist),
                      "Share of tets per radius-ratio bin (3 x inradius / circumradius)."});

  if (run.mesh_before && run.mesh_after) {
    render::SurfaceView view;
    view.azimuth_deg = kViewAzimuth;
    view.elevation_deg = kViewElevation;
    view.title = "Before";
    view.id = "liver-before";
    pictures.push_back({view.id, render::surface_svg(render::boundary_surface(*run.mesh_before), view),
                        "The liver's boundary surface before the resection."});
    view.title = "After";
    view.id = "liver-after";
    std::vector<render::SurfaceTriangle> after = render::classify_surface(*run.mesh_after, *run.mesh_before);
    explode_pieces(*run.mesh_after, after, kExplodeGap * diagonal(after));
    pictures.push_back({view.id, render::surface_svg(after, view),
                        "After: the surfaces the cautery exposed in yellow, the organ's own surface in red; the "
                        "resected piece drawn pulled away from the rest."});
  }
  return pictures;
}

}  // namespace tetcut::stats
