// Shape quality of a tetrahedron (design invariant I7).
#pragma once

#include <algorithm>
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

// The largest cosine of the six dihedral angles: the smallest angle is at least theta exactly
// when this is at most cos(theta). No inverse cosine: the floor test runs on every tet a cut
// makes. 1 for a flat tet.
double max_dihedral_cosine(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

// radius_ratio() and max_dihedral_cosine() of one tet in one pass (they share the face normals),
// each equal to what its own function returns: what the improvement pass tests floors with.
struct TetShape {
  double ratio, max_cosine;
};
TetShape tet_shape(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

// The angle, in degrees, whose cosine is c: the smallest dihedral angle of a tet whose
// max_dihedral_cosine() is c.
double degrees_of_cosine(double c);

// The smallest sine of the six dihedral angles, 3 V |e| / (2 A_i A_j) at edge e between faces i
// and j: small for an angle near 0 or near 180 degrees, Stellar's default objective (Klingner and
// Shewchuk, "Aggressive tetrahedral mesh improvement"). 0 for a flat or inverted tet.
double min_dihedral_sine(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

// The weight of the smallest dihedral sine in quality(): F / sin(theta) for the floors the
// improvement pass holds (CutParams::quality_floor, min_dihedral_deg), so that the two floors meet
// at one value of quality() and neither term is traded away for the other at the floor; 0 for no
// angle floor (quality() is then the radius ratio). Per thread, set for one run of the pass by
// Improver::run (improve/improver.cpp): every operator measures through quality(), and a
// run of the pass is one thread's. Default: the default floors, 0.1 and 15 degrees.
inline constexpr double kDihedralSineWeight = 0.1 / 0.25881904510252074;
inline thread_local double t_dihedral_sine_weight = kDihedralSineWeight;

// The measure the improvement pass raises and judges every operation by: the worse of the radius
// ratio and the weighted minimum dihedral sine, so an operation lifts the tet's worst angle and
// its roundness together (a radius ratio alone lets a tet at 0.1 keep a 2-degree dihedral).
// Every operator of improve/ measures through these, so the objective changes here and nowhere
// else. The floors themselves are tested per term (improver.hpp, I7).
// min(radius_ratio, w x min_dihedral_sine) in one pass over the tet: the two share the face
// normals and their lengths (11 square roots where the two apart take 15). 0 for a flat or
// inverted tet.
double weighted_quality(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, double w);
inline double quality(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const double w = t_dihedral_sine_weight;
  return w > 0.0 ? weighted_quality(a, b, c, d, w) : radius_ratio(a, b, c, d);
}
inline double quality(const TetMesh& mesh, const TetMesh::TetVerts& v) {
  return quality(mesh.position(v[0]), mesh.position(v[1]), mesh.position(v[2]), mesh.position(v[3]));
}
inline double quality(const TetMesh& mesh, TetId t) { return quality(mesh, mesh.tet(t)); }
// The worst quality() among `tets` (live), 1 when there is none.
double worst_quality(const TetMesh& mesh, std::span<const TetId> tets);

}  // namespace tetcut
