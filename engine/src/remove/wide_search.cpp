#include "remove/wide_search.hpp"

#include <algorithm>

#include "tetcut/detail/reserve_touched.hpp"

namespace tetcut::detail {

void WideSearch::reserve() {
  reserve_touched(pool_, 4096);
  for (auto* v : {&candidates_, &frontier_, &next_frontier_}) reserve_touched(*v, 256);
  for (auto* v : {&tmp_tets_, &tmp_path_}) reserve_touched(*v, 256);
  reserve_touched(tmp_sizes_, 64);
}
namespace {

// Two candidate sets of one round are kept for the next one: enough for a path extended by
// each of two components, small enough to bound the work.
constexpr std::size_t kFrontierWidth = 4;

}  // namespace

void WideSearch::add_candidate(const Candidate& from, std::span<const TetId> extra, std::uint32_t max_set_size) {
  if (extra.empty() || from.size + extra.size() > max_set_size) return;
  const std::uint32_t begin = from.begin, size = from.size;
  Candidate c;
  c.begin = static_cast<std::uint32_t>(pool_.size());
  c.size = size + static_cast<std::uint32_t>(extra.size());
  c.prefix = {size, from.offence.vertices_passed};
  for (std::uint32_t i = begin; i < begin + size; ++i) {
    const TetId x = pool_[i];  // a copy: push_back may reallocate pool_
    pool_.push_back(x);
  }
  pool_.insert(pool_.end(), extra.begin(), extra.end());
  candidates_.push_back(c);
}

void WideSearch::expand(const TetMesh& mesh, SetRemovalWorkspace& ws, const Candidate& from,
                        const WideSearchLimits& limits) {
  ws.mark(mesh, std::span<const TetId>(pool_.data() + from.begin, from.size));
  const Removability& off = from.offence;
  tmp_tets_.clear();
  tmp_sizes_.clear();
  auto part = [&](std::size_t offset, std::size_t n) { return std::span<const TetId>(tmp_tets_.data() + offset, n); };
  ws.remaining_pieces(mesh, off, tmp_tets_, tmp_sizes_);
  if (off.kind == SingularityKind::kEdge) {
    // Around the edge the remaining tets form several runs: remove all but one of them, or all.
    std::size_t offset = 0;
    for (std::uint32_t n : tmp_sizes_) {
      add_candidate(from, part(offset, n), limits.max_set_size);
      offset += n;
    }
    if (tmp_sizes_.size() >= 2) add_candidate(from, part(0, tmp_tets_.size()), limits.max_set_size);
  } else if (off.kind == SingularityKind::kVertex) {
    if (tmp_sizes_.size() >= 2) {
      std::size_t offset = 0;
      for (std::uint32_t n : tmp_sizes_) {
        add_candidate(from, part(offset, n), limits.max_set_size);
        offset += n;
      }
    }
    tmp_path_.clear();
    if (ws.path_to_border(mesh, off.vertex, off.tet, limits.max_path_depth, tmp_path_))
      add_candidate(from, tmp_path_, limits.max_set_size);
    // The vertex goes entirely (beyond the paper).
    add_candidate(from, part(0, tmp_tets_.size()), limits.max_set_size);
  }
}

bool WideSearch::find(const TetMesh& mesh, SetRemovalWorkspace& ws, std::span<const TetId> seed,
                      const Removability& offence, const WideSearchLimits& limits, std::vector<TetId>& out) {
  pool_.assign(seed.begin(), seed.end());
  frontier_.clear();
  Candidate start;
  start.size = static_cast<std::uint32_t>(seed.size());
  start.offence = offence;
  frontier_.push_back(start);
  int evaluations = 0;
  for (int round = 0; round < limits.max_rounds; ++round) {
    candidates_.clear();
    for (const Candidate& f : frontier_) expand(mesh, ws, f, limits);
    if (candidates_.empty()) return false;
    // Smallest first; ties in generation order.
    std::sort(candidates_.begin(), candidates_.end(), [](const Candidate& x, const Candidate& y) {
      return x.size != y.size ? x.size < y.size : x.begin < y.begin;
    });
    next_frontier_.clear();
    for (Candidate& c : candidates_) {
      if (evaluations >= limits.max_evaluations) return false;
      const std::span<const TetId> set(pool_.data() + c.begin, c.size);
      const Removability check = ws.check(mesh, set, c.prefix);
      ++evaluations;
      if (check.removable()) {
        out.assign(set.begin(), set.end());
        return true;
      }
      if (next_frontier_.size() < kFrontierWidth) {
        c.offence = check;
        next_frontier_.push_back(c);
      }
    }
    frontier_.swap(next_frontier_);
  }
  return false;
}

}  // namespace tetcut::detail
