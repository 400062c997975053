// Shape quality of a tetrahedron (design invariant I7).
#pragma once

#include <span>

#include "tetcut/ids.hpp"
#include "tetcut/mesh.hpp"
#include "tetcut/vec3.hpp"

namespace tetcut {

// Radius ratio 3 * inradius / circumradius: 1 for the regular tet, 0 for a flat one, negative
// values are never returned (inverted tets measure by their absolute volume).
double radius_ratio(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

// The worst radius ratio among `tets` (live), 1 when there is none: the "worst new tet" of a
// split, a refinement or a cut, measured once on the tets the caller cares about.
double min_radius_ratio(const TetMesh& mesh, std::span<const TetId> tets);

// Smallest of the six dihedral angles, in degrees (70.53 for the regular tet).
double min_dihedral_angle_deg(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

// The measure the improvement pass raises and judges every operation by, and the one its floor
// is set in (I7, with the hosts'): the radius ratio, as Klingner and Shewchuk's Stellar offers it
// among its objectives. Every operator of improve/ measures through these, so the objective
// changes here and nowhere else.
inline double quality(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) { return radius_ratio(a, b, c, d); }
inline double quality(const TetMesh& mesh, const TetMesh::TetVerts& v) {
  return quality(mesh.position(v[0]), mesh.position(v[1]), mesh.position(v[2]), mesh.position(v[3]));
}
inline double quality(const TetMesh& mesh, TetId t) { return quality(mesh, mesh.tet(t)); }
// The worst quality() among `tets` (live), 1 when there is none.
double worst_quality(const TetMesh& mesh, std::span<const TetId> tets);

}  // namespace tetcut
