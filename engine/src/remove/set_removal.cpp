#include "remove/set_removal.hpp"

#include <algorithm>
#include <cassert>
#include <utility>

#include "tetcut/detail/local_tables.hpp"
#include "tetcut/detail/reserve_touched.hpp"

namespace tetcut {
void SetRemovalWorkspace::reserve(std::uint32_t tets, std::uint32_t vertices) {
  marked_.reserve(tets);
  in_shell_.reserve(tets);
  visited_.reserve(tets);
  bfs_parent_.reserve(tets);
  walked_.reserve(vertices);
  vertex_slot_.reserve(vertices);
  for (auto* v : {&shell_, &queue_, &ring_, &distinct_, &at_vertex_}) detail::reserve_touched(*v, 2048);
  detail::reserve_touched(depth_, 512);
  detail::reserve_touched(set_vertices_, 2048);
  detail::reserve_touched(vertex_begin_, 2048);
  detail::reserve_touched(vertex_changed_, 2048);
}

void SetRemovalWorkspace::mark(const TetMesh&, std::span<const TetId> set) {
  marked_.clear();
  for (TetId t : set) marked_.insert(t);
}

void SetRemovalWorkspace::collect_shell(const TetMesh& mesh, VertId v, TetId seed) {
  in_shell_.clear();
  shell_.clear();
  shell_.push_back(seed);
  in_shell_.insert(seed);
  for (std::size_t i = 0; i < shell_.size(); ++i) {
    const TetId cur = shell_[i];
    const int lv = mesh.local_index(cur, v);
    assert(lv >= 0);
    for (int f = 0; f < 4; ++f) {
      if (f == lv) continue;
      const FaceRef n = mesh.neighbour(cur, f);
      if (!n.valid() || !in_shell_.insert(n.tet)) continue;
      shell_.push_back(n.tet);
    }
  }
}

template <class Visit>
void SetRemovalWorkspace::visit_fresh_shell_neighbours(const TetMesh& mesh, VertId v, TetId cur, Visit&& visit) {
  const int lv = mesh.local_index(cur, v);
  for (int f = 0; f < 4; ++f) {
    if (f == lv) continue;
    const FaceRef n = mesh.neighbour(cur, f);
    if (!n.valid() || marked(n.tet) || !visited_.insert(n.tet)) continue;
    visit(n.tet);
  }
}

// The link of v is a disk (v on the surface) or a sphere; the set's tets at v are triangles of
// it, the kept tets at v the kept region K of the link. The interface between K and what goes
// (the boundary faces of the mesh count as "goes": the link's own border is glued to a removed
// cell) is the boundary of K. Both I5 at v and I6 at every edge (v, w) hold after the removal
// iff K is empty or a disk: the kept tets around (v, w) are the triangles of K at the link
// vertex w, one run iff one fan. The test walks the boundary of K from one interface edge,
// keeping K on one hand, and accepts iff the walk comes back having followed every interface
// edge and passed no link vertex twice: then the boundary is one simple closed curve, and by
// Jordan-Schoenflies K is a disk (docs/removal-proof.md, "The set test"). A link vertex met
// twice is a pinch of K, that is two runs of kept tets around the edge (v, w): it is reported
// as that edge. Everything is local: the set's faces at v, the vertex's boundary face count,
// and the turns of one walk; never the whole shell.
SetRemovalWorkspace::VertexVerdict SetRemovalWorkspace::vertex_ok(const TetMesh& mesh, VertId v,
                                                                  std::span<const TetId> removed_at_v) {
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
  if (inner == 0) return {kept_boundary == 0, VertId{}};
  const std::uint32_t interface = inner + kept_boundary;

  // Walk the boundary of K through the start edge, keeping the removed side on one hand. State:
  // kept tet u, the link edge (from, pivot) just followed; turn around the mesh edge (v, pivot)
  // through kept tets until the next face at v has a removed tet or nothing behind it.
  const std::array<VertId, 4> sv = mesh.tet(start);
  VertId from{}, pivot{};
  for (int i = 0; i < 4; ++i) {
    if (i == start_face || sv[i] == v) continue;
    (from.valid() ? pivot : from) = sv[i];
  }
  // Every link vertex the walk reaches is stamped when it becomes the pivot; `from` becomes the
  // pivot last, the one whose turn leads back onto the start edge.
  walked_.clear();
  walked_.insert(pivot);
  TetId u = start;
  std::uint32_t followed = 1;
  // A valid mesh closes the walk within a few turns per edge; the bound only guards the loop.
  for (std::uint32_t steps = 0; steps < 64u * interface + 1024u; ++steps) {
    const TetMesh::TetVerts uv = mesh.tet(u);
    int face = 0;  // the face of u at v and pivot, away from `from`
    while (face < 3 && uv[face] != from) ++face;
    // u's fourth vertex besides v, pivot and from (all four are distinct): on the interface the
    // next link vertex, else the vertex of the entry face that takes `from`'s place.
    const VertId fourth{uv[0].value ^ uv[1].value ^ uv[2].value ^ uv[3].value ^ v.value ^ pivot.value ^ from.value};
    const FaceRef n = mesh.neighbour(u, face);
    if (!n.valid() || marked(n.tet)) {
      // An interface edge (pivot, fourth): follow it.
      if (u == start && face == start_face) return {followed == interface, VertId{}};
      ++followed;
      if (!walked_.insert(fourth)) return {false, fourth};  // K pinched there
      from = pivot;
      pivot = fourth;
      continue;
    }
    // Kept tet behind: turn into it around (v, pivot), entering by the face (v, pivot, fourth).
    u = n.tet;
    from = fourth;
  }
  return {false, VertId{}};
}

Removability SetRemovalWorkspace::check(const TetMesh& mesh, std::span<const TetId> set, TestedPrefix prefix) {
  // Marks the set and groups its tets by vertex in two linear passes (a bucket per vertex, in
  // the order the set first names them), rather than sorting (vertex, tet) pairs: the test runs
  // for every candidate set, and the grouping would otherwise be much of its cost.
  marked_.clear();
  vertex_slot_.clear();
  distinct_.clear();
  set_vertices_.clear();
  vertex_begin_.clear();
  vertex_changed_.clear();
  for (std::size_t k = 0; k < set.size(); ++k) {
    const TetId t = set[k];
    if (!marked_.insert(t)) continue;  // a tet listed twice counts once
    distinct_.push_back(t);
    const bool added = k >= prefix.tets;
    for (VertId v : mesh.tet(t)) {
      if (!vertex_slot_.contains(v)) {
        vertex_slot_.set(v, static_cast<std::uint32_t>(set_vertices_.size()));
        set_vertices_.push_back(v);
        vertex_begin_.push_back(0);
        vertex_changed_.push_back(0);
      }
      const std::uint32_t slot = *vertex_slot_.find(v);
      ++vertex_begin_[slot];  // a count for now
      vertex_changed_[slot] |= static_cast<std::uint8_t>(added);
    }
  }
  std::uint32_t offset = 0;
  for (std::uint32_t& b : vertex_begin_) offset += std::exchange(b, offset);
  at_vertex_.resize(offset);
  for (TetId t : distinct_)
    for (VertId v : mesh.tet(t)) at_vertex_[vertex_begin_[*vertex_slot_.find(v)]++] = t;
  // Each begin now holds its end; the first vertex begins at 0.
  for (std::size_t i = 0; i < set_vertices_.size(); ++i) {
    const std::uint32_t begin = i == 0 ? 0 : vertex_begin_[i - 1];
    const std::span<const TetId> group(at_vertex_.data() + begin, vertex_begin_[i] - begin);
    const VertId v = set_vertices_[i];
    if (i < prefix.vertices && !vertex_changed_[i]) {
      assert(vertex_ok(mesh, v, group).ok && "a vertex of the tested prefix passes again");
      continue;
    }
    const VertexVerdict verdict = vertex_ok(mesh, v, group);
    if (verdict.ok) continue;
    Removability result = offence(mesh, v, group, verdict);
    result.vertices_passed = static_cast<std::uint32_t>(i);
    return result;
  }
  Removability result;
  result.vertices_passed = static_cast<std::uint32_t>(set_vertices_.size());
  return result;
}

Removability SetRemovalWorkspace::offence(const TetMesh& mesh, VertId v, std::span<const TetId> removed_at_v,
                                             const VertexVerdict& verdict) {
  Removability result;
  result.tet = removed_at_v.front();
  if (!verdict.pinched.valid()) {
    result.kind = SingularityKind::kVertex;
    result.vertex = v;
    return result;
  }
  // Two runs of kept tets around (v, pinched): named from a removed tet on that edge (there is
  // one, or its ring would be whole: one run).
  result.kind = SingularityKind::kEdge;
  for (TetId t : removed_at_v) {
    const int lw = mesh.local_index(t, verdict.pinched);
    if (lw < 0) continue;
    const int e = kEdgeIndex[mesh.local_index(t, v)][lw];
    result.tet = t;
    result.local_edge = static_cast<std::uint8_t>(e);
    result.edge = {mesh.vertex(t, kEdgeVerts[e][0]), mesh.vertex(t, kEdgeVerts[e][1])};
    return result;
  }
  assert(false && "a pinched link vertex lies on a removed tet at v");
  return result;
}

Removability SetRemovalWorkspace::check_at(const TetMesh& mesh, std::span<const TetId> set, VertId v) {
  mark(mesh, set);
  // The set's distinct tets at v (a tet listed twice counts once).
  visited_.clear();
  at_vertex_.clear();
  for (TetId t : set)
    if (mesh.local_index(t, v) >= 0 && visited_.insert(t)) at_vertex_.push_back(t);
  Removability result;
  if (at_vertex_.empty()) return result;
  const VertexVerdict verdict = vertex_ok(mesh, v, at_vertex_);
  if (!verdict.ok) result = offence(mesh, v, at_vertex_, verdict);
  return result;
}

void SetRemovalWorkspace::remaining_components(const TetMesh& mesh, VertId v, TetId seed,
                                               std::vector<TetId>& tets,
                                               std::vector<std::uint32_t>& sizes) {
  collect_shell(mesh, v, seed);
  visited_.clear();
  for (TetId start : shell_) {
    if (marked(start) || !visited_.insert(start)) continue;
    const std::size_t begin = tets.size();
    tets.push_back(start);
    for (std::size_t i = begin; i < tets.size(); ++i)
      visit_fresh_shell_neighbours(mesh, v, tets[i], [&](TetId n) { tets.push_back(n); });
    sizes.push_back(static_cast<std::uint32_t>(tets.size() - begin));
  }
}

void SetRemovalWorkspace::remaining_pieces(const TetMesh& mesh, const Removability& offence,
                                           std::vector<TetId>& tets, std::vector<std::uint32_t>& sizes) {
  if (offence.kind == SingularityKind::kVertex) {
    remaining_components(mesh, offence.vertex, offence.tet, tets, sizes);
  } else if (offence.kind == SingularityKind::kEdge) {
    remaining_runs(mesh, offence.tet, offence.local_edge, tets, sizes);
  }
}

// The breadth-first search both path queries run (paper 3.5): from the marked tets around v,
// through unmarked tets around v, at most max_depth steps. Each tet reached with a border face
// through v goes to at_border(), which returns true to stop the search; a border tet is not
// walked through. True when stopped, or at once (nothing reported) when a marked tet already
// has a border face through v.
template <class AtBorder>
bool SetRemovalWorkspace::search_to_border(const TetMesh& mesh, VertId v, TetId seed, int max_depth, AtBorder&& at_border) {
  collect_shell(mesh, v, seed);
  visited_.clear();
  bfs_parent_.clear();
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
    visited_.insert(t);
    queue_.push_back(t);
    depth_.push_back(0);
  }
  for (std::size_t i = 0; i < queue_.size(); ++i) {
    const TetId cur = queue_[i];
    const int d = depth_[i];
    if (d > 0 && has_border_face(cur)) {
      if (at_border(cur)) return true;
      continue;
    }
    if (d >= max_depth) continue;
    visit_fresh_shell_neighbours(mesh, v, cur, [&](TetId n) {
      bfs_parent_.set(n, cur);
      queue_.push_back(n);
      depth_.push_back(static_cast<std::uint8_t>(d + 1));
    });
  }
  return false;
}

