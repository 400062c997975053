#include "improve/flips.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/quality.hpp"
#include "tetcut/detail/local_tables.hpp"
#include "tetcut/detail/reserve_touched.hpp"
#include "tetcut/predicates.hpp"

namespace tetcut::detail {
namespace {

bool positive(const TetMesh& mesh, const TetMesh::TetVerts& v) {
  return orientation(mesh.position(v[0]), mesh.position(v[1]), mesh.position(v[2]), mesh.position(v[3])) > 0;
}

// The vertex of u other than a, b and `not_this` (u has a and b).
VertId other_vertex(const TetMesh& mesh, TetId u, VertId a, VertId b, VertId not_this) {
  for (VertId x : mesh.tet(u))
    if (x != a && x != b && x != not_this) return x;
  return kNoVert;
}

bool shares(const TetMesh& mesh, TetId u, VertId x) { return mesh.local_index(u, x) >= 0; }

// Twice the largest of a few edge lengths, cubed: the scale of a determinant of those edges.
double cube_scale(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const double l = std::max({norm(b - a), norm(c - a), norm(d - a), norm(c - b), norm(d - b), norm(d - c)});
  return l * l * l;
}

}  // namespace

void Flipper::reserve() {
  reserve_touched(shell_, 64);
  reserve_touched(scratch_, 256);
}

bool Flipper::has_edge(const TetMesh& mesh, VertId u, VertId w) { return mesh.find_edge(u, w, kNoTet, scratch_).valid(); }

bool Flipper::has_face(const TetMesh& mesh, VertId u, VertId w, VertId x) {
  mesh.vertex_shell(u, scratch_);
  return std::any_of(scratch_.begin(), scratch_.end(), [&](TetId t) { return shares(mesh, t, w) && shares(mesh, t, x); });
}

Refusal Flipper::plan_edge_removal(const TetMesh& mesh, TetId t, int local_edge, double margin, Plan& plan) {
  plan.start(Operator::kEdgeRemoval);
  const VertId a = mesh.vertex(t, kEdgeVerts[local_edge][0]), b = mesh.vertex(t, kEdgeVerts[local_edge][1]);
  const bool open = mesh.edge_shell(t, local_edge, shell_);
  const int n = static_cast<int>(shell_.size());
  if (open ? (n < 2 || n + 1 > kMaxRing) : (n < 3 || n > kMaxRing)) return Refusal::kNotFlippable;

  // The ring of vertices around (a, b), in the shell's rotation order: tet i holds ring[i] and
  // ring[i + 1] (ring[n] is ring[0] when the shell closes).
  std::array<VertId, kMaxRing + 1> ring{};
  int m = 0;
  if (open) {
    // The first tet's vertex that the second does not have: an end of the open ring.
    for (VertId x : mesh.tet(shell_[0]))
      if (x != a && x != b && !shares(mesh, shell_[1], x)) ring[m] = x;
    ++m;
  }
  for (int i = 0; i + 1 < n; ++i) {
    VertId common = kNoVert;
    for (VertId x : mesh.tet(shell_[i]))
      if (x != a && x != b && shares(mesh, shell_[i + 1], x)) common = x;
    ring[m++] = common;
  }
  if (open) {
    ring[m] = other_vertex(mesh, shell_[n - 1], a, b, ring[m - 1]);
    ++m;
  } else {
    VertId common = kNoVert;
    for (VertId x : mesh.tet(shell_[n - 1]))
      if (x != a && x != b && shares(mesh, shell_[0], x)) common = x;
    ring[m++] = common;
    std::rotate(ring.begin(), ring.begin() + m - 1, ring.begin() + m);  // ring[0] is shared by tets n-1 and 0
  }
  for (int i = 0; i < m; ++i)
    if (!ring[i].valid()) return Refusal::kNotFlippable;
  const Vec3 pa = mesh.position(a), pb = mesh.position(b);
  if (open) {
    // On the surface only where the boundary stays the same plane: the two boundary faces at
    // (a, b) coplanar, to rounding of their own coordinates.
    const Vec3 r0 = mesh.position(ring[0]), rm = mesh.position(ring[m - 1]);
    if (std::abs(dot(pb - pa, cross(r0 - pa, rm - pa))) > 1e-12 * cube_scale(pa, pb, r0, rm)) return Refusal::kSurfaceConstraint;
  }

  plan.worst_before = worst_quality(mesh, shell_);
  // Tets (r_i, r_j, r_k, a) and (r_i, r_k, r_j, b) for i < j < k when the ring turns
  // counter-clockwise seen from a, which orientation(a, b, r_0, r_1) < 0 says; mirrored otherwise.
  const bool ccw_from_a = orientation(pa, pb, mesh.position(ring[0]), mesh.position(ring[1])) < 0;
  auto triangle_tets = [&](int i, int j, int k) {
    std::array<TetMesh::TetVerts, 2> out{};
    out[0] = ccw_from_a ? TetMesh::TetVerts{ring[i], ring[j], ring[k], a} : TetMesh::TetVerts{ring[i], ring[k], ring[j], a};
    out[1] = ccw_from_a ? TetMesh::TetVerts{ring[i], ring[k], ring[j], b} : TetMesh::TetVerts{ring[i], ring[j], ring[k], b};
    return out;
  };
  // The worse of the triangle's two tets, or `at_most` as soon as one is no better than it (the
  // caller then has no use for the figure): the quality before the orientation, the cheaper one.
  auto triangle_quality = [&](int i, int j, int k, double at_most) {
    const auto tets = triangle_tets(i, j, k);
    const double first = quality(mesh, tets[0]);
    if (!(first > at_most)) return at_most;
    const double q = std::min(first, quality(mesh, tets[1]));
    if (!(q > at_most)) return at_most;
    if (!positive(mesh, tets[0]) || !positive(mesh, tets[1])) return -1.0;
    return q;
  };
  // best[i][j]: the best worst quality of a triangulation of the polygon ring[i..j] closed by the
  // chord (i, j); split[i][j] the apex it uses (Klincsek).
  constexpr double kNone = -std::numeric_limits<double>::infinity();
  double best[kMaxRing][kMaxRing];
  std::int8_t split[kMaxRing][kMaxRing];
  for (int gap = 1; gap < m; ++gap)
    for (int i = 0; i + gap < m; ++i) {
      const int j = i + gap;
      best[i][j] = gap == 1 ? std::numeric_limits<double>::infinity() : kNone;
      split[i][j] = -1;
      for (int k = i + 1; k < j; ++k) {
        // Only a triangulation better than the best so far matters: its triangle is measured
        // only then (the same choice, fewer measures).
        const double bound = std::min(best[i][k], best[k][j]);
        if (!(bound > best[i][j])) continue;
        const double q = std::min(bound, triangle_quality(i, k, j, best[i][j]));
        if (q > best[i][j]) {
          best[i][j] = q;
          split[i][j] = static_cast<std::int8_t>(k);
        }
      }
    }
  plan.worst_after = best[0][m - 1];
  if (!(plan.worst_after > 0.0)) return Refusal::kInvertedChild;
  if (!(plan.worst_after > plan.worst_before * (1.0 + margin))) return Refusal::kNotBetter;

  // Collect the triangles; every chord that is not a ring edge is a new edge and must not exist
  // yet (nor, for three tets, the one new face).
  plan.removed.assign(shell_.begin(), shell_.end());
  std::array<std::pair<std::int8_t, std::int8_t>, 2 * kMaxRing> stack{};
  int top = 0;
  stack[top++] = {0, static_cast<std::int8_t>(m - 1)};
  if (open && has_edge(mesh, ring[0], ring[m - 1])) return Refusal::kExistingSimplex;
  while (top > 0) {
    const auto [i, j] = stack[--top];
    if (j - i < 2) continue;
    const int k = split[i][j];
    const auto tets = triangle_tets(i, k, j);
    plan.added.push_back(tets[0]);
    plan.added.push_back(tets[1]);
    for (const auto& [x, y] : {std::pair<int, int>{i, k}, std::pair<int, int>{k, j}}) {
      if (y - x >= 2 && has_edge(mesh, ring[x], ring[y])) return Refusal::kExistingSimplex;
      stack[top++] = {static_cast<std::int8_t>(x), static_cast<std::int8_t>(y)};
    }
  }
  if (!open && m == 3 && has_face(mesh, ring[0], ring[1], ring[2])) return Refusal::kExistingSimplex;
  return Refusal::kNone;
}

Refusal Flipper::plan_face_flip(const TetMesh& mesh, TetId t, int face, double margin, Plan& plan) {
  plan.start(Operator::kFaceRemoval);
  const FaceRef across = mesh.neighbour(t, face);
  if (!across.valid()) return Refusal::kNotFlippable;
  const VertId d = mesh.vertex(t, face), e = mesh.vertex(across.tet, across.face);
  const VertId p = mesh.vertex(t, kFaceVerts[face][0]), q = mesh.vertex(t, kFaceVerts[face][1]),
               r = mesh.vertex(t, kFaceVerts[face][2]);
  // The segment d-e must cross the triangle p q r: the three tets around it all of one sign.
  std::array<TetMesh::TetVerts, 3> tets = {TetMesh::TetVerts{p, q, d, e}, TetMesh::TetVerts{q, r, d, e},
                                           TetMesh::TetVerts{r, p, d, e}};
  int sign = 0;
  for (auto& v : tets) {
    const int s = orientation(mesh.position(v[0]), mesh.position(v[1]), mesh.position(v[2]), mesh.position(v[3]));
    if (s == 0 || (sign != 0 && s != sign)) return Refusal::kNotFlippable;
    sign = s;
  }
  if (sign < 0)
    for (auto& v : tets) std::swap(v[0], v[1]);
  const TetId pair[2] = {t, across.tet};
  plan.worst_before = worst_quality(mesh, pair);
  plan.worst_after = std::min({quality(mesh, tets[0]), quality(mesh, tets[1]), quality(mesh, tets[2])});
  if (!(plan.worst_after > plan.worst_before * (1.0 + margin))) return Refusal::kNotBetter;
  if (has_edge(mesh, d, e)) return Refusal::kExistingSimplex;
  plan.removed.assign(std::begin(pair), std::end(pair));
  plan.added.assign(tets.begin(), tets.end());
  return Refusal::kNone;
}

}  // namespace tetcut::detail
