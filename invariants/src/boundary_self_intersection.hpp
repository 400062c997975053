// The geometric half of I3 at the exact level: does the boundary surface intersect itself?
// A small interface so that CGAL stays inside one translation unit (it takes about a minute to
// compile, and nothing else in the checker needs it).
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "tetcut/vec3.hpp"

namespace tetcut::invariants::detail {

struct SelfIntersections {
  bool tested = false;         // false: the triangles do not form a surface CGAL accepts
  std::uint64_t pair_count = 0;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> first_pairs;  // triangle indices
  std::string message;         // why it was not tested
};

// `triangles`: #F by 3 vertex ids into `positions`, consistently oriented, forming a
// 2-manifold (the caller has checked I3, I5 and I6). Two triangles intersect when they share
// more than their common vertices or edge: pairs sharing a vertex or an edge are tested for a
// degenerate overlap only (CGAL's Polygon_mesh_processing::self_intersections semantics),
// with exact predicates.
SelfIntersections find_boundary_self_intersections(std::span<const Vec3> positions,
                                                   std::span<const std::array<std::uint32_t, 3>> triangles,
                                                   std::size_t max_pairs);

}  // namespace tetcut::invariants::detail
