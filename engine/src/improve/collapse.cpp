#include "improve/collapse.hpp"

#include <algorithm>
#include <cmath>

#include "core/quality.hpp"
#include "tetcut/detail/local_tables.hpp"
#include "tetcut/detail/reserve_touched.hpp"
#include "tetcut/predicates.hpp"

namespace tetcut::detail {
namespace {

template <class T>
bool has(const std::vector<T>& list, const T& x) {
  return std::find(list.begin(), list.end(), x) != list.end();
}

std::array<VertId, 2> sorted(VertId a, VertId b) { return a < b ? std::array<VertId, 2>{a, b} : std::array<VertId, 2>{b, a}; }
std::array<VertId, 3> sorted(VertId a, VertId b, VertId c) {
  std::array<VertId, 3> s{a, b, c};
  std::sort(s.begin(), s.end());
  return s;
}

// The link of x (its star's opposite triangles), split into vertices, edges and triangles; a
// boundary face (x, p, q) adds the edge (p, q) and the vertices p, q to `boundary_*` (the link
// of x in the surface: the cone over the boundary that makes Dey's condition hold on it).
void link(const TetMesh& mesh, VertId x, std::span<const TetId> star, std::vector<VertId>& near,
          std::vector<std::array<VertId, 2>>& edges, std::vector<std::array<VertId, 3>>& faces) {
  near.clear();
  edges.clear();
  faces.clear();
  for (TetId t : star) {
    const int lx = mesh.local_index(t, x);
    const VertId p = mesh.vertex(t, kFaceVerts[lx][0]), q = mesh.vertex(t, kFaceVerts[lx][1]), r = mesh.vertex(t, kFaceVerts[lx][2]);
    for (VertId y : {p, q, r})
      if (!has(near, y)) near.push_back(y);
    for (const auto& e : {sorted(p, q), sorted(q, r), sorted(r, p)})
      if (!has(edges, e)) edges.push_back(e);
    faces.push_back(sorted(p, q, r));
  }
}

// The boundary faces at x as the edges opposite x: its link in the surface.
void boundary_link(const TetMesh& mesh, VertId x, std::span<const TetId> star, std::vector<std::array<VertId, 2>>& out) {
  out.clear();
  for (TetId t : star) {
    const int lx = mesh.local_index(t, x);
    for (int f = 0; f < 4; ++f) {
      if (f == lx || !mesh.is_boundary_face(t, f)) continue;
      std::array<VertId, 2> e{};
      int k = 0;
      for (int i = 0; i < 3; ++i)
        if (const VertId y = mesh.vertex(t, kFaceVerts[f][i]); y != x) e[static_cast<std::size_t>(k++)] = y;
      out.push_back(sorted(e[0], e[1]));
    }
  }
}

}  // namespace

void Collapser::reserve() {
  for (auto* v : {&star_v_, &star_w_, &ring_}) reserve_touched(*v, 128);
  for (auto* v : {&near_v_, &near_w_}) reserve_touched(*v, 128);
  reserve_touched(edges_v_, 256);
  reserve_touched(edges_w_, 256);
  reserve_touched(faces_v_, 128);
  reserve_touched(faces_w_, 128);
  reserve_touched(surface_v_, 64);
  reserve_touched(surface_w_, 64);
}

int Collapser::boundary_planes(const TetMesh& mesh, VertId x, std::span<const TetId> star, std::array<Vec3, 3>& planes) const {
  int count = 0;
  for (TetId t : star) {
    const int lx = mesh.local_index(t, x);
    for (int f = 0; f < 4; ++f) {
      if (f == lx || !mesh.is_boundary_face(t, f)) continue;
      const Vec3 a = mesh.position(mesh.vertex(t, kFaceVerts[f][0]));
      Vec3 n = cross(mesh.position(mesh.vertex(t, kFaceVerts[f][1])) - a, mesh.position(mesh.vertex(t, kFaceVerts[f][2])) - a);
      n = (1.0 / norm(n)) * n;
      bool known = false;
      for (int k = 0; k < count; ++k) known = known || (norm(cross(planes[k], n)) <= 1e-9 && dot(planes[k], n) > 0);
      if (known) continue;
      if (count == 3) return 4;
      planes[count++] = n;
    }
  }
  return count;
}

Refusal Collapser::plan(const TetMesh& mesh, VertId v, VertId w, double margin, double to_beat, Plan& plan) {
  plan.start(Operator::kCollapse);
  if (v == w) return Refusal::kNotAnEdge;
  mesh.vertex_shell(v, star_v_);
  ring_.clear();
  for (TetId t : star_v_)
    if (mesh.local_index(t, w) >= 0) ring_.push_back(t);
  if (ring_.empty()) return Refusal::kNotAnEdge;

  // The surface keeps its shape.
  if (mesh.is_boundary_vertex(v)) {
    const TetId t = ring_.front();
    if (!mesh.is_boundary_edge(t, mesh.local_edge(t, v, w))) return Refusal::kSurfaceConstraint;
    std::array<Vec3, 3> planes{};
    const int count = boundary_planes(mesh, v, star_v_, planes);
    if (count == 2) {
      const Vec3 d = mesh.position(w) - mesh.position(v);
      for (int k = 0; k < 2; ++k)
        if (std::abs(dot(planes[k], d)) > 1e-9 * norm(d)) return Refusal::kSurfaceConstraint;
    } else if (count != 1) {
      return Refusal::kSurfaceConstraint;
    }
  }

  // The new tets: positive, and better than v's star.
  plan.removed.assign(star_v_.begin(), star_v_.end());
  for (TetId t : star_v_) {
    TetMesh::TetVerts q = mesh.tet(t);
    plan.worst_before = std::min(plan.worst_before, quality(mesh, q));
    if (mesh.local_index(t, w) >= 0) continue;
    q[static_cast<std::size_t>(mesh.local_index(t, v))] = w;
    if (orientation(mesh.position(q[0]), mesh.position(q[1]), mesh.position(q[2]), mesh.position(q[3])) <= 0)
      return Refusal::kInvertedChild;
    plan.worst_after = std::min(plan.worst_after, quality(mesh, q));
    if (plan.worst_after <= to_beat) return Refusal::kNotBetter;
    plan.added.push_back(q);
  }
  if (!(plan.worst_after > plan.worst_before * (1.0 + margin))) return Refusal::kNotBetter;

  // Dey's link condition, with the surface's cone: Lk(v) and Lk(w) meet in Lk(vw) only.
  mesh.vertex_shell(w, star_w_);
  link(mesh, v, star_v_, near_v_, edges_v_, faces_v_);
  link(mesh, w, star_w_, near_w_, edges_w_, faces_w_);
  auto ring_has = [&](VertId x) {
    return std::any_of(ring_.begin(), ring_.end(), [&](TetId t) { return mesh.local_index(t, x) >= 0; });
  };
  auto ring_has_edge = [&](VertId x, VertId y) {
    return std::any_of(ring_.begin(), ring_.end(), [&](TetId t) { return mesh.local_index(t, x) >= 0 && mesh.local_index(t, y) >= 0; });
  };
  for (VertId x : near_v_)
    if (x != w && has(near_w_, x) && !ring_has(x)) return Refusal::kLinkCondition;
  for (const auto& e : edges_v_)
    if (e[0] != w && e[1] != w && has(edges_w_, e) && !ring_has_edge(e[0], e[1])) return Refusal::kLinkCondition;
  for (const auto& f : faces_v_)
    if (has(faces_w_, f)) return Refusal::kLinkCondition;
  if (mesh.is_boundary_vertex(v) && mesh.is_boundary_vertex(w)) {
    // The cone over the surface: a vertex joined to both by boundary edges must be on a boundary
    // face with both, and no boundary edge of one's surface link may be in the other's (two
    // surface triangles would coincide).
    boundary_link(mesh, v, star_v_, surface_v_);
    boundary_link(mesh, w, star_w_, surface_w_);
    for (const auto& e : surface_v_) {
      if (e[0] == w || e[1] == w) continue;
      if (has(surface_w_, e)) return Refusal::kLinkCondition;
      for (VertId x : e) {
        const bool joined_to_w = std::any_of(surface_w_.begin(), surface_w_.end(), [&](const auto& f) { return f[0] == x || f[1] == x; });
        if (joined_to_w && !has(surface_v_, sorted(w, x))) return Refusal::kLinkCondition;
      }
    }
  }
  return Refusal::kNone;
}

}  // namespace tetcut::detail
