#include "detail/set_removal.hpp"

#include <algorithm>
#include <cassert>

#include "detail/local_tables.hpp"
#include "detail/reserve_touched.hpp"

namespace tetcut {
namespace {

// A fresh generation for a stamp array; on wrap-around the array is really cleared once.
std::uint32_t next_gen(std::vector<std::uint32_t>& stamps, std::uint32_t& gen) {
  if (++gen == 0) {
    std::fill(stamps.begin(), stamps.end(), 0u);
    gen = 1;
  }
  return gen;
}

}  // namespace

void SetRemovalWorkspace::grow(const TetMesh& mesh) {
  // Grows with the mesh only: a warm workspace on a mesh that does not grow never allocates.
  if (set_stamp_.size() < mesh.tet_capacity()) {
    const std::size_t n = mesh.tet_capacity() + mesh.tet_capacity() / 4 + 16;
    set_stamp_.resize(n, 0);
    shell_stamp_.resize(n, 0);
    visit_stamp_.resize(n, 0);
    parent_.resize(n, 0);
  }
}

void SetRemovalWorkspace::reserve(std::uint32_t tets) {
  if (set_stamp_.size() < tets) {
    set_stamp_.resize(tets, 0);
    shell_stamp_.resize(tets, 0);
    visit_stamp_.resize(tets, 0);
    parent_.resize(tets, 0);
  }
  for (auto* v : {&shell_, &queue_, &ring_, &group_}) detail::reserve_touched(*v, 512);
  detail::reserve_touched(depth_, 512);
  detail::reserve_touched(at_vertex_, 2048);
  edges_seen_.reserve(4096);
}

void SetRemovalWorkspace::mark(const TetMesh& mesh, std::span<const TetId> set) {
  grow(mesh);
  const std::uint32_t g = next_gen(set_stamp_, set_gen_);
  for (TetId t : set) set_stamp_[t.value] = g;
}

void SetRemovalWorkspace::collect_shell(const TetMesh& mesh, VertId v, TetId seed) {
  const std::uint32_t g = next_gen(shell_stamp_, shell_gen_);
  shell_.clear();
  shell_.push_back(seed);
  shell_stamp_[seed.value] = g;
  for (std::size_t i = 0; i < shell_.size(); ++i) {
    const TetId cur = shell_[i];
    const int lv = mesh.local_index(cur, v);
    assert(lv >= 0);
    for (int f = 0; f < 4; ++f) {
      if (f == lv) continue;
      const FaceRef n = mesh.neighbour(cur, f);
      if (!n.valid() || shell_stamp_[n.tet.value] == g) continue;
      shell_stamp_[n.tet.value] = g;
      shell_.push_back(n.tet);
    }
  }
}

template <class Visit>
void SetRemovalWorkspace::visit_fresh_shell_neighbours(const TetMesh& mesh, VertId v, TetId cur, std::uint32_t g,
                                                       Visit&& visit) {
  const int lv = mesh.local_index(cur, v);
  for (int f = 0; f < 4; ++f) {
    if (f == lv) continue;
    const FaceRef n = mesh.neighbour(cur, f);
    if (!n.valid() || marked(n.tet) || visit_stamp_[n.tet.value] == g) continue;
    visit_stamp_[n.tet.value] = g;
    visit(n.tet);
  }
}

// The link of v is a disk (v on the surface) or a sphere; the set's tets at v are triangles of
// it. Once every edge of the set has passed edge_ok(), the kept and the removed triangles each
// form one fan around every link vertex, so the interface between what stays and what goes
// (the boundary faces of the mesh count as "goes": the link's own border is glued to a removed
// cell) is a union of disjoint circles, and by Jordan's theorem what stays is a disk iff there
// is exactly one circle, or nothing stays iff there is none. So the test follows one circle
// and compares its length with the number of interface edges, both of which are local: the
// faces at v of the set's tets with a kept tet behind them, and the boundary faces at v of kept
// tets (the vertex's boundary face count minus the set's). It never walks the whole shell.
bool SetRemovalWorkspace::vertex_ok(const TetMesh& mesh, VertId v, std::span<const TetId> removed_at_v) {
  std::uint32_t inner = 0, removed_boundary = 0;
  TetId start{};
  int start_face = 0;
  for (TetId t : removed_at_v) {
    const int lv = mesh.local_index(t, v);
    for (int f = 0; f < 4; ++f) {
      if (f == lv) continue;
      const FaceRef n = mesh.neighbour(t, f);
      if (!n.valid()) {
        ++removed_boundary;
      } else if (!marked(n.tet)) {
        if (inner++ == 0) {
          start = n.tet;
          start_face = n.face;
        }
      }
    }
  }
  const std::uint32_t kept_boundary = mesh.boundary_face_count(v) - removed_boundary;
  // No interface inside the link: nothing stays (a kept part would border the removed one).
  if (inner == 0) return kept_boundary == 0;
  const std::uint32_t interface = inner + kept_boundary;

  // Walk the circle through the start edge, keeping the removed side on one hand. State: kept
  // tet u, the link edge (from, pivot) just followed; turn around the mesh edge (v, pivot)
  // through kept tets until the next face at v has a removed tet or nothing behind it.
  const std::array<VertId, 4> sv = mesh.tet(start);
  VertId from{}, pivot{};
  for (int i = 0; i < 4; ++i) {
    if (i == start_face || sv[i] == v) continue;
    (from.valid() ? pivot : from) = sv[i];
  }
  TetId u = start;
  std::uint32_t followed = 1;
  // A valid mesh closes the circle within a few turns per edge; the bound only guards the loop.
  for (std::uint32_t steps = 0; steps < 64u * interface + 1024u; ++steps) {
    const int face = mesh.local_index(u, from);  // the face of u at v and pivot, away from `from`
    const FaceRef n = mesh.neighbour(u, face);
    if (!n.valid() || marked(n.tet)) {
      // An interface edge (pivot, next): follow it.
      if (u == start && face == start_face) return followed == interface;
      ++followed;
      VertId next{};
      for (int i = 0; i < 4; ++i) {
        const VertId w = mesh.vertex(u, i);
        if (w != v && w != pivot && w != from) next = w;
      }
      from = pivot;
      pivot = next;
      continue;
    }
    // Kept tet behind: turn into it around (v, pivot); the face we entered by holds `from`'s
    // replacement, the vertex of the entry face other than v and pivot.
    VertId entry_other{};
    for (int i = 0; i < 4; ++i) {
      if (i == face) continue;
      const VertId w = mesh.vertex(u, i);
      if (w != v && w != pivot) entry_other = w;
    }
    u = n.tet;
    from = entry_other;
  }
  return false;
}

bool SetRemovalWorkspace::edge_ok(const TetMesh& mesh, TetId t, int local_edge) {
  const bool open = mesh.edge_shell(t, local_edge, ring_);
  const std::size_t n = ring_.size();
  // Count runs of unmarked tets: a run starts at an unmarked tet whose predecessor is marked
  // (or, on an open ring, at the first tet).
  int runs = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (marked(ring_[i])) continue;
    const bool starts = open ? (i == 0 || marked(ring_[i - 1])) : marked(ring_[(i + n - 1) % n]);
    runs += starts;
  }
  return runs <= 1;
}

