// The figures of the paper's Tables 1 and 2 (Forest, Delingette, Ayache 2002, section 3.6), as
// printed, so that `tetcut stats` can put ours beside them row for row.
//
// The paper's meshes: 1 a simple cylinder, 2 a thin sheet with an average thickness of two tets,
// 3 a rough liver (3,970 tets), 4 a finer liver (8,454 tets), 5 a liver locally refined with a
// home-made edge splitting method (9,933 tets for a third of the liver).
#pragma once

#include <array>

namespace tetcut::stats {

// Table 1: "Estimation of the occurrence of vertex or edge singularities when removing a
// tetrahedron on the mesh surface".
struct PaperTable1Row {
  int mesh;                 // 1..5
  int operations;           // removal operations
  double removable_pct;     // % removable directly
  double vertex_pct;        // % of problems due to vertices
  double edge_pct;          // % of problems due to edges
};

// Table 2: "Analysis of tetrahedra removal strategy" (the neighbour strategy, paper 3.5).
struct PaperTable2Row {
  int mesh;
  double vertex_unresolved_pct, vertex_cardinality;
  double edge_unresolved_pct, edge_cardinality;
  double global_unresolved_pct, global_cardinality;
};

inline constexpr std::array<PaperTable1Row, 5> kPaperTable1{{
    {1, 130, 89.3, 9.2, 1.5},
    {2, 265, 62.3, 31.7, 6.0},
    {3, 460, 84.1, 13.5, 2.4},
    {4, 1448, 83.8, 14.4, 1.8},
    {5, 2268, 86.1, 13.3, 0.6},
}};

inline constexpr std::array<PaperTable2Row, 5> kPaperTable2{{
    {1, 8.3, 3.1, 50.0, 6.0, 1.5, 1.2},
    {2, 14.3, 3.1, 43.8, 4.7, 7.1, 1.8},
    {3, 6.4, 2.9, 54.5, 5.0, 2.2, 1.3},
    {4, 10.1, 3.2, 34.6, 4.0, 2.1, 1.3},
    {5, 15.6, 3.3, 35.7, 3.8, 2.3, 1.3},
}};

// The counts behind the paper's rate cells, rebuilt from its percentages (fisher_exact.hpp uses
// them): k events of n, each the nearest integer to the printed figure x n / 100, with n the
// row's operations (Table 1, Table 2's global column) or the rebuilt singularities (Table 2's
// vertex and edge columns). The paper's own rounding is not uniform (mesh 1's 89.3 % removable
// is 116/130 = 89.2, its removable column is 100 minus the other two; mesh 2's global 7.1 % is
// 19/265 = 7.2; mesh 3's 6.4 % is 4/62 = 6.45), so each count is within 0.1 point of its figure.
// Where the printed figures admit two counts both are kept as a range: mesh 4's vertex
// singularities are 208 or 209 of 1,448 (14.4 %; 21 unresolved is 10.1 % of 208, 10.0 of 209),
// mesh 5's 301 or 302 of 2,268 (13.3 %; 47 unresolved, 15.6 % of either). Every edge row is
// pinned by Table 2: 2, 16, 11, 26 and 14 edge singularities (1/2, 7/16, 6/11, 9/26, 5/14 left).
// tests/stats/fisher_exact_test.cpp checks each against the printed figure and the sums.
struct PaperCount {
  int k_lo, k_hi;  // events
  int n_lo, n_hi;  // trials
};
constexpr PaperCount exactly(int k, int n) { return {k, k, n, n}; }

struct PaperTable1Counts {
  PaperCount removable, vertex, edge;
};
struct PaperTable2Counts {
  PaperCount vertex_unresolved, edge_unresolved, global_unresolved;
};

inline constexpr std::array<PaperTable1Counts, 5> kPaperTable1Counts{{
    {exactly(116, 130), exactly(12, 130), exactly(2, 130)},
    {exactly(165, 265), exactly(84, 265), exactly(16, 265)},
    {exactly(387, 460), exactly(62, 460), exactly(11, 460)},
    {{1213, 1214, 1448, 1448}, {208, 209, 1448, 1448}, exactly(26, 1448)},
    {{1952, 1953, 2268, 2268}, {301, 302, 2268, 2268}, exactly(14, 2268)},
}};

inline constexpr std::array<PaperTable2Counts, 5> kPaperTable2Counts{{
    {exactly(1, 12), exactly(1, 2), exactly(2, 130)},
    {exactly(12, 84), exactly(7, 16), exactly(19, 265)},
    {exactly(4, 62), exactly(6, 11), exactly(10, 460)},
    {{21, 21, 208, 209}, exactly(9, 26), exactly(30, 1448)},
    {{47, 47, 301, 302}, exactly(5, 14), exactly(52, 2268)},
}};

}  // namespace tetcut::stats
