// Smoothing of the vertices a cut made: moving one vertex to raise the worst quality() (core/
// quality.hpp) of the tets around it (optimization-based smoothing: Freitag, Jones and Plassmann 1995, as Klingner and
// Shewchuk's Stellar uses it, reduced to its core: a direction that raises every tet of the star
// within a few per cent of the worst one (the active set), a backtracking line search, accepted
// only when the worst tet of the star improves and every tet stays positive by the exact
// predicate).
//
// Which vertices may move is the pass's rule (improver.hpp): those the open transaction made, and
// those there before it within the cut's reach (ChangeLog::moved). An interior vertex moves freely; a surface vertex only
// within its surface: in the plane of its boundary faces when they are all coplanar, along the
// line where two such planes meet when its boundary faces lie in exactly two (a crease, e.g. the
// midpoint of an edge of the organ's surface), otherwise not at all. "Coplanar" is to within a
// normal angle of 1e-9 radians, so the surface moves by at most 1e-9 times the displacement.
// One exception, on the cut's own surface (a vertex within the cut's reach, the tool's ball grown
// by D_ref): the surface the cautery leaves is the ball approximated by whole tets, rough at the
// scale of an edge, and a vertex there may move off the planes of its boundary faces by at most
// kCutSurfaceTolerance (5 %) of its shortest edge.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "core/tool.hpp"
#include "improve/operation.hpp"
#include "tetcut/mesh.hpp"

namespace tetcut::detail {

inline constexpr double kCutSurfaceTolerance = 0.05;

class Smoother {
 public:
  void reserve();
  // Where to move v so that the worst quality() of its star
  // rises by more than the relative `margin` (Operator::kSmoothing: v's star removed and added
  // again, v placed at its new position); kNotBetter when nowhere found does, kSurfaceConstraint
  // when v may not move at all.
  // `tool`: the cut's reach, where the cut's own surface may move within the tolerance.
  [[nodiscard]] Refusal plan(const TetMesh& mesh, VertId v, double margin, const Tool* tool, Plan& plan);

 private:
  struct StarTet {
    std::array<Vec3, 4> corners;  // v's slot holds its current position
    int slot;
  };
  // The worst quality() of the star with v at p (-1 when a tet is not positive); stops at the
  // first tet not above `floor` (what a candidate must beat) and returns its quality.
  double evaluate(const Vec3& p, double floor = -1.0) const;
  // The gradient of star tet i's quality() at p, projected on the directions v may take.
  Vec3 gradient(std::size_t i, const Vec3& p, int dims, double h) const;
  // The directions v may move in: 3 (interior, or the cut's surface within the tolerance), 2 (a
  // plane), 1 (a line) or 0.
  int constraint(const TetMesh& mesh, VertId v, const Tool* tool);
  // A candidate position stays within the tolerance of the cut's surface (when that applies).
  [[nodiscard]] bool near_surface(const Vec3& p) const;

  std::vector<TetId> shell_;
  std::vector<StarTet> star_;
  static constexpr std::size_t kMaxActive = 4;
  static constexpr std::size_t kMaxSurfaceNormals = 16;
  std::vector<Vec3> active_;  // gradients of the star's tets near its worst
  std::array<Vec3, 3> basis_{};  // orthonormal directions v may move along
  std::vector<Vec3> surface_normals_;  // the cut's surface at v: unit normals of its boundary faces
  Vec3 start_{};
  double surface_tolerance_ = 0.0;     // how far off them v may go (0: not on the cut's surface)
};

}  // namespace tetcut::detail