bool SetRemovalWorkspace::path_to_border(const TetMesh& mesh, VertId v, TetId seed, int max_depth,
                                         std::vector<TetId>& out) {
  return search_to_border(mesh, v, seed, max_depth, [&](TetId end) {
    border_path(end, out);
    return true;  // the nearest border tet ends the search
  });
}

bool SetRemovalWorkspace::border_paths(const TetMesh& mesh, VertId v, TetId seed, int max_depth,
                                       std::vector<TetId>& ends) {
  ends.clear();
  const bool opens = search_to_border(mesh, v, seed, max_depth, [&](TetId end) {
    ends.push_back(end);
    return false;
  });
  return opens || !ends.empty();
}

void SetRemovalWorkspace::border_path(TetId end, std::vector<TetId>& out) const {
  // The start tets were reached from nowhere: the walk back stops at them.
  const std::size_t begin = out.size();
  for (TetId p = end; bfs_parent_.contains(p); p = bfs_parent_.get(p, kNoTet)) out.push_back(p);
  std::reverse(out.begin() + static_cast<std::ptrdiff_t>(begin), out.end());
}

void SetRemovalWorkspace::remaining_runs(const TetMesh& mesh, TetId seed, int local_edge,
                                         std::vector<TetId>& tets, std::vector<std::uint32_t>& sizes) {
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
