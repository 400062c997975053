#include "refine/refine.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

#include "core/quality.hpp"
#include "tetcut/detail/local_tables.hpp"
#include "tetcut/detail/reserve_touched.hpp"

namespace tetcut {
namespace {

double length(const TetMesh& mesh, VertId a, VertId b) { return norm(mesh.position(b) - mesh.position(a)); }

}  // namespace

std::optional<std::string> validate(const RefineParams& params) {
  if (!std::isfinite(params.d_ref) || params.d_ref <= 0.0) return "D_ref must be a positive finite length";
  if (!std::isfinite(params.p) || params.p <= 1.0) return "p must be a finite number greater than 1";
  if (params.max_iterations == 0) return "the iteration bound must be at least 1";
  if (params.max_tets_created == 0) return "the tet budget (max_tets_created) must be positive";
  return std::nullopt;
}

MeshScale measure_scale(const TetMesh& mesh) {
  MeshScale scale;
  double shortest2 = std::numeric_limits<double>::infinity(), sum = 0.0;
  std::uint64_t edges = 0;
  for (std::uint32_t t = 0; t < mesh.tet_capacity(); ++t) {
    if (!mesh.is_live(TetId{t})) continue;
    for (int e = 0; e < 6; ++e) {
      const Vec3 d = mesh.position(mesh.vertex(TetId{t}, kEdgeVerts[e][1])) - mesh.position(mesh.vertex(TetId{t}, kEdgeVerts[e][0]));
      shortest2 = std::min(shortest2, dot(d, d));
      sum += norm(d);
      ++edges;
    }
  }
  scale.shortest_edge = std::isfinite(shortest2) ? std::sqrt(shortest2) : 0.0;
  scale.mean_edge = edges ? sum / static_cast<double>(edges) : 0.0;
  scale.volume = mesh.total_volume();
  return scale;
}

namespace {

// Volume of the largest tet whose edges are all at most `edge`: the regular one.
double regular_tet_volume(double edge) { return edge * edge * edge / (6.0 * std::numbers::sqrt2); }

double ball_volume(double diameter) { return std::numbers::pi / 6.0 * diameter * diameter * diameter; }

std::string short_number(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3g", x);
  return buffer;
}

// x rounded up to three significant digits: a suggested minimum must not round below it.
double round_up_3(double x) {
  const double unit = std::pow(10.0, std::floor(std::log10(x)) - 2);
  return std::ceil(x * (1 + 1e-9) / unit) * unit;
}

}  // namespace

double min_tets_to_refine(const MeshScale& scale, double tool_diameter, double d_ref) {
  if (!(d_ref > 0.0) || !(d_ref < scale.shortest_edge)) return 0.0;
  return std::min(ball_volume(tool_diameter), scale.volume) / regular_tet_volume(d_ref);
}

std::optional<std::string> check_scale(const MeshScale& scale, double tool_diameter, double d_ref_factor,
                                       std::uint32_t max_tets_created) {
  const double d_ref = d_ref_factor * tool_diameter;
  if (!std::isfinite(d_ref) || !(d_ref > 0.0)) return std::nullopt;
  const double needed = min_tets_to_refine(scale, tool_diameter, d_ref);
  if (needed <= max_tets_created) return std::nullopt;
  // The smallest factor that fits: the D_ref at which the bound meets the budget, or the
  // shortest edge, where the bound stops applying.
  const double fits = std::cbrt(std::min(ball_volume(tool_diameter), scale.volume) * 6.0 * std::numbers::sqrt2 /
                                static_cast<double>(max_tets_created));
  const double factor = std::min(fits, scale.shortest_edge) / tool_diameter;
  return "d_ref_factor " + short_number(d_ref_factor) + " is too small for this mesh and tool: D_ref = " +
         short_number(d_ref) + " is below the mesh's shortest edge (" + short_number(scale.shortest_edge) +
         "), so every tet the tool meets must be split down to it, at least " + (needed < 1e15 ? std::to_string(static_cast<long long>(std::ceil(needed))) : short_number(needed)) +
         " new tets per cut, more than the per-cut budget (max_tets_created " + std::to_string(max_tets_created) +
         "); a d_ref_factor of " + short_number(round_up_3(factor)) + " or more fits";
}

void Refiner::collect_long_edges(const TetMesh& mesh, double d_ref) {
  edges_.clear();
  seen_.clear();
  for (TetId t : current_) {
    if (!mesh.is_live(t)) continue;
    for (int e = 0; e < 6; ++e) {
      const Edge edge{mesh.vertex(t, kEdgeVerts[e][0]), mesh.vertex(t, kEdgeVerts[e][1]), t};
      if (length(mesh, edge.a, edge.b) > d_ref && seen_.insert(edge.a, edge.b)) edges_.push_back(edge);
    }
  }
}

// Paper 3.2: limit the ratio of edge lengths among the children by also splitting the long
// edges opposite each split edge. Edges added here are scanned too; each is more than p times
// longer than the edge that brought it in, so the closure is small.
std::uint32_t Refiner::add_shell_edges(const TetMesh& mesh, double p) {
  std::uint32_t born_parents = 0;
  for (std::size_t i = 0; i < edges_.size(); ++i) {
    const Edge e = edges_[i];
    const double threshold = p * length(mesh, e.a, e.b);
    const EdgeRef edge = mesh.find_edge(e.a, e.b, e.hint, shell_);  // every edge here was found in a tet
    if (!edge.valid()) continue;
    mesh.edge_shell(edge.tet, edge.edge, shell_);
    for (TetId t : shell_) {
      // The shells of the round's edges are exactly the tets the split will replace.
      if (born_.contains(t)) {
        born_.erase(t);
        ++born_parents;
      }
      const int lo = opposite_edge(static_cast<std::uint8_t>(mesh.local_edge(t, e.a, e.b)));
      const Edge opposite{mesh.vertex(t, kEdgeVerts[lo][0]), mesh.vertex(t, kEdgeVerts[lo][1]), t};
      if (length(mesh, opposite.a, opposite.b) > threshold && seen_.insert(opposite.a, opposite.b))
        edges_.push_back(opposite);
    }
  }
  return born_parents;
}

RefineReport Refiner::refine(TetMesh& mesh, std::span<const TetId> initial, const RefineParams& params,
                             std::vector<TetId>& region) {
  if (params.rule == RefinementRule::kGraded) return graded_.refine(mesh, initial, params, region, splitter_);
  RefineReport report;
  region.assign(initial.begin(), initial.end());
  current_.assign(initial.begin(), initial.end());
  born_.clear();
  std::uint64_t net = 0;  // live tets made by this call
  for (;;) {
    collect_long_edges(mesh, params.d_ref);
    if (edges_.empty()) break;
    if (report.iterations == params.max_iterations) {
      report.converged = false;
      break;
    }
    const std::uint32_t born_parents = add_shell_edges(mesh, params.p);
    created_.clear();
    const SplitResult split = splitter_.split(mesh, edges_, params.method, &created_, children_allowed(params, net, born_parents));
    if (!split.ok()) {
      report.refusal = split.refusal;
      break;
    }
    for (TetId t : created_) born_.insert(t);
    net = net + split.tets_created - born_parents;
    count_split(report, split, net);
    if (params.measure_quality) report.min_radius_ratio = std::min(report.min_radius_ratio, min_radius_ratio(mesh, created_));
    region.insert(region.end(), created_.begin(), created_.end());
    if (params.focus)
      created_.erase(std::remove_if(created_.begin(), created_.end(), [&](TetId t) { return !tet_meets_tool(mesh, t, *params.focus); }),
                     created_.end());
    current_.swap(created_);
  }
  finish_region(mesh, region);
  return report;
}

std::uint64_t children_allowed(const RefineParams& params, std::uint64_t net, std::uint32_t born_parents) {
  return params.max_tets_created - std::min<std::uint64_t>(net, params.max_tets_created) + born_parents;
}

void count_split(RefineReport& report, const SplitResult& split, std::uint64_t net) {
  report.net_tets_created = static_cast<std::uint32_t>(net);
  ++report.iterations;
  report.edges_split += split.edges_split;
  report.tets_created += split.tets_created;
  report.tets_removed += split.tets_removed;
}

void finish_region(const TetMesh& mesh, std::vector<TetId>& region) {
  std::sort(region.begin(), region.end());
  region.erase(std::unique(region.begin(), region.end()), region.end());
  region.erase(std::remove_if(region.begin(), region.end(), [&](TetId t) { return !mesh.is_live(t); }), region.end());
}

void Refiner::reserve(std::uint32_t tets) {
  using detail::reserve_touched;
  splitter_.reserve(tets);
  graded_.reserve(tets);
  born_.reserve(tets);
  reserve_touched(current_, 4096);
  reserve_touched(created_, 4096);
  reserve_touched(shell_, 256);
  reserve_touched(edges_, 2048);
  seen_.reserve(8192);
}

}  // namespace tetcut
