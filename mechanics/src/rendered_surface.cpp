#include "tetcut/mechanics/rendered_surface.hpp"

#include <algorithm>
#include <bit>
#include <cmath>

#include "tetcut/detail/local_tables.hpp"

namespace tetcut::mechanics {
namespace {

std::array<std::uint32_t, 3> sorted_key(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  std::array<std::uint32_t, 3> k{a, b, c};
  std::sort(k.begin(), k.end());
  return k;
}
// The index slot a triangle's probe starts at: a window of 2^kWindowShift slots per vertex id,
// the triangle's smallest vertex's (the other two pick the slot in it), so the triangles around
// the vertices a cut touches share cache lines and pages however large the mesh around them, as
// tensor_mass.cpp homes its edges (why: there). 16 slots per vertex: with 8, the lookups of the
// interior faces a cut removes (most of them, and they end only at an empty slot) ran long
// around the low ids Gmsh gives boundary vertices. reserve() sizes the index to every window.
constexpr unsigned kWindowShift = 4;
std::size_t triangle_home(const std::array<std::uint32_t, 3>& k) {
  const std::uint64_t x = (std::uint64_t{k[1]} * 0x9E3779B97F4A7C15ULL) ^ (std::uint64_t{k[2]} * 0xC2B2AE3D27D4EB4FULL);
  return (std::size_t{k[0]} << kWindowShift) + static_cast<std::size_t>(x >> (64 - kWindowShift));
}

}  // namespace

RenderedSurface::RenderedSurface(const TetMesh& mesh) {
  reserve(mesh.tet_capacity() + mesh.tet_capacity() / 2, mesh.vertex_capacity() + mesh.vertex_capacity() / 2);
  grow(mesh.tet_capacity(), mesh.vertex_capacity());
  for (std::uint32_t t = 0; t < mesh.tet_capacity(); ++t) {
    const TetId id{t};
    if (!mesh.is_live(id)) continue;
    const auto v = mesh.tet(id);
    tets_[t] = {v[0].value, v[1].value, v[2].value, v[3].value};
    for (int f = 0; f < 4; ++f)
      if (mesh.is_boundary_face(id, f)) insert(mesh, id, f);
  }
  changed_triangles_.clear();  // a copy starts from the whole surface, not from these
  changed_vertices_.clear();
}

void RenderedSurface::reserve(std::uint32_t tets, std::uint32_t vertices) {
  tets_.reserve(tets);
  normal_sum_.reserve(vertices);
  normal_scale_.reserve(vertices);
  vertex_triangles_.reserve(vertices);
  const std::size_t triangles = 2 * std::size_t{vertices};
  triangles_.reserve(triangles);
  free_triangles_.reserve(triangles);
  candidates_.reserve(4096);
  changed_triangles_.reserve(4096);
  changed_vertices_.reserve(4096);
  created_faces_.reserve(4096);
  shell_.reserve(256);
  const std::size_t slots = std::bit_ceil(std::max(2 * triangles, std::size_t{vertices} << kWindowShift));
  if (index_.size() < slots) grow_index(slots);
}

void RenderedSurface::grow(std::uint32_t tets, std::uint32_t vertices) {
  if (tets > tets_.size()) tets_.resize(tets, {kDead, kDead, kDead, kDead});
  if (vertices > normal_sum_.size()) {
    normal_sum_.resize(vertices);
    normal_scale_.resize(vertices, 0.0);
    vertex_triangles_.resize(vertices, 0);
  }
}

void RenderedSurface::grow_index(std::size_t capacity) {
  index_.assign(capacity, kEmpty);
  const std::size_t mask = capacity - 1;
  for (std::uint32_t s = 0; s < triangles_.size(); ++s) {
    const Triangle& t = triangles_[s];
    if (!t.v[0].valid()) continue;
    std::size_t h = triangle_home(sorted_key(t.v[0].value, t.v[1].value, t.v[2].value)) & mask;
    while (index_[h] != kEmpty) h = (h + 1) & mask;
    index_[h] = s;
  }
}

std::uint32_t RenderedSurface::find(const Key& key) const {
  const std::size_t mask = index_.size() - 1;
  for (std::size_t h = triangle_home(key) & mask; index_[h] != kEmpty; h = (h + 1) & mask) {
    const Triangle& t = triangles_[index_[h]];
    if (sorted_key(t.v[0].value, t.v[1].value, t.v[2].value) == key) return index_[h];
  }
  return kEmpty;
}

void RenderedSurface::account(const Triangle& t, double sign) {
  const double scale = norm(t.area_vector);
  for (VertId v : t.v) {
    changed_vertices_.push_back(v);
    normal_sum_[v.value] = normal_sum_[v.value] + sign * t.area_vector;
    normal_scale_[v.value] += sign * scale;
    if (sign > 0) {
      ++vertex_triangles_[v.value];
    } else if (--vertex_triangles_[v.value] == 0) {
      normal_sum_[v.value] = Vec3{};  // off the surface: exactly nothing
      normal_scale_[v.value] = 0.0;
    }
  }
}

void RenderedSurface::insert(const TetMesh& mesh, TetId tet, int face) {
  const auto& f = kFaceVerts[face];
  Triangle t;
  t.v = {mesh.vertex(tet, f[0]), mesh.vertex(tet, f[1]), mesh.vertex(tet, f[2])};
  const Vec3 &a = mesh.position(t.v[0]), &b = mesh.position(t.v[1]), &c = mesh.position(t.v[2]);
  t.area_vector = cross(b - a, c - a);
  if (2 * (live_triangles_ + 1) > index_.size()) grow_index(std::max<std::size_t>(16, 2 * index_.size()));
  std::uint32_t slot;
  if (!free_triangles_.empty()) {
    slot = free_triangles_.back();
    free_triangles_.pop_back();
  } else {
    slot = static_cast<std::uint32_t>(triangles_.size());
    triangles_.push_back({});
  }
  triangles_[slot] = t;
  changed_triangles_.push_back(slot);
  const std::size_t mask = index_.size() - 1;
  std::size_t h = triangle_home(sorted_key(t.v[0].value, t.v[1].value, t.v[2].value)) & mask;
  while (index_[h] != kEmpty) h = (h + 1) & mask;
  index_[h] = slot;
  ++live_triangles_;
  account(t, +1.0);
}

void RenderedSurface::erase(std::uint32_t slot) {
  const Triangle t = triangles_[slot];
  account(t, -1.0);
  const std::size_t mask = index_.size() - 1;
  auto home_of = [&](std::uint32_t s) {
    const Triangle& x = triangles_[s];
    return triangle_home(sorted_key(x.v[0].value, x.v[1].value, x.v[2].value)) & mask;
  };
  std::size_t hole = home_of(slot);
  while (index_[hole] != slot) hole = (hole + 1) & mask;
  // Backward-shift deletion (linear probing keeps no tombstones).
  for (std::size_t next = (hole + 1) & mask; index_[next] != kEmpty; next = (next + 1) & mask) {
    const std::size_t home = home_of(index_[next]);
    const bool stays = hole <= next ? (home > hole && home <= next) : (home > hole || home <= next);
    if (!stays) {
      index_[hole] = index_[next];
      hole = next;
    }
  }
  index_[hole] = kEmpty;
  triangles_[slot] = Triangle{{kNoVert, kNoVert, kNoVert}, Vec3{}};
  changed_triangles_.push_back(slot);
  free_triangles_.push_back(slot);
  --live_triangles_;
}

bool RenderedSurface::contains(const Triangle& t) const {
  const std::uint32_t slot = find(sorted_key(t.v[0].value, t.v[1].value, t.v[2].value));
  if (slot == kEmpty) return false;
  const auto& s = triangles_[slot].v;
  for (int r = 0; r < 3; ++r)
    if (s[0] == t.v[r] && s[1] == t.v[(r + 1) % 3] && s[2] == t.v[(r + 2) % 3]) return true;
  return false;
}

Vec3 RenderedSurface::normal(VertId v) const {
  const Vec3& s = normal_sum_[v.value];
  const double n = norm(s);
  return n > 0 ? (1.0 / n) * s : Vec3{};
}

std::uint32_t RenderedSurface::apply(const TetMesh& mesh, const ChangeLog& log) {
  const MeshReadScope reading(mesh, "RenderedSurface::apply()");
  changed_triangles_.clear();
  changed_vertices_.clear();
  grow(mesh.tet_capacity(), mesh.vertex_capacity());
  std::uint32_t unknown = 0;
  candidates_.clear();
  created_faces_.clear();
  // The removed tets' faces leave the surface. One that was interior may now be laid bare on an
  // untouched tet: a candidate.
  for (TetId t : log.removed) {
    auto& tv = tets_[t.value];
    if (tv[0] == kDead) {
      ++unknown;
      continue;
    }
    for (const auto& f : kFaceVerts) {
      const Key key = sorted_key(tv[f[0]], tv[f[1]], tv[f[2]]);
      if (const std::uint32_t slot = find(key); slot != kEmpty) {
        erase(slot);  // it was on the surface: nothing lies beyond it
      } else {
        candidates_.push_back(key);
      }
    }
    tv = {kDead, kDead, kDead, kDead};
  }
  // The created tets' boundary faces join it; an interior face of theirs that was on it leaves.
  for (const CreatedTet& c : log.created) {
    const auto v = mesh.tet(c.tet);
    tets_[c.tet.value] = {v[0].value, v[1].value, v[2].value, v[3].value};
    for (int face = 0; face < 4; ++face) {
      const auto& f = kFaceVerts[face];
      const Key key = sorted_key(v[f[0]].value, v[f[1]].value, v[f[2]].value);
      if (const std::uint32_t slot = find(key); slot != kEmpty) erase(slot);
      if (mesh.is_boundary_face(c.tet, face)) insert(mesh, c.tet, face);
      created_faces_.push_back(key);
    }
  }
  // A candidate twice is a face between two removed tets; one a created tet has is settled. The
  // rest face an untouched tet, found in the shell of their smallest vertex (sorted, so that
  // one shell serves all the faces around that vertex).
  std::sort(candidates_.begin(), candidates_.end());
  std::sort(created_faces_.begin(), created_faces_.end());
  VertId shell_of = kNoVert;
  for (std::size_t i = 0; i < candidates_.size(); ++i) {
    const Key& key = candidates_[i];
    if (i + 1 < candidates_.size() && candidates_[i + 1] == key) {
      ++i;
      continue;
    }
    if (std::binary_search(created_faces_.begin(), created_faces_.end(), key)) continue;
    const VertId a{key[0]}, b{key[1]}, c{key[2]};
    if (!mesh.is_live(a) || !mesh.is_live(b) || !mesh.is_live(c)) continue;
    if (shell_of != a) {
      mesh.vertex_shell(a, shell_);
      shell_of = a;
    }
    for (TetId t : shell_) {
      const int lb = mesh.local_index(t, b), lc = mesh.local_index(t, c);
      if (lb < 0 || lc < 0) continue;
      const int face = 6 - mesh.local_index(t, a) - lb - lc;
      if (mesh.is_boundary_face(t, face)) insert(mesh, t, face);
      break;
    }
  }
  return unknown;
}

}  // namespace tetcut::mechanics
