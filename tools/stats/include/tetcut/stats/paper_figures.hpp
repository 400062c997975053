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

}  // namespace tetcut::stats
