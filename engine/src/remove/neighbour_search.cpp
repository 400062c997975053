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
  for (auto* v : {&base_, &candidate_, &parts_}) reserve_touched(*v, 256);
  reserve_touched(sizes_, 64);
}

void NeighbourSearch::consider(const TetMesh& mesh, SetRemovalWorkspace& ws, std::span<const TetId> base,
                               std::span<const TetId> extra, std::uint32_t max_set_size, std::vector<TetId>& out,
                               TestedPrefix tested) {
  const std::size_t size = base.size() + extra.size();
  if (size > max_set_size || (!out.empty() && size >= out.size())) return;
  candidate_.assign(base.begin(), base.end());
  candidate_.insert(candidate_.end(), extra.begin(), extra.end());
  if (ws.check(mesh, candidate_, tested).removable()) out.swap(candidate_);
}

bool NeighbourSearch::find(const TetMesh& mesh, SetRemovalWorkspace& ws, TetId t, const Removability& first,
                           int max_depth, std::uint32_t max_set_size, std::vector<TetId>& out) {
  out.clear();
  path_found_ = false;
  if (first.kind == SingularityKind::kEdge) {
    sides_of_edge(mesh, ws, t, first.edge.a, first.edge.b, parts_, sizes_);
    const TetId one[1] = {t};
    std::size_t offset = 0;
    for (std::uint32_t n : sizes_) {  // the left set, the right set: the smaller removable one
      consider(mesh, ws, one, std::span<const TetId>(parts_.data() + offset, n), max_set_size, out);
      offset += n;
    }
    if (out.empty() && sizes_.size() >= 2) consider(mesh, ws, one, parts_, max_set_size, out);  // the whole set
    return !out.empty();
  }
  if (first.kind != SingularityKind::kVertex) return false;

  base_.assign(1, t);
  if (!shortest_path_to_border(mesh, ws, t, first.vertex, max_depth, parts_)) return false;
  base_.insert(base_.end(), parts_.begin(), parts_.end());
  path_found_ = true;
  const Removability check = ws.check(mesh, base_);
  if (check.removable()) {
    out = base_;
    return true;
  }
  // The path divides the remaining tets around one vertex (or edge) into pieces: extend it by
  // each piece (ws still has base_ marked from the check).
  parts_.clear();
  sizes_.clear();
  ws.remaining_pieces(mesh, check, parts_, sizes_);
  if (sizes_.size() < 2) return false;
  std::size_t offset = 0;
  for (std::uint32_t n : sizes_) {
    consider(mesh, ws, base_, std::span<const TetId>(parts_.data() + offset, n), max_set_size, out,
             {static_cast<std::uint32_t>(base_.size()), check.vertices_passed});
    offset += n;
  }
  return !out.empty();
}

}  // namespace tetcut::detail
