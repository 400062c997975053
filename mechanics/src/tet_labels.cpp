#include "tetcut/mechanics/tet_labels.hpp"

#include <algorithm>

namespace tetcut::mechanics {

TetLabels::TetLabels(const TetMesh& mesh, std::span<const std::uint32_t> labels) {
  reserve(mesh.tet_capacity() + mesh.tet_capacity() / 2);
  tets_.resize(mesh.tet_capacity(), {kDead, kDead, kDead, kDead});
  labels_.resize(mesh.tet_capacity(), kNoLabel);
  for (std::uint32_t t = 0; t < mesh.tet_capacity(); ++t) {
    if (!mesh.is_live(TetId{t})) continue;
    const auto v = mesh.tet(TetId{t});
    tets_[t] = {v[0].value, v[1].value, v[2].value, v[3].value};
    labels_[t] = labels[t];
  }
}

void TetLabels::reserve(std::uint32_t tets) {
  tets_.reserve(tets);
  labels_.reserve(tets);
  created_labels_.reserve(std::max<std::size_t>(created_labels_.capacity(), 4096));
}

std::uint32_t TetLabels::apply(const TetMesh& mesh, const ChangeLog& log) {
  const MeshReadScope reading(mesh, "TetLabels::apply()");
  if (mesh.tet_capacity() > tets_.size()) {
    tets_.resize(mesh.tet_capacity(), {kDead, kDead, kDead, kDead});
    labels_.resize(mesh.tet_capacity(), kNoLabel);
  }
  if (log.undo) return restore(mesh, log);
  // The created tets' labels first, while their parents are still here.
  std::uint32_t orphans = 0;
  created_labels_.clear();
  // The parents as they were: a vertex the operation moved is where the log says it was (moved
  // is sorted by id).
  auto before = [&](std::uint32_t v) -> Vec3 {
    const auto m = std::lower_bound(log.moved.begin(), log.moved.end(), VertId{v},
                                    [](const MovedVertex& x, VertId id) { return x.vertex < id; });
    return m != log.moved.end() && m->vertex == VertId{v} ? m->before : mesh.position(VertId{v});
  };
  for (const CreatedTet& c : log.created) {
    const auto cv = mesh.tet(c.tet);
    const auto parents = log.parents_of(c);
    const Vec3 centroid = tet_centroid(mesh.position(cv[0]), mesh.position(cv[1]), mesh.position(cv[2]),
                                       mesh.position(cv[3]));
    const std::uint32_t label = inherited_label(
        parents, log.removed, [&](TetId p) { return has(p); }, [&](TetId p) { return labels_[p.value]; },
        [&](TetId p) {
          const auto& pv = tets_[p.value];
          return tet_contains(before(pv[0]), before(pv[1]), before(pv[2]), before(pv[3]), centroid);
        });
    if (label == kNoLabel) ++orphans;
    created_labels_.push_back(label);
  }
  const bool changed = !log.removed.empty() || !log.created.empty() || !log.moved.empty();
  if (history_limit_ > 0 && changed) {  // a log that changes nothing is not kept, as the Cutter keeps no such cut
    // The ring's next slot, the oldest when it is full: cleared, its capacity kept, so that a
    // session that keeps history stops allocating once each slot has held its largest cut.
    if (history_.size() < history_limit_) history_.resize(history_limit_);
    newest_ = kept_ == 0 ? 0 : (newest_ + 1) % history_limit_;
    kept_ = std::min(kept_ + 1, history_limit_);
    auto& taken = history_[newest_];
    taken.clear();
    for (TetId t : log.removed)
      if (has(t)) taken.emplace_back(t, labels_[t.value]);
  }
  for (TetId t : log.removed) {
    if (!has(t)) continue;
    tets_[t.value] = {kDead, kDead, kDead, kDead};
    labels_[t.value] = kNoLabel;
  }
  for (std::size_t k = 0; k < log.created.size(); ++k) {
    const TetId t = log.created[k].tet;
    const auto v = mesh.tet(t);
    tets_[t.value] = {v[0].value, v[1].value, v[2].value, v[3].value};
    labels_[t.value] = created_labels_[k];
  }
  return orphans;
}

void TetLabels::keep_history(std::uint32_t logs) {
  if (logs == history_limit_) return;
  // The newest min(kept, logs) entries, oldest first from slot 0 (a change of the limit, between
  // cuts: the one place the ring is laid out again).
  const std::uint32_t keep = std::min(kept_, logs);
  std::vector<std::vector<std::pair<TetId, std::uint32_t>>> ring(logs);
  for (std::uint32_t k = 0; k < keep; ++k)
    ring[k] = std::move(history_[(newest_ + history_limit_ - (keep - 1 - k)) % history_limit_]);
  history_ = std::move(ring);
  history_limit_ = logs;
  kept_ = keep;
  newest_ = keep == 0 ? 0 : keep - 1;
}

std::uint32_t TetLabels::restore(const TetMesh& mesh, const ChangeLog& log) {
  for (TetId t : log.removed) {
    if (!has(t)) continue;
    tets_[t.value] = {kDead, kDead, kDead, kDead};
    labels_[t.value] = kNoLabel;
  }
  // The newest kept entry (none: every restored tet is an orphan), cleared once read.
  using Taken = std::pair<TetId, std::uint32_t>;
  std::vector<Taken>* kept = nullptr;
  if (kept_ > 0) {
    kept = &history_[newest_];
    newest_ = (newest_ + history_limit_ - 1) % history_limit_;
    --kept_;
  }
  const std::span<const Taken> taken = kept ? std::span<const Taken>(*kept) : std::span<const Taken>{};
  if (mesh.tet_capacity() > tets_.size()) {
    tets_.resize(mesh.tet_capacity(), {kDead, kDead, kDead, kDead});
    labels_.resize(mesh.tet_capacity(), kNoLabel);
  }
  std::uint32_t orphans = 0;
  for (const CreatedTet& c : log.created) {
    const auto it = std::lower_bound(taken.begin(), taken.end(), c.tet,
                                     [](const Taken& x, TetId id) { return x.first < id; });
    const std::uint32_t label = it != taken.end() && it->first == c.tet ? it->second : kNoLabel;
    if (label == kNoLabel) ++orphans;
    const auto v = mesh.tet(c.tet);
    tets_[c.tet.value] = {v[0].value, v[1].value, v[2].value, v[3].value};
    labels_[c.tet.value] = label;
  }
  if (kept) kept->clear();
  return orphans;
}

void TetLabels::renumber(const Renumbering& renumbering) {
  std::vector<std::array<std::uint32_t, 4>> tets(tets_.size(), {kDead, kDead, kDead, kDead});
  std::vector<std::uint32_t> labels(labels_.size(), kNoLabel);
  for (std::size_t old = 0; old < renumbering.tet_old_to_new.size() && old < tets_.size(); ++old) {
    const TetId now = renumbering.tet_old_to_new[old];
    if (!now.valid() || tets_[old][0] == kDead) continue;
    auto v = tets_[old];
    for (std::uint32_t& x : v) x = renumbering.vert_old_to_new[x].value;
    tets[now.value] = v;
    labels[now.value] = labels_[old];
  }
  tets_ = std::move(tets);
  labels_ = std::move(labels);
  // Kept under the old ids (and no Cutter undoes across a compaction).
  for (auto& taken : history_) taken.clear();
  kept_ = 0;
  newest_ = 0;
}

}  // namespace tetcut::mechanics
