// TetMesh's queries (the mesh itself: include/tetcut/mesh.hpp): shells around edges and vertices,
// boundary faces and normals, volumes and lengths. Mutations are in mesh_mutation.cpp, the
// journal that undoes them in mesh_journal.cpp.
#include "tetcut/mesh.hpp"

#include <algorithm>
#include <bit>
#include <cassert>
#include <cstring>

#include "tetcut/detail/local_tables.hpp"
#include "tetcut/predicates.hpp"

namespace tetcut {
namespace {

bool contains(const std::vector<TetId>& tets, TetId t) {
  return std::find(tets.begin(), tets.end(), t) != tets.end();
}

}  // namespace

// Rotation about an edge (style: CGAL's next_around_edge). We enter a tet through one of the two
// faces containing the edge; we leave through the other one.
namespace {
struct EdgeWalker {
  const std::vector<std::array<std::uint32_t, 4>>& verts;
  const std::vector<std::array<std::uint32_t, 4>>& adj;
  std::uint32_t a, b;

  // The face of t, other than `entered`, that contains edge (a, b).
  int exit_face(std::uint32_t t, int entered) const {
    int la = 0, lb = 0;
    for (int i = 0; i < 4; ++i) {
      if (verts[t][i] == a) la = i;
      if (verts[t][i] == b) lb = i;
    }
    const std::uint8_t e = kEdgeIndex[la][lb];
    return kEdgeFaces[e][0] == entered ? kEdgeFaces[e][1] : kEdgeFaces[e][0];
  }
};
}  // namespace

EdgeRef TetMesh::find_edge(VertId a, VertId b, TetId hint, std::vector<TetId>& shell_scratch) const {
  if (is_live(hint))
    if (const int e = local_edge(hint, a, b); e >= 0) return {hint, static_cast<std::uint8_t>(e)};
  if (!is_live(a)) return {};
  vertex_shell(a, shell_scratch);
  for (TetId t : shell_scratch)
    if (const int e = local_edge(t, a, b); e >= 0) return {t, static_cast<std::uint8_t>(e)};
  return {};
}

bool TetMesh::is_boundary_edge(TetId t, int local_edge) const {
  EdgeWalker walk{tet_verts_, tet_adj_, tet_verts_[t.value][kEdgeVerts[local_edge][0]],
                  tet_verts_[t.value][kEdgeVerts[local_edge][1]]};
  std::uint32_t cur = t.value;
  int face = kEdgeFaces[local_edge][0];
  // A manifold edge shell closes or ends; the bound only guards against corrupted adjacency.
  for (std::uint32_t steps = 0; steps <= tet_capacity(); ++steps) {
    const std::uint32_t adj = tet_adj_[cur][face];
    if (adj == kNoNeighbour) return true;
    cur = adj >> 2;
    if (cur == t.value) return false;
    face = walk.exit_face(cur, static_cast<int>(adj & 3u));
  }
  assert(false && "edge walk did not terminate: corrupted adjacency");
  return true;
}

bool TetMesh::edge_shell(TetId t, int local_edge, std::vector<TetId>& out) const {
  out.clear();
  EdgeWalker walk{tet_verts_, tet_adj_, tet_verts_[t.value][kEdgeVerts[local_edge][0]],
                  tet_verts_[t.value][kEdgeVerts[local_edge][1]]};
  // First direction: out of face kEdgeFaces[e][1]; collected backwards, then reversed, so that
  // the result reads from one end (boundary face) through t to the other.
  std::uint32_t cur = t.value;
  int face = kEdgeFaces[local_edge][1];
  bool open = false;
  for (std::uint32_t steps = 0; steps <= tet_capacity(); ++steps) {
    const std::uint32_t adj = tet_adj_[cur][face];
    if (adj == kNoNeighbour) {
      open = true;
      break;
    }
    cur = adj >> 2;
    if (cur == t.value) break;
    out.push_back(TetId{cur});
    face = walk.exit_face(cur, static_cast<int>(adj & 3u));
  }
  if (!open) {
    // Closed ring: t first, then the ring in the direction walked.
    out.insert(out.begin(), t);
    return false;
  }
  std::reverse(out.begin(), out.end());
  out.push_back(t);
  cur = t.value;
  face = kEdgeFaces[local_edge][0];
  for (std::uint32_t steps = 0; steps <= tet_capacity(); ++steps) {
    const std::uint32_t adj = tet_adj_[cur][face];
    if (adj == kNoNeighbour) break;
    cur = adj >> 2;
    out.push_back(TetId{cur});
    face = walk.exit_face(cur, static_cast<int>(adj & 3u));
  }
  return true;
}

void TetMesh::vertex_shell(VertId v, std::vector<TetId>& out) const {
  out.clear();
  const TetId seed = vert_tet_[v.value];
  if (!seed.valid()) return;
  out.push_back(seed);
  // Breadth-first through the faces that contain v: in a manifold mesh they connect the shell.
  for (std::size_t i = 0; i < out.size(); ++i) {
    const TetId cur = out[i];
    const int lv = local_index(cur, v);
    for (int f = 0; f < 4; ++f) {
      if (f == lv) continue;
      const std::uint32_t adj = tet_adj_[cur.value][f];
      if (adj == kNoNeighbour) continue;
      const TetId next{adj >> 2};
      if (!contains(out, next)) out.push_back(next);
    }
  }
}

void TetMesh::vertex_neighbours(VertId v, std::vector<VertId>& out, std::vector<TetId>& shell_scratch) const {
  vertex_shell(v, shell_scratch);
  out.clear();
  for (TetId t : shell_scratch)
    for (std::uint32_t w : tet_verts_[t.value])
      if (w != v.value && std::find(out.begin(), out.end(), VertId{w}) == out.end()) out.push_back(VertId{w});
}

void TetMesh::boundary_faces(std::vector<FaceRef>& out) const {
  out.clear();
  for (std::uint32_t t = 0; t < tet_capacity(); ++t) {
    if (tet_verts_[t][0] == kDeadTetMarker) continue;
    for (int f = 0; f < 4; ++f)
      if (tet_adj_[t][f] == kNoNeighbour) out.push_back({TetId{t}, static_cast<std::uint8_t>(f)});
  }
}

Vec3 TetMesh::boundary_normal(VertId v) const {
  std::vector<TetId> shell;
  return boundary_normal(v, shell);
}

Vec3 TetMesh::boundary_normal(VertId v, std::vector<TetId>& shell_scratch) const {
  if (!is_live(v) || !is_boundary_vertex(v)) return {};
  vertex_shell(v, shell_scratch);
  Vec3 sum{};
  for (TetId t : shell_scratch) {
    const int lv = local_index(t, v);
    const auto& verts = tet_verts_[t.value];
    for (int f = 0; f < 4; ++f) {
      if (f == lv || tet_adj_[t.value][f] != kNoNeighbour) continue;
      const Vec3& p = positions_[verts[kFaceVerts[f][0]]];
      const Vec3& q = positions_[verts[kFaceVerts[f][1]]];
      const Vec3& r = positions_[verts[kFaceVerts[f][2]]];
      sum = sum + cross(q - p, r - p);  // twice the area times the outward unit normal
    }
  }
  const double len = norm(sum);
  return len > 0.0 ? (1.0 / len) * sum : Vec3{};
}

double TetMesh::volume(TetId t) const {
  const auto& v = tet_verts_[t.value];
  return signed_volume(positions_[v[0]], positions_[v[1]], positions_[v[2]], positions_[v[3]]);
}

double TetMesh::mean_edge_length() const {
  double sum = 0.0;
  std::uint64_t n = 0;
  for (std::uint32_t t = 0; t < tet_capacity(); ++t) {
    if (!is_live(TetId{t})) continue;
    for (int e = 0; e < 6; ++e) {
      sum += norm(position(vertex(TetId{t}, kEdgeVerts[e][1])) - position(vertex(TetId{t}, kEdgeVerts[e][0])));
      ++n;
    }
  }
  return n > 0 && sum > 0 ? sum / static_cast<double>(n) : 1.0;
}

double TetMesh::total_volume() const {
  double sum = 0.0;
  for (std::uint32_t t = 0; t < tet_capacity(); ++t)
    if (tet_verts_[t][0] != kDeadTetMarker) sum += volume(TetId{t});
  return sum;
}

RawMesh TetMesh::to_raw() const {
  RawMesh raw;
  std::vector<std::uint32_t> new_id(vertex_capacity(), kDeadTetMarker);
  raw.positions.reserve(live_vertices_);
  for (std::uint32_t v = 0; v < vertex_capacity(); ++v)
    if (vert_tet_[v].valid()) {
      new_id[v] = static_cast<std::uint32_t>(raw.positions.size());
      raw.positions.push_back(positions_[v]);
    }
  raw.tets.reserve(live_tets_);
  for (const auto& t : tet_verts_)
    if (t[0] != kDeadTetMarker) raw.tets.push_back({new_id[t[0]], new_id[t[1]], new_id[t[2]], new_id[t[3]]});
  return raw;
}

std::size_t TetMesh::memory_bytes() const {
  return tet_verts_.capacity() * sizeof(tet_verts_[0]) + tet_adj_.capacity() * sizeof(tet_adj_[0]) +
         positions_.capacity() * sizeof(Vec3) + vert_tet_.capacity() * sizeof(TetId) +
         vert_boundary_faces_.capacity() * sizeof(std::uint32_t) + free_vert_next_.capacity() * sizeof(VertId);
}

}  // namespace tetcut
