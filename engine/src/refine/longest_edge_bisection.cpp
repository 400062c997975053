#include "refine/longest_edge_bisection.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include "core/quality.hpp"
#include "core/tool.hpp"
#include "refine/refine.hpp"
#include "tetcut/detail/local_tables.hpp"
#include "tetcut/detail/reserve_touched.hpp"

namespace tetcut {
namespace {

// What the selection compares with D_ref (paper 3.3): the edge's length, not its square, so that
// a tet this rule leaves is one the selection takes, bit for bit.
bool has_edge_longer_than(const TetMesh& mesh, TetId t, double d_ref) {
  for (int e = 0; e < 6; ++e)
    if (norm(mesh.position(mesh.vertex(t, kEdgeVerts[e][1])) - mesh.position(mesh.vertex(t, kEdgeVerts[e][0]))) > d_ref)
      return true;
  return false;
}

}  // namespace

bool LongestEdgeBisection::longer(const RankedEdge& x, const RankedEdge& y) {
  if (x.length2 != y.length2) return x.length2 > y.length2;
  return std::pair(x.lo, x.hi) > std::pair(y.lo, y.hi);
}

LongestEdgeBisection::RankedEdge LongestEdgeBisection::longest_edge(const TetMesh& mesh, TetId t) {
  RankedEdge best;
  for (int e = 0; e < 6; ++e) {
    const VertId a = mesh.vertex(t, kEdgeVerts[e][0]), b = mesh.vertex(t, kEdgeVerts[e][1]);
    const Vec3 d = mesh.position(b) - mesh.position(a);
    const RankedEdge edge{dot(d, d), std::min(a.value, b.value), std::max(a.value, b.value), t, e};
    if (e == 0 || longer(edge, best)) best = edge;
  }
  return best;
}

LongestEdgeBisection::RankedEdge LongestEdgeBisection::terminal_edge(const TetMesh& mesh, TetId t, bool& cut_short) {
  RankedEdge edge = longest_edge(mesh, t);
  cut_short = false;
  for (std::uint32_t step = 0;; ++step) {
    mesh.edge_shell(edge.tet, edge.local, shell_);
    // The next edge of the path: the longest of the longest edges around this one (Rivara's
    // LEPP moves to any tet with a longer longest edge; taking the longest shortens the path).
    RankedEdge next = edge;
    for (TetId u : shell_)
      if (const RankedEdge candidate = longest_edge(mesh, u); longer(candidate, next)) next = candidate;
    if (next.lo == edge.lo && next.hi == edge.hi) return edge;  // the longest edge of every tet around it
    if (edge.length2 >= kNearlyLongest * kNearlyLongest * next.length2) return edge;  // nearly so
    if (step + 1 == kMaxPathSteps) {
      cut_short = true;
      return edge;
    }
    edge = next;
  }
}

RefineReport LongestEdgeBisection::refine(TetMesh& mesh, std::span<const TetId> initial, const RefineParams& params,
                                          std::vector<TetId>& region, EdgeSplitter& splitter) {
  RefineReport report;
  region.assign(initial.begin(), initial.end());
  queue_.assign(initial.begin(), initial.end());
  target_.clear();
  born_.clear();
  for (TetId t : initial) target_.insert(t);
  std::uint64_t net = 0;  // live tets made by this call
  for (std::size_t head = 0; head < queue_.size() && report.refusal == SplitRefusal::kNone; ++head) {
    const TetId t = queue_[head];
    // Until t is gone: each bisection halves an edge at least as long as t's longest, so t's turn
    // comes after a few (its own longest edge is terminal once the longer ones around it are cut).
    while (mesh.is_live(t) && target_.contains(t) && has_edge_longer_than(mesh, t, params.d_ref)) {
      bool cut_short = false;
      const RankedEdge edge = terminal_edge(mesh, t, cut_short);
      report.paths_cut_short += cut_short ? 1 : 0;
      // The shell is what the bisection replaces: remember each tet's side of it and its marks.
      parents_.clear();
      std::uint32_t born_parents = 0;
      for (TetId u : shell_) {
        const int lo = opposite_edge(static_cast<std::uint8_t>(mesh.local_edge(u, VertId{edge.lo}, VertId{edge.hi})));
        const std::uint32_t c = mesh.vertex(u, kEdgeVerts[lo][0]).value, d = mesh.vertex(u, kEdgeVerts[lo][1]).value;
        parents_.push_back({std::min(c, d), std::max(c, d), target_.contains(u)});
        if (born_.contains(u)) ++born_parents;
      }
      const Edge split_edge{VertId{edge.lo}, VertId{edge.hi}, edge.tet};
      created_.clear();
      const SplitResult split = splitter.split(mesh, std::span(&split_edge, 1), SplitMethod::kBisection, &created_,
                                               children_allowed(params, net, born_parents));
      if (!split.ok()) {
        report.refusal = split.refusal;
        break;
      }
      // Ids freed by the split may come back as its children outside a transaction: the parents'
      // marks go before the children's are set.
      for (TetId u : shell_) {
        target_.erase(u);
        born_.erase(u);
      }
      for (TetId child : created_) {
        born_.insert(child);
        // The child's two vertices off the edge are its parent's (the third is the midpoint).
        std::array<std::uint32_t, 2> off{};
        int found = 0;
        for (VertId v : mesh.tet(child))
          if (v.value != edge.lo && v.value != edge.hi && found < 2)
            for (const ShellTet& p : parents_)
              if (v.value == p.c || v.value == p.d) {
                off[static_cast<std::size_t>(found++)] = v.value;
                break;
              }
        std::sort(off.begin(), off.end());
        const auto parent = std::find_if(parents_.begin(), parents_.end(),
                                         [&](const ShellTet& p) { return p.c == off[0] && p.d == off[1]; });
        if (parent == parents_.end() || !parent->target) continue;
        if (params.focus && !tet_meets_tool(mesh, child, *params.focus)) continue;
        target_.insert(child);
        queue_.push_back(child);
      }
      net = net + split.tets_created - born_parents;
      count_split(report, split, net);
      if (params.measure_quality) report.min_radius_ratio = std::min(report.min_radius_ratio, min_radius_ratio(mesh, created_));
      region.insert(region.end(), created_.begin(), created_.end());
    }
  }
  finish_region(mesh, region);
  return report;
}

void LongestEdgeBisection::reserve(std::uint32_t tets) {
  using detail::reserve_touched;
  target_.reserve(tets);
  born_.reserve(tets);
  reserve_touched(queue_, 4096);
  reserve_touched(shell_, 256);
  reserve_touched(created_, 512);
  reserve_touched(parents_, 256);
}

}  // namespace tetcut
