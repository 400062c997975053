#include "remove/neighbour_search.hpp"

#include "tetcut/detail/local_tables.hpp"
#include "tetcut/detail/reserve_touched.hpp"

namespace tetcut::detail {

bool shortest_path_to_border(const TetMesh& mesh, SetRemovalWorkspace& ws, TetId t, VertId v, int max_depth,
                             std::vector<TetId>& path) {
  const TetId one[1] = {t};
  ws.mark(mesh, one);
  path.clear();
  return ws.path_to_border(mesh, v, t, max_depth, path);
}

void sides_of_edge(const TetMesh& mesh, SetRemovalWorkspace& ws, TetId t, VertId a, VertId b, std::vector<TetId>& tets,
                   std::vector<std::uint32_t>& sizes) {
  const TetId one[1] = {t};
  ws.mark(mesh, one);
  tets.clear();
  sizes.clear();
  const int local_edge = mesh.local_edge(t, a, b);
  ws.remaining_runs(mesh, t, local_edge, tets, sizes);
}

void NeighbourSearch::reserve() {
  for (auto* v : {&base_, &candidate_, &parts_, &ends_, &shortest_}) reserve_touched(*v, 256);
  reserve_touched(sizes_, 64);
}

EdgeCandidateVerdict NeighbourSearch::consider(const TetMesh& mesh, SetRemovalWorkspace& ws,
                                               std::span<const TetId> base, std::span<const TetId> extra,
                                               std::uint32_t max_set_size, std::vector<TetId>& out,
                                               TestedPrefix tested, Edge edge) {
  const std::size_t size = base.size() + extra.size();
  if (size > max_set_size) return EdgeCandidateVerdict::kTooLarge;
  if (!out.empty() && size >= out.size()) return EdgeCandidateVerdict::kSkipped;
  candidate_.assign(base.begin(), base.end());
  candidate_.insert(candidate_.end(), extra.begin(), extra.end());
  const Removability check = ws.check(mesh, candidate_, tested);
  if (check.removable()) {
    out.swap(candidate_);
    return EdgeCandidateVerdict::kRemovable;
  }
  // Where the set test failed, relative to the singular edge and T (base.front()).
  auto at_end = [&](VertId v) { return v == edge.a || v == edge.b; };
  if (check.kind == SingularityKind::kEdge)
    return at_end(check.edge.a) || at_end(check.edge.b) ? EdgeCandidateVerdict::kEdgeAtEnd
                                                         : EdgeCandidateVerdict::kEdgeElsewhere;
  if (at_end(check.vertex)) return EdgeCandidateVerdict::kVertexAtEnd;
  return mesh.local_index(base.front(), check.vertex) >= 0 ? EdgeCandidateVerdict::kVertexOfT
                                                          : EdgeCandidateVerdict::kVertexOfSide;
}

bool NeighbourSearch::find(const TetMesh& mesh, SetRemovalWorkspace& ws, TetId t, const Removability& first,
                           int max_depth, std::uint32_t max_set_size, std::vector<TetId>& out, bool first_found) {
  out.clear();
  path_found_ = false;
  shortest_.clear();
  edge_configuration_ = kNoConfiguration;
  if (first.kind == SingularityKind::kEdge) {
    sides_of_edge(mesh, ws, t, first.edge.a, first.edge.b, parts_, sizes_);
    const TetId one[1] = {t};
    // Each candidate's verdict, for the report; a third run, which an open
    // ring split by T cannot have, would be tested and not recorded.
    EdgeCandidateVerdict verdicts[3] = {EdgeCandidateVerdict::kSkipped, EdgeCandidateVerdict::kSkipped,
                                        EdgeCandidateVerdict::kSkipped};
    std::size_t offset = 0;
    for (std::size_t k = 0; k < sizes_.size(); ++k) {  // the left set, the right set: the smaller removable one
      if (first_found && !out.empty()) break;  // or the first
      const EdgeCandidateVerdict v = consider(mesh, ws, one, std::span<const TetId>(parts_.data() + offset, sizes_[k]),
                                              max_set_size, out, {}, first.edge);
      if (k < 2) verdicts[k] = v;
      offset += sizes_[k];
    }
    if (out.empty() && sizes_.size() >= 2)  // the whole set
      verdicts[2] = consider(mesh, ws, one, parts_, max_set_size, out, {}, first.edge);
    edge_configuration_ = EdgeSearchTally::configuration(verdicts[0], verdicts[1], verdicts[2]);
    return !out.empty();
  }
  if (first.kind != SingularityKind::kVertex) return false;

  // Breadth-first from T through v's shell to every border tet within max_depth: one path per
  // end, shortest first.
  const TetId one[1] = {t};
  ws.mark(mesh, one);
  if (!ws.border_paths(mesh, first.vertex, t, max_depth, ends_)) return false;
  if (ends_.empty()) ends_.push_back(kNoTet);  // T itself opens onto the border at v: T alone
  for (std::size_t k = 0; k < ends_.size(); ++k) {
    base_.assign(1, t);
    if (ends_[k].valid()) ws.border_path(ends_[k], base_);
    if (k == 0) {
      shortest_.assign(base_.begin(), base_.end());  // what 3.7 refines along
      path_found_ = true;
    }
    // Later paths are no shorter: once a removable set is as small as this path, none can win.
    if (base_.size() > max_set_size || (!out.empty() && base_.size() >= out.size())) break;
    const Removability check = ws.check(mesh, base_);
    if (check.removable()) {
      out = base_;
      break;
    }
    // "The path ... often divides the adjacency of one of the tetrahedron vertices into two
    // connected components": the path extended by each (ws still has base_ marked). An edge
    // pinched by the path is left to the wide search (ours).
    if (check.kind != SingularityKind::kVertex) continue;
    parts_.clear();
    sizes_.clear();
    ws.remaining_pieces(mesh, check, parts_, sizes_);
    if (sizes_.size() < 2) continue;
    std::size_t offset = 0;
    for (std::uint32_t n : sizes_) {
      consider(mesh, ws, base_, std::span<const TetId>(parts_.data() + offset, n), max_set_size, out,
               {static_cast<std::uint32_t>(base_.size()), check.vertices_passed});
      offset += n;
      if (first_found && !out.empty()) break;
    }
    if (first_found && !out.empty()) break;
  }
  return !out.empty();
}

}  // namespace tetcut::detail
