// The fallback with a proof: a construction, local to the stars of T's four vertices, whose set
// is always removable (docs/removal-proof.md).
//
// Let f be the piecewise-linear function that is 1 at T's vertices and 0 at every other vertex
// (the sum of T's vertices' barycentric coordinates). Split every edge with exactly one end in
// T at its midpoint, where f = 1/2. After the split no edge joins a vertex with f = 1 to one
// with f = 0, so every child lies on one side of the level set f = 1/2, a normal surface of the
// original mesh; remove T and every child whose vertices all have f >= 1/2. What remains is
// the mesh cut along that normal surface, which is a 3-manifold: the set is removable.
//
// The argument is combinatorial, so any point inside each edge will do in place of its
// midpoint (the new vertex then takes the value 1/2 of the function interpolated on the split
// mesh): where a midpoint would make a child flat or inverted, the splitter moves the point
// (SplitPoint::kPositiveChildren; docs/removal-proof.md, "Any split point").
//
// T itself is never split (none of its edges has exactly one end in T), and every other tet of
// the stars is. Cost: O(star of T) edges and children; the split is planned and checked by the
// splitter before the mesh changes, and the caller's tet budget is checked on the plan.
#pragma once

#include <cstdint>
#include <vector>

#include "remove/removal_context.hpp"

namespace tetcut::detail {

class NormalSurfaceFallback {
 public:
  // Working sizes, allocated and touched now (a larger request grows them once).
  void reserve();
  // Removes T with the half-star around it; returns the size of the set, 0 when the splitter
  // refused (a child not positive at any of its split points, or the budget: the mesh as before).
  std::uint32_t remove(RemovalContext& ctx, TetId t);

  // The plan alone: the edges with exactly one end in T, one hint each.
  void plan(const TetMesh& mesh, TetId t, std::vector<Edge>& edges);

 private:
  std::vector<Edge> edges_;
  std::vector<TetId> shell_, set_, larger_;
  std::vector<std::uint32_t> split_points_;  // sorted: the new vertices, f = 1/2
};

}  // namespace tetcut::detail
