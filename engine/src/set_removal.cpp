#include "tetcut/set_removal.hpp"

#include <algorithm>
#include <cassert>

#include "tetcut/local_tables.hpp"

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
  if (vert_stamp_.size() < mesh.vertex_capacity()) {
    const std::size_t n = mesh.vertex_capacity() + mesh.vertex_capacity() / 4 + 16;
    vert_stamp_.resize(n, 0);
    link_stamp_.resize(n, 0);
  }
}

void SetRemovalWorkspace::reserve(std::uint32_t tets, std::uint32_t vertices) {
  if (set_stamp_.size() < tets) {
    set_stamp_.resize(tets, 0);
    shell_stamp_.resize(tets, 0);
    visit_stamp_.resize(tets, 0);
    parent_.resize(tets, 0);
  }
  if (vert_stamp_.size() < vertices) {
    vert_stamp_.resize(vertices, 0);
    link_stamp_.resize(vertices, 0);
  }
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

bool SetRemovalWorkspace::vertex_ok(const TetMesh& mesh, VertId v, TetId seed) {
  collect_shell(mesh, v, seed);
  // F: remaining tets; Eb: their faces through v with no remaining tet behind; V: link vertices.
  std::uint32_t f_count = 0, open_faces = 0, v_count = 0;
  TetId first{};
  const std::uint32_t lg = next_gen(link_stamp_, link_gen_);
  for (TetId t : shell_) {
    if (marked(t)) continue;
    if (!first.valid()) first = t;
    ++f_count;
    const int lv = mesh.local_index(t, v);
    for (int i = 0; i < 4; ++i) {
      if (i == lv) continue;
      const VertId w = mesh.vertex(t, i);
      if (link_stamp_[w.value] != lg) {
        link_stamp_[w.value] = lg;
        ++v_count;
      }
      const FaceRef n = mesh.neighbour(t, i);
      if (!n.valid() || marked(n.tet)) ++open_faces;
    }
  }
  if (f_count == 0) return true;  // the vertex goes with the set

  // Face-connected? Breadth-first through unmarked tets only.
  const std::uint32_t g = next_gen(visit_stamp_, visit_gen_);
  queue_.clear();
  queue_.push_back(first);
  visit_stamp_[first.value] = g;
  for (std::size_t i = 0; i < queue_.size(); ++i) {
    const TetId cur = queue_[i];
    const int lv = mesh.local_index(cur, v);
    for (int f = 0; f < 4; ++f) {
      if (f == lv) continue;
      const FaceRef n = mesh.neighbour(cur, f);
      if (!n.valid() || marked(n.tet) || visit_stamp_[n.tet.value] == g) continue;
      visit_stamp_[n.tet.value] = g;
      queue_.push_back(n.tet);
    }
  }
  if (queue_.size() != f_count) return false;

  // Each remaining tet has 3 link edges; interior ones are shared by two tets.
  const std::uint32_t e_count = (3 * f_count + open_faces) / 2;
  const std::int64_t chi = static_cast<std::int64_t>(v_count) - e_count + f_count;
  return chi == 1;
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

  const std::uint32_t vg = next_gen(vert_stamp_, vert_gen_);
  for (TetId t : set) {
    for (int i = 0; i < 4; ++i) {
      const VertId v = mesh.vertex(t, i);
      if (vert_stamp_[v.value] == vg) continue;
      vert_stamp_[v.value] = vg;
      if (!vertex_ok(mesh, v, t)) {
        result.ok = false;
        result.kind = SingularityKind::kVertex;
        result.vertex = v;
        result.tet = t;
        return result;
      }
    }
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
    for (std::size_t i = begin; i < tets.size(); ++i) {
      const TetId cur = tets[i];
      const int lv = mesh.local_index(cur, v);
      for (int f = 0; f < 4; ++f) {
        if (f == lv) continue;
        const FaceRef n = mesh.neighbour(cur, f);
        if (!n.valid() || marked(n.tet) || visit_stamp_[n.tet.value] == g) continue;
        visit_stamp_[n.tet.value] = g;
        tets.push_back(n.tet);
      }
    }
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
    const int lv = mesh.local_index(cur, v);
    for (int f = 0; f < 4; ++f) {
      if (f == lv) continue;
      const FaceRef n = mesh.neighbour(cur, f);
      if (!n.valid() || marked(n.tet) || visit_stamp_[n.tet.value] == g) continue;
      visit_stamp_[n.tet.value] = g;
      parent_[n.tet.value] = cur.value;
      queue_.push_back(n.tet);
      depth_.push_back(static_cast<std::uint8_t>(d + 1));
    }
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