SetRemovalCheck SetRemovalWorkspace::check(const TetMesh& mesh, std::span<const TetId> set) {
  mark(mesh, set);
  SetRemovalCheck result;

  edges_seen_.clear();
  for (TetId t : set) {
    for (int e = 0; e < 6; ++e) {
      const VertId a = mesh.vertex(t, kEdgeVerts[e][0]), b = mesh.vertex(t, kEdgeVerts[e][1]);
      if (!edges_seen_.insert(a, b)) continue;
      if (!edge_ok(mesh, t, e)) {
        result.ok = false;
        result.kind = SingularityKind::kEdge;
        result.edge = {a, b};
        result.tet = t;
        result.local_edge = static_cast<std::uint8_t>(e);
        return result;
      }
    }
  }

  // Vertex by vertex, with the set's tets at each (a tet listed twice counts once).
  at_vertex_.clear();
  for (TetId t : set)
    for (int i = 0; i < 4; ++i) at_vertex_.push_back({mesh.vertex(t, i).value, t.value});
  std::sort(at_vertex_.begin(), at_vertex_.end());
  at_vertex_.erase(std::unique(at_vertex_.begin(), at_vertex_.end()), at_vertex_.end());
  for (std::size_t i = 0; i < at_vertex_.size();) {
    std::size_t j = i;
    group_.clear();
    while (j < at_vertex_.size() && at_vertex_[j].first == at_vertex_[i].first) group_.push_back(TetId{at_vertex_[j++].second});
    const VertId v{at_vertex_[i].first};
    if (!vertex_ok(mesh, v, group_)) {
      result.ok = false;
      result.kind = SingularityKind::kVertex;
      result.vertex = v;
      result.tet = group_.front();
      return result;
    }
    i = j;
  }
  return result;
}

