// The checker's own local combinatorics of one tet, derived here from the two conventions alone
// (face i is the face opposite vertex i; (v0, v1, v2, v3) is positive when
// det(v1 - v0, v2 - v0, v3 - v0) > 0). Not taken from the engine's local_tables.hpp: were the
// engine's table wrong, a checker reading it would agree with it (style: a second witness).
#pragma once

#include <array>
#include <cstdint>

namespace tetcut::invariants::detail {

using TetFaceTable = std::array<std::array<std::uint8_t, 3>, 4>;
using TetEdgeTable = std::array<std::array<std::uint8_t, 4>, 6>;

// Face i: the three other vertices, counter-clockwise seen from outside a positive tet, i.e. so
// that (face, vertex i) is a negative tet. Listed in increasing order, (j, k, l, i) is
// (0, 1, 2, 3) with i moved to the end by 3 - i transpositions, an odd permutation exactly when
// i is even; for odd i the last two are swapped to make it odd.
constexpr TetFaceTable make_face_table() {
  TetFaceTable faces{};
  for (std::uint8_t i = 0; i < 4; ++i) {
    std::uint8_t n = 0;
    for (std::uint8_t j = 0; j < 4; ++j)
      if (j != i) faces[i][n++] = j;
    if (i % 2 == 1) std::swap(faces[i][1], faces[i][2]);
  }
  return faces;
}

// The six edges (a, b), a < b, each with the two vertices off it (c, d), c < d.
constexpr TetEdgeTable make_edge_table() {
  TetEdgeTable edges{};
  std::uint8_t e = 0;
  for (std::uint8_t a = 0; a < 4; ++a)
    for (std::uint8_t b = a + 1; b < 4; ++b) {
      std::uint8_t n = 2;
      edges[e] = {a, b, 0, 0};
      for (std::uint8_t x = 0; x < 4; ++x)
        if (x != a && x != b) edges[e][n++] = x;
      ++e;
    }
  return edges;
}

inline constexpr TetFaceTable kTetFaces = make_face_table();
inline constexpr TetEdgeTable kTetEdges = make_edge_table();

constexpr bool every_face_omits_exactly_its_vertex() {
  for (int i = 0; i < 4; ++i) {
    int seen = 0;
    for (int k = 0; k < 3; ++k) {
      if (kTetFaces[i][k] == i) return false;
      seen |= 1 << kTetFaces[i][k];
    }
    if (seen != (0xF & ~(1 << i))) return false;
  }
  return true;
}
static_assert(every_face_omits_exactly_its_vertex());
// Orientation itself is checked against the exact predicate in tests/invariants.

}  // namespace tetcut::invariants::detail
