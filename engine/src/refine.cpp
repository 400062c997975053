#include "tetcut/refine.hpp"

#include <algorithm>
#include <cmath>

#include "tetcut/local_tables.hpp"

namespace tetcut {
namespace {

double length(const TetMesh& mesh, VertId a, VertId b) { return norm(mesh.position(b) - mesh.position(a)); }

bool meets(const TetMesh& mesh, TetId t, const Ball& ball) {
  const auto v = mesh.tet(t);
  return intersects(ball, mesh.position(v[0]), mesh.position(v[1]), mesh.position(v[2]), mesh.position(v[3]));
}

}  // namespace

std::optional<std::string> validate(const RefineParams& params) {
  if (!std::isfinite(params.d_ref) || params.d_ref <= 0.0) return "D_ref must be a positive finite length";
  if (!std::isfinite(params.p) || params.p <= 1.0) return "p must be a finite number greater than 1";
  if (params.max_iterations == 0) return "the iteration bound must be at least 1";
  return std::nullopt;
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
void Refiner::add_shell_edges(const TetMesh& mesh, double p) {
  for (std::size_t i = 0; i < edges_.size(); ++i) {
    const Edge e = edges_[i];
    const double threshold = p * length(mesh, e.a, e.b);
    TetId start = e.hint;  // every edge here was found in a tet
    if (!mesh.is_live(start) || mesh.local_index(start, e.a) < 0 || mesh.local_index(start, e.b) < 0) {
      start = kNoTet;
      mesh.vertex_shell(e.a, shell_);
      for (TetId t : shell_)
        if (mesh.local_index(t, e.b) >= 0) {
          start = t;
          break;
        }
    }
    if (!start.valid()) continue;
    mesh.edge_shell(start, kEdgeIndex[mesh.local_index(start, e.a)][mesh.local_index(start, e.b)], shell_);
    for (TetId t : shell_) {
      const int le = kEdgeIndex[mesh.local_index(t, e.a)][mesh.local_index(t, e.b)];
      const int lo = opposite_edge(static_cast<std::uint8_t>(le));
      const Edge opposite{mesh.vertex(t, kEdgeVerts[lo][0]), mesh.vertex(t, kEdgeVerts[lo][1]), t};
      if (length(mesh, opposite.a, opposite.b) > threshold && seen_.insert(opposite.a, opposite.b))
        edges_.push_back(opposite);
    }
  }
}

RefineReport Refiner::refine(TetMesh& mesh, std::span<const TetId> initial, const RefineParams& params,
                             std::vector<TetId>& region, ChangeLog* log) {
  RefineReport report;
  region.assign(initial.begin(), initial.end());
  current_.assign(initial.begin(), initial.end());
  for (;;) {
    collect_long_edges(mesh, params.d_ref);
    if (edges_.empty()) break;
    if (report.iterations == params.max_iterations) {
      report.converged = false;
      break;
    }
    add_shell_edges(mesh, params.p);
    created_.clear();
    const SplitResult split = splitter_.split(mesh, edges_, params.method, &created_, log);
    if (!split.ok()) {
      report.refusal = split.refusal;
      break;
    }
    ++report.iterations;
    report.edges_split += split.edges_split;
    report.tets_created += split.tets_created;
    report.tets_removed += split.tets_removed;
    report.min_radius_ratio = std::min(report.min_radius_ratio, split.min_radius_ratio);
    region.insert(region.end(), created_.begin(), created_.end());
    if (params.focus)
      created_.erase(std::remove_if(created_.begin(), created_.end(), [&](TetId t) { return !meets(mesh, t, *params.focus); }),
                     created_.end());
    current_.swap(created_);
  }
  std::sort(region.begin(), region.end());
  region.erase(std::unique(region.begin(), region.end()), region.end());
  region.erase(std::remove_if(region.begin(), region.end(), [&](TetId t) { return !mesh.is_live(t); }), region.end());
  return report;
}

}  // namespace tetcut