void SetRemovalWorkspace::remaining_components(const TetMesh& mesh, VertId v, TetId seed,
                                               std::vector<TetId>& tets,
                                               std::vector<std::uint32_t>& sizes) {
  grow(mesh);
  collect_shell(mesh, v, seed);
  const std::uint32_t g = next_gen(visit_stamp_, visit_gen_);
  for (TetId start : shell_) {
    if (marked(start) || visit_stamp_[start.value] == g) continue;
    const std::size_t begin = tets.size();
    tets.push_back(start);
    visit_stamp_[start.value] = g;
    for (std::size_t i = begin; i < tets.size(); ++i)
      visit_fresh_shell_neighbours(mesh, v, tets[i], g, [&](TetId n) { tets.push_back(n); });
    sizes.push_back(static_cast<std::uint32_t>(tets.size() - begin));
  }
}

bool SetRemovalWorkspace::path_to_border(const TetMesh& mesh, VertId v, TetId seed, int max_depth,
                                         std::vector<TetId>& out) {
  grow(mesh);
  collect_shell(mesh, v, seed);
  const std::uint32_t g = next_gen(visit_stamp_, visit_gen_);
  queue_.clear();
  depth_.clear();
  auto has_border_face = [&](TetId t) {
    const int lv = mesh.local_index(t, v);
    for (int f = 0; f < 4; ++f)
      if (f != lv && mesh.is_boundary_face(t, f)) return true;
    return false;
  };
  for (TetId t : shell_) {
    if (!marked(t)) continue;
    if (has_border_face(t)) return true;  // the hole already opens onto the surface
    visit_stamp_[t.value] = g;
    parent_[t.value] = TetId{}.value;
    queue_.push_back(t);
    depth_.push_back(0);
  }
  for (std::size_t i = 0; i < queue_.size(); ++i) {
    const TetId cur = queue_[i];
    const int d = depth_[i];
    if (d > 0 && has_border_face(cur)) {
      const std::size_t begin = out.size();
      for (TetId p = cur; !marked(p); p = TetId{parent_[p.value]}) out.push_back(p);
      std::reverse(out.begin() + static_cast<std::ptrdiff_t>(begin), out.end());
      return true;
    }
    if (d >= max_depth) continue;
    visit_fresh_shell_neighbours(mesh, v, cur, g, [&](TetId n) {
      parent_[n.value] = cur.value;
      queue_.push_back(n);
      depth_.push_back(static_cast<std::uint8_t>(d + 1));
    });
  }
  return false;
}

void SetRemovalWorkspace::remaining_runs(const TetMesh& mesh, TetId seed, int local_edge,
                                         std::vector<TetId>& tets, std::vector<std::uint32_t>& sizes) {
  grow(mesh);
  const bool open = mesh.edge_shell(seed, local_edge, ring_);
  const std::size_t n = ring_.size();
  // On a closed ring start right after a marked tet so that no run is cut in two.
  std::size_t start = 0;
  if (!open) {
    for (std::size_t i = 0; i < n; ++i)
      if (marked(ring_[i])) {
        start = (i + 1) % n;
        break;
      }
  }
  bool in_run = false;
  std::size_t begin = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const TetId t = ring_[(start + k) % n];
    if (marked(t)) {
      if (in_run) sizes.push_back(static_cast<std::uint32_t>(tets.size() - begin));
      in_run = false;
      continue;
    }
    if (!in_run) {
      in_run = true;
      begin = tets.size();
    }
    tets.push_back(t);
  }
  if (in_run) sizes.push_back(static_cast<std::uint32_t>(tets.size() - begin));
}

}  // namespace tetcut
