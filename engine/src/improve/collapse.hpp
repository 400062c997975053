// Edge collapse: a vertex the cut made merged into a neighbour, when nothing else lifts a sliver
// (Mmg's collapse operator; Klingner and Shewchuk use it among their topological operations).
// The tets around the edge (v, w) go; every other tet around v takes w in v's place. v must be a
// vertex the open transaction made: input vertices, and those of earlier cuts, never vanish.
//
// Kept a 3-manifold by the link condition (Dey, Edelsbrunner, Guha and Nekhayev, "Topology
// preserving edge contraction", 1999): the links of v and w meet exactly in the link of the edge
// (a vertex joined to both spans a triangle with v and w; an edge of both links spans a tet with
// them; no triangle is in both). On the surface, v collapses only along a boundary edge and only
// where the surface keeps its shape: v's boundary faces coplanar, or v on the line where two
// planes meet and w on it too; an interior v may go to any neighbour. Every new tet is positive by
// the exact predicate, and the worst of them must beat the worst of v's star.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "improve/operation.hpp"
#include "tetcut/mesh.hpp"

namespace tetcut::detail {

class Collapser {
 public:
  void reserve();
  // Plans merging v into w (Operator::kCollapse: v's star removed, the tets around v without w
  // added with w for v). Refused when the link condition, the surface, orientation or quality
  // refuses it, or when its worst new tet would not beat `to_beat` (the caller's best so far:
  // the cheap tests run first, the link condition last).
  [[nodiscard]] Refusal plan(const TetMesh& mesh, VertId v, VertId w, double margin, double to_beat, Plan& plan);

 private:
  // The planes of the boundary faces at x (at most 3 recorded), from its star.
  int boundary_planes(const TetMesh& mesh, VertId x, std::span<const TetId> star, std::array<Vec3, 3>& planes) const;

  std::vector<TetId> star_v_, star_w_, ring_;
  std::vector<VertId> near_v_, near_w_;
  std::vector<std::array<VertId, 2>> edges_v_, edges_w_;
  std::vector<std::array<VertId, 3>> faces_v_, faces_w_;
  std::vector<std::array<VertId, 2>> surface_v_, surface_w_;  // boundary links
};

}  // namespace tetcut::detail
