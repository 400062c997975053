// The subdivision of one tetrahedron whose edges are split at their midpoints (paper 3.2,
// Figure 2), as a table indexed by which edges are split and by the order of the tet's global
// vertex ids.
//
// Local point labels: 0..3 are the tet's corners, 4 + e is the midpoint of local edge e
// (kEdgeVerts). Conformity between neighbours comes from rules that look at one face only, so
// the two tets sharing a face always triangulate it alike (the paper's "lexicographic order"):
//   - a face with one split edge: two triangles from the midpoint (the only choice);
//   - a face with two split edges: the fan from the midpoint of the edge whose sorted global
//     vertex ids come first;
//   - a face with three split edges: the red 1:4 split (one central triangle).
// Each tet is then subdivided without Steiner points: the corners whose three edges are all
// split are cut off (the corner tets), and the remaining convex polytope is coned from a point
// whose incident facets are all fans around it. Such a point exists for all 64 masks under all
// 24 vertex orders (checked exhaustively by tests); with all six edges split the polytope is the
// central octahedron and the cone point is chosen to cut it along its shortest diagonal (1:8).
//
// The resulting tet counts are those of the paper's ten configurations: 1 edge: 2; two edges on
// a face: 3; two opposite: 4; three on a face or around a vertex: 4; three along a path: 4 or 5;
// four edges: 5 or 6; five: 7; six: 8.
#pragma once

#include <array>
#include <cstdint>

namespace tetcut {

inline constexpr int kMaxSplitChildren = 8;

struct SplitTemplate {
  std::uint8_t count = 0;
  // Children as local point labels, positively oriented whenever the parent is.
  std::array<std::array<std::uint8_t, 4>, kMaxSplitChildren> children{};
};

// Index 0..23 of the order of four distinct global ids: rank[i] is the position of local vertex
// i when the four ids are sorted.
std::uint8_t vertex_order_index(const std::array<std::uint32_t, 4>& global_ids);

// The template for `mask` (bit e set when local edge e is split; 1..63) and the vertex order.
// For mask 63, `diagonal` (0..2) selects which interior diagonal of the central octahedron is
// used: the one joining the midpoints of local edges d and 5 - d.
const SplitTemplate& split_template(std::uint8_t mask, std::uint8_t order_index, std::uint8_t diagonal = 0);

}  // namespace tetcut
