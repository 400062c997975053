#include "cut/fragment_search.hpp"

#include <algorithm>
#include <cmath>

#include "tetcut/detail/reserve_touched.hpp"

namespace tetcut::detail {

void FragmentSearch::reserve(std::uint32_t tets, std::uint32_t bound) {
  // The marks: a tet or vertex per entry, at most half full (the search stops as bounded before
  // that), for a search of the bound plus a large cut's seeds, never more than the mesh's ids.
  const std::size_t entries = std::min<std::size_t>(std::size_t{bound} + 3 * 16384, std::size_t{tets} * 5) + 1024;
  std::size_t capacity = 1024;
  while (capacity < 2 * entries) capacity *= 2;
  if (marks_.size() < capacity) {
    marks_.assign(capacity, Mark{});
    marks_used_.clear();
  }
  reserve_touched(marks_used_, capacity / 2);
  const std::size_t room = std::size_t{bound} + 16384;
  reserve_touched(groups_, 16384);
  reserve_touched(walking_, 16384);
  reserve_touched(finished_, 16384);
  reserve_touched(visited_, room);
  reserve_touched(tets_, room);
  reserve_touched(pieces_, 1024);
}

std::uint32_t FragmentSearch::probe(std::uint32_t key) const {
  const auto mask = static_cast<std::uint32_t>(marks_.size() - 1);
  std::uint32_t i = (key * 0x9E3779B1u) & mask;
  while (marks_[i].key != kNone && marks_[i].key != key) i = (i + 1) & mask;
  return i;
}

bool FragmentSearch::full() const { return 2 * marks_used_.size() >= marks_.size(); }

void FragmentSearch::seed(TetId t) {
  const std::uint32_t slot = probe(t.value);
  if (marks_[slot].key == t.value || full()) return;  // already reached from another seed
  const auto g = static_cast<std::uint32_t>(groups_.size());
  groups_.push_back({g, kNone, kNone, 0, kNone, 0, kNone, t.value, 0.0, Vec3{}});
  visit(*mesh_, t, g, slot);
  walking_.push_back(g);
}

std::uint32_t FragmentSearch::label(std::uint32_t g) {
  Group& group = groups_[g];
  if (group.label == kNone) group.label = labels_->label(*mesh_, TetId{group.seed});
  return group.label;
}

void FragmentSearch::start_measuring(const TetMesh& mesh) {
  measuring_ = true;
  for (std::uint32_t slot : visited_) measure(mesh, TetId{marks_[slot].key}, groups_[find(marks_[slot].group)]);
}

void FragmentSearch::measure(const TetMesh& mesh, TetId t, Group& group) {
  const auto v = mesh.tet(t);
  const Vec3 &a = mesh.position(v[0]), &b = mesh.position(v[1]), &c = mesh.position(v[2]), &d = mesh.position(v[3]);
  const double volume = std::abs(dot(b - a, cross(c - a, d - a))) / 6.0;
  group.volume += volume;
  group.moment = group.moment + (0.25 * volume) * (a + b + c + d);
}

void FragmentSearch::visit(const TetMesh& mesh, TetId t, std::uint32_t g, std::uint32_t slot) {
  marks_used_.push_back(slot);
  marks_[slot] = {t.value, g, kNone};
  Group& group = groups_[g];
  if (group.head == kNone) group.head = slot;
  else marks_[group.tail].next = slot;
  group.tail = slot;
  ++group.tets;
  if (measuring_) measure(mesh, t, group);
  visited_.push_back(slot);
}

std::uint32_t FragmentSearch::unite(std::uint32_t g, std::uint32_t h) {
  // The group with more tets stays the root; the other's queue and sums join it.
  if (groups_[g].tets < groups_[h].tets) std::swap(g, h);
  Group &root = groups_[g], &child = groups_[h];
  child.parent = g;
  if (child.head != kNone) {
    if (root.head == kNone) root.head = child.head;
    else marks_[root.tail].next = child.head;
    root.tail = child.tail;
  }
  root.tets += child.tets;
  if (root.label == kNone) root.label = child.label;  // one piece before the cut: one label
  root.volume += child.volume;
  root.moment = root.moment + child.moment;
  return g;
}

std::uint32_t FragmentSearch::expand(const TetMesh& mesh, std::uint32_t g) {
  const std::uint32_t head = groups_[g].head;
  const TetId t{marks_[head].key};
  groups_[g].head = marks_[head].next;
  for (int f = 0; f < 4; ++f) {
    const FaceRef n = mesh.neighbour(t, f);
    if (!n.valid()) continue;
    const std::uint32_t slot = probe(n.tet.value);
    if (marks_[slot].key != n.tet.value) {
      if (full()) {
        overflow_ = true;  // a tet left unvisited: no group can be called whole any more
        return g;
      }
      visit(mesh, n.tet, g, slot);
      continue;
    }
    const std::uint32_t other = find(marks_[slot].group);
    if (other != g) g = unite(g, other);
  }
  return g;
}

void FragmentSearch::unite_by_shared_vertices(const TetMesh& mesh) {
  for (std::uint32_t tet_slot : visited_) {
    std::uint32_t root = find(marks_[tet_slot].group);
    for (VertId v : mesh.tet(TetId{marks_[tet_slot].key})) {
      const std::uint32_t key = v.value | kVertexKey;
      const std::uint32_t slot = probe(key);
      if (marks_[slot].key != key) {
        if (full()) return;  // the rest stay apart: the walk merges them
        marks_used_.push_back(slot);
        marks_[slot] = {key, root, kNone};
        continue;
      }
      const std::uint32_t other = find(marks_[slot].group);
      if (other != root) root = unite(root, other);
    }
  }
}

void FragmentSearch::list_roots() {
  // Each root once (a group merged into another is listed by its root); the ones with nothing
  // left to expand are finished, whole pieces (every neighbour of their tets is theirs).
  ++listing_;
  std::size_t kept = 0;
  for (std::uint32_t g : walking_) {
    const std::uint32_t r = find(g);
    if (groups_[r].round == listing_) continue;
    groups_[r].round = listing_;
    if (groups_[r].head == kNone) finished_.push_back(r);
    else walking_[kept++] = r;
  }
  walking_.resize(kept);
}

bool FragmentSearch::resolved() {
  // Most cuts: every seed merged into one group, nothing finished.
  if (finished_.empty() && walking_.size() <= 1) return true;
  // Decided only once few groups walk (the many seeds of a cut merge in the first rounds).
  constexpr std::size_t kFew = 16;
  if (walking_.size() > kFew) return false;
  for (std::uint32_t w : walking_) {
    for (std::uint32_t other : walking_)
      if (other != w && label(other) == label(w)) return false;
    for (std::uint32_t f : finished_)
      if (label(f) == label(w) && groups_[f].volume > groups_[w].volume) return false;
  }
  return true;
}

void FragmentSearch::run(TetMesh& mesh, const PieceLabels& labels, std::span<const TetId> removed,
                         std::span<const TetId> created, std::uint32_t bound) {
  for (std::uint32_t i : marks_used_) marks_[i].key = kNone;  // the last search's marks, only
  marks_used_.clear();
  mesh_ = &mesh;
  labels_ = &labels;
  measuring_ = false;
  overflow_ = false;
  groups_.clear();
  walking_.clear();
  finished_.clear();
  visited_.clear();
  pieces_.clear();
  tets_.clear();
  bounded_ = false;

  for (TetId t : created) seed(t);
  for (TetId r : removed)
    for (VertId v : mesh.tet_at_start(r))
      if (mesh.is_live(v)) seed(mesh.vertex_tet(v));

  // Seeds that share a vertex are one piece (around a vertex the mesh is manifold): most cuts
  // end here, with one group and no walk.
  unite_by_shared_vertices(mesh);
  // Lockstep rounds: every walking root expands one tet.
  while (true) {
    list_roots();
    if (!finished_.empty() && !measuring_) start_measuring(mesh);
    if (walking_.empty() || resolved()) break;
    if (visited_.size() >= bound || full()) {
      bounded_ = true;
      break;
    }
    for (std::size_t i = 0, n = walking_.size(); i < n && !overflow_; ++i) {
      const std::uint32_t g = walking_[i];
      if (find(g) == g && groups_[g].head != kNone) expand(mesh, g);
    }
    if (overflow_) {
      bounded_ = true;
      finished_.clear();
      walking_.clear();
      break;
    }
  }
  collect();
}

void FragmentSearch::collect() {
  // A finished group is a detached piece when a larger group of its label exists: another
  // finished one (equal volumes: the later seed is the smaller), or a walking one that already
  // visited more (a bounded search leaves alone a finished group it cannot compare).
  auto larger = [&](std::uint32_t a, std::uint32_t b) {  // a before b: more volume, or the earlier seed
    return groups_[a].volume > groups_[b].volume || (groups_[a].volume == groups_[b].volume && a < b);
  };
  std::uint32_t total = 0;
  for (std::uint32_t f : finished_) {
    const Group& g = groups_[f];
    std::uint32_t organ = kNone;
    for (std::uint32_t other : finished_)
      if (other != f && label(other) == label(f) && larger(other, f) && (organ == kNone || larger(other, organ)))
        organ = other;
    for (std::uint32_t w : walking_)
      if (label(w) == label(f) && groups_[w].volume > g.volume && (organ == kNone || larger(w, organ))) organ = w;
    if (organ == kNone) continue;
    groups_[f].piece = static_cast<std::uint32_t>(pieces_.size());
    pieces_.push_back({total, 0, g.volume, (1.0 / g.volume) * g.moment, TetId{groups_[organ].seed}});
    total += g.tets;
  }
  if (pieces_.empty()) return;
  // The pieces' tets from the visit order, then each piece sorted by id.
  tets_.resize(total);
  for (std::uint32_t slot : visited_) {
    const std::uint32_t piece = groups_[find(marks_[slot].group)].piece;
    if (piece == kNone) continue;
    Piece& p = pieces_[piece];
    tets_[p.first + p.count++] = TetId{marks_[slot].key};
  }
  for (Piece& p : pieces_) std::sort(tets_.begin() + p.first, tets_.begin() + p.first + p.count);
}

}  // namespace tetcut::detail
