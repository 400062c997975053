#include "core/quality.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "tetcut/detail/local_tables.hpp"

namespace tetcut {

double radius_ratio(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  // inradius r = 3V / A (A: the sum of the face areas); circumradius R = |o| for the
  // circumcentre relative to a, o = (|b'|^2 c'xd' + |c'|^2 d'xb' + |d'|^2 b'xc') / (2 D) with
  // b' = b - a, ... and D = b'.(c'xd') = 6V. So 3r/R = 3 D^2 / (A |2 D o|): five square roots
  // (four areas and |2 D o|) where the edge-product form needed eleven. It runs for every tet a
  // cut makes (the report's worst quality).
  const Vec3 pb = b - a, pc = c - a, pd = d - a;
  const Vec3 cd = cross(pc, pd), db = cross(pd, pb), bc = cross(pb, pc);
  const double det = dot(pb, cd);
  if (det == 0.0) return 0.0;
  const Vec3 twice_d_o = dot(pb, pb) * cd + dot(pc, pc) * db + dot(pd, pd) * bc;
  const double area = 0.5 * (norm(cd) + norm(db) + norm(bc) + norm(cross(c - b, d - b)));
  const double denominator = area * norm(twice_d_o);
  if (!(denominator > 0.0)) return 0.0;
  return std::clamp(3.0 * det * det / denominator, 0.0, 1.0);
}

double min_dihedral_angle_deg(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const Vec3 p[4] = {a, b, c, d};
  // Outward face normals; the dihedral angle at edge e is pi minus the angle between the
  // normals of the two faces that contain e.
  Vec3 n[4];
  for (int f = 0; f < 4; ++f) {
    const Vec3& u = p[kFaceVerts[f][0]];
    const Vec3& v = p[kFaceVerts[f][1]];
    const Vec3& w = p[kFaceVerts[f][2]];
    n[f] = cross(v - u, w - u);
  }
  double smallest = 180.0;
  for (int e = 0; e < 6; ++e) {
    const Vec3& n0 = n[kEdgeFaces[e][0]];
    const Vec3& n1 = n[kEdgeFaces[e][1]];
    const double len = norm(n0) * norm(n1);
    if (len == 0.0) return 0.0;
    const double cosine = std::clamp(dot(n0, n1) / len, -1.0, 1.0);
    const double angle = 180.0 - std::acos(cosine) * 180.0 / std::numbers::pi;
    smallest = std::min(smallest, angle);
  }
  return smallest;
}

namespace {

// Outward face normals (twice the face areas), kFaceVerts' orientation.
void face_normals(const Vec3 (&p)[4], Vec3 (&n)[4]) {
  for (int f = 0; f < 4; ++f) {
    const Vec3& u = p[kFaceVerts[f][0]];
    n[f] = cross(p[kFaceVerts[f][1]] - u, p[kFaceVerts[f][2]] - u);
  }
}

}  // namespace

double max_dihedral_cosine(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const Vec3 p[4] = {a, b, c, d};
  Vec3 n[4];
  face_normals(p, n);
  double largest = -1.0;
  for (int e = 0; e < 6; ++e) {
    const Vec3& n0 = n[kEdgeFaces[e][0]];
    const Vec3& n1 = n[kEdgeFaces[e][1]];
    const double len = norm(n0) * norm(n1);
    if (!(len > 0.0)) return 1.0;
    // The dihedral angle is pi minus the angle between the outward normals.
    largest = std::max(largest, -dot(n0, n1) / len);
  }
  return std::min(largest, 1.0);
}

TetShape tet_shape(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  // radius_ratio()'s terms, in its order; the outward normals of kFaceVerts are n0 and the
  // negated cd, db, bc (a cross product's operands swapped negate it exactly).
  const Vec3 pb = b - a, pc = c - a, pd = d - a;
  const Vec3 cd = cross(pc, pd), db = cross(pd, pb), bc = cross(pb, pc), n0 = cross(c - b, d - b);
  const double fa = norm(n0), fb = norm(cd), fc = norm(db), fd = norm(bc);
  TetShape out{0.0, 1.0};
  const double det = dot(pb, cd);
  if (det != 0.0) {
    const Vec3 twice_d_o = dot(pb, pb) * cd + dot(pc, pc) * db + dot(pd, pd) * bc;
    const double denominator = 0.5 * (fb + fc + fd + fa) * norm(twice_d_o);
    if (denominator > 0.0) out.ratio = std::clamp(3.0 * det * det / denominator, 0.0, 1.0);
  }
  const Vec3 n[4] = {n0, -1.0 * cd, -1.0 * db, -1.0 * bc};
  const double len[4] = {fa, fb, fc, fd};
  double largest = -1.0;
  for (int e = 0; e < 6; ++e) {
    const int i = kEdgeFaces[e][0], j = kEdgeFaces[e][1];
    const double l = len[i] * len[j];
    if (!(l > 0.0)) return out;
    largest = std::max(largest, -dot(n[i], n[j]) / l);
  }
  out.max_cosine = std::min(largest, 1.0);
  return out;
}

double weighted_quality(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, double w) {
  // radius_ratio()'s terms: the face normals cd, db, bc (the faces at a) and n0 (opposite a).
  const Vec3 pb = b - a, pc = c - a, pd = d - a;
  const Vec3 cd = cross(pc, pd), db = cross(pd, pb), bc = cross(pb, pc), n0 = cross(c - b, d - b);
  const double det = dot(pb, cd);
  if (!(det > 0.0)) return 0.0;
  const Vec3 twice_d_o = dot(pb, pb) * cd + dot(pc, pc) * db + dot(pd, pd) * bc;
  // |n| of the face opposite each vertex: a's is n0, b's |cd|, c's |db|, d's |bc|.
  const double fa = norm(n0), fb = norm(cd), fc = norm(db), fd = norm(bc);
  const double denominator = 0.5 * (fb + fc + fd + fa) * norm(twice_d_o);
  if (!(denominator > 0.0)) return 0.0;
  const double ratio = std::clamp(3.0 * det * det / denominator, 0.0, 1.0);
  // The sine at each edge: det |e| / (|n_i| |n_j|), n_i and n_j the faces not opposite its ends.
  const double faces_ab = fc * fd, faces_ac = fb * fd, faces_ad = fb * fc, faces_bc = fa * fd, faces_bd = fa * fc,
               faces_cd = fa * fb;
  if (!(faces_ab > 0.0 && faces_ac > 0.0 && faces_ad > 0.0 && faces_bc > 0.0 && faces_bd > 0.0 && faces_cd > 0.0)) return 0.0;
  const double per_det = std::min({norm(pb) / faces_ab, norm(pc) / faces_ac, norm(pd) / faces_ad, norm(c - b) / faces_bc,
                                   norm(d - b) / faces_bd, norm(d - c) / faces_cd});
  return std::min(ratio, w * std::min(1.0, det * per_det));
}

double degrees_of_cosine(double c) { return std::acos(std::clamp(c, -1.0, 1.0)) * 180.0 / std::numbers::pi; }

double min_dihedral_sine(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const Vec3 p[4] = {a, b, c, d};
  Vec3 n[4];
  face_normals(p, n);
  const double det = dot(b - a, cross(c - a, d - a));  // 6V
  if (!(det > 0.0)) return 0.0;
  double len[4];
  for (int f = 0; f < 4; ++f) len[f] = norm(n[f]);
  double smallest = 1.0;
  for (int e = 0; e < 6; ++e) {
    // 3V|e| / (2 A_i A_j) = det |e| / (|n_i| |n_j|).
    const double faces = len[kEdgeFaces[e][0]] * len[kEdgeFaces[e][1]];
    if (!(faces > 0.0)) return 0.0;
    smallest = std::min(smallest, det * norm(p[kEdgeVerts[e][1]] - p[kEdgeVerts[e][0]]) / faces);
  }
  return smallest;
}

double min_radius_ratio(const TetMesh& mesh, std::span<const TetId> tets) {
  double worst = 1.0;
  for (TetId t : tets) {
    const TetMesh::TetVerts v = mesh.tet(t);
    worst = std::min(worst, radius_ratio(mesh.position(v[0]), mesh.position(v[1]), mesh.position(v[2]), mesh.position(v[3])));
  }
  return worst;
}

double worst_quality(const TetMesh& mesh, std::span<const TetId> tets) {
  double worst = 1.0;
  for (TetId t : tets) worst = std::min(worst, quality(mesh, t));
  return worst;
}

}  // namespace tetcut
