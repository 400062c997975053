// Local combinatorics of one tetrahedron, all in one place (style: CGAL's Triangulation_utils_3).
//
// Conventions used everywhere in tetcut:
//  - a tet (v0, v1, v2, v3) is positively oriented when det(v1 - v0, v2 - v0, v3 - v0) > 0;
//  - local face i is the face opposite local vertex i;
//  - kFaceVerts[i] lists face i's vertices counter-clockwise seen from outside the tet, so that
//    its right-hand normal points out of a positive tet;
//  - local edge e joins kEdgeVerts[e]; the edge opposite e is 5 - e.
#pragma once

#include <array>
#include <cstdint>

namespace tetcut {

inline constexpr std::uint8_t kFaceVerts[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};

inline constexpr std::uint8_t kEdgeVerts[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};

// The two local faces that contain local edge e: those opposite the two vertices not on e.
inline constexpr std::uint8_t kEdgeFaces[6][2] = {{2, 3}, {1, 3}, {1, 2}, {0, 3}, {0, 2}, {0, 1}};

// kEdgeIndex[a][b]: local edge joining local vertices a and b (a != b); 0xFF on the diagonal.
inline constexpr std::uint8_t kEdgeIndex[4][4] = {
    {0xFF, 0, 1, 2}, {0, 0xFF, 3, 4}, {1, 3, 0xFF, 5}, {2, 4, 5, 0xFF}};

inline constexpr std::uint8_t opposite_edge(std::uint8_t e) { return static_cast<std::uint8_t>(5 - e); }

namespace detail {
constexpr bool face_excludes_its_vertex() {
  for (int f = 0; f < 4; ++f)
    for (int k = 0; k < 3; ++k)
      if (kFaceVerts[f][k] == f) return false;
  return true;
}
constexpr bool edge_faces_contain_edge() {
  for (int e = 0; e < 6; ++e)
    for (int s = 0; s < 2; ++s) {
      const int f = kEdgeFaces[e][s];
      if (kEdgeVerts[e][0] == f || kEdgeVerts[e][1] == f) return false;
    }
  return true;
}
constexpr bool edge_index_inverts_edge_verts() {
  for (int e = 0; e < 6; ++e)
    if (kEdgeIndex[kEdgeVerts[e][0]][kEdgeVerts[e][1]] != e ||
        kEdgeIndex[kEdgeVerts[e][1]][kEdgeVerts[e][0]] != e)
      return false;
  return true;
}
constexpr bool opposite_edges_are_disjoint() {
  for (int e = 0; e < 6; ++e) {
    const int o = opposite_edge(static_cast<std::uint8_t>(e));
    for (int a = 0; a < 2; ++a)
      for (int b = 0; b < 2; ++b)
        if (kEdgeVerts[e][a] == kEdgeVerts[o][b]) return false;
  }
  return true;
}
}  // namespace detail

static_assert(detail::face_excludes_its_vertex());
static_assert(detail::edge_faces_contain_edge());
static_assert(detail::edge_index_inverts_edge_verts());
static_assert(detail::opposite_edges_are_disjoint());

}  // namespace tetcut
