#include "tetcut/render/surface.hpp"

#include <algorithm>
#include <cmath>

#include "cut/spatial_index.hpp"
#include "tetcut/detail/local_tables.hpp"

namespace tetcut::render {
namespace {

// Relative tolerance of the on-the-original-surface test (see the header).
constexpr double kRelativeTolerance = 1e-9;

SurfaceTriangle face_triangle(const TetMesh& mesh, TetId t, int face) {
  const auto v = mesh.tet(t);
  return {mesh.position(v[kFaceVerts[face][0]]), mesh.position(v[kFaceVerts[face][1]]),
          mesh.position(v[kFaceVerts[face][2]]), false};
}

template <class Visit>
void for_each_boundary_face(const TetMesh& mesh, Visit&& visit) {
  for (std::uint32_t i = 0; i < mesh.tet_capacity(); ++i) {
    const TetId t{i};
    if (!mesh.is_live(t)) continue;
    for (int f = 0; f < 4; ++f)
      if (mesh.is_boundary_face(t, f)) visit(t, f);
  }
}

// Mean edge length of the live tets (each interior edge counted once per tet, which is close
// enough for a grid cell size) and the bounding box diagonal.
struct MeshScale {
  double mean_edge = 0.0;
  double diagonal = 0.0;
};

MeshScale mesh_scale(const TetMesh& mesh) {
  Vec3 lo{HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  double edge_sum = 0.0;
  std::uint64_t edges = 0;
  for (std::uint32_t i = 0; i < mesh.tet_capacity(); ++i) {
    const TetId t{i};
    if (!mesh.is_live(t)) continue;
    const auto v = mesh.tet(t);
    for (int e = 0; e < 6; ++e) {
      edge_sum += norm(mesh.position(v[kEdgeVerts[e][1]]) - mesh.position(v[kEdgeVerts[e][0]]));
      ++edges;
    }
    for (VertId u : v) {
      const Vec3& p = mesh.position(u);
      lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
      hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
    }
  }
  if (edges == 0) return {};
  return {edge_sum / static_cast<double>(edges), norm(hi - lo)};
}

// Whether triangle `s` lies, within tol, inside original boundary triangle `f` (same plane,
// centroid inside, same outward side).
bool lies_on(const SurfaceTriangle& s, const SurfaceTriangle& f, double tol) {
  const Vec3 n = cross(f.b - f.a, f.c - f.a);
  const double n_len = norm(n);
  if (!(n_len > 0.0)) return false;
  for (const Vec3& p : {s.a, s.b, s.c})
    if (std::fabs(dot(p - f.a, n)) > tol * n_len) return false;
  if (dot(cross(s.b - s.a, s.c - s.a), n) <= 0.0) return false;
  const Vec3 g = (1.0 / 3.0) * (s.a + s.b + s.c);
  const Vec3* corners[3] = {&f.a, &f.b, &f.c};
  for (int k = 0; k < 3; ++k) {
    const Vec3& p = *corners[k];
    const Vec3& q = *corners[(k + 1) % 3];
    // Signed distance from g to the edge line pq, positive inside: cross(q-p, g-p).n / (|n||pq|).
    if (dot(cross(q - p, g - p), n) < -tol * n_len * norm(q - p)) return false;
  }
  return true;
}

}  // namespace

std::vector<SurfaceTriangle> boundary_surface(const TetMesh& mesh) {
  std::vector<SurfaceTriangle> out;
  for_each_boundary_face(mesh, [&](TetId t, int f) { out.push_back(face_triangle(mesh, t, f)); });
  return out;
}

std::vector<SurfaceTriangle> classify_surface(const TetMesh& mesh, const TetMesh& original) {
  std::vector<SurfaceTriangle> out = boundary_surface(mesh);
  const MeshScale scale = mesh_scale(original);
  if (!(scale.mean_edge > 0.0)) {
    for (SurfaceTriangle& s : out) s.cut = true;  // no original surface to lie on
    return out;
  }
  const double tol = kRelativeTolerance * scale.diagonal;
  SpatialIndex index(scale.mean_edge);
  index.build(original);
  std::vector<TetId> near;
  for (SurfaceTriangle& s : out) {
    const Vec3 g = (1.0 / 3.0) * (s.a + s.b + s.c);
    index.query(original, Tool::ball(g, tol), near);
    bool on_original = false;
    for (TetId o : near) {
      for (int f = 0; f < 4 && !on_original; ++f)
        on_original = original.is_boundary_face(o, f) && lies_on(s, face_triangle(original, o, f), tol);
      if (on_original) break;
    }
    s.cut = !on_original;
  }
  return out;
}

}  // namespace tetcut::render
