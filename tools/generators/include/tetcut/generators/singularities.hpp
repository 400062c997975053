// A complete finder of topological singularities in a raw tet array (paper 2.1: a mesh is a
// 3-manifold iff every vertex shell and every edge shell is one face-connected component, and,
// design I5, every vertex link is a disk or a sphere). Unlike the checker, which lists only the
// first offenders, this lists every singular vertex and edge with its shell's components: repair
// needs all of them.
#pragma once

#include <cstdint>
#include <vector>

#include "tetcut/raw_mesh.hpp"

namespace tetcut::generators {

struct SingularEdge {
  std::uint32_t a = 0, b = 0;                          // a < b
  std::vector<std::vector<std::uint32_t>> components;  // tets of each face-connected component
};

struct SingularVertex {
  std::uint32_t vertex = 0;
  std::vector<std::vector<std::uint32_t>> components;  // tets of each face-connected component
  bool on_boundary = false;  // some face through the vertex belongs to one tet only
  // Euler characteristic of the link: #edges - #faces + #tets through the vertex. A manifold
  // vertex has 1 (disk) on the boundary, 2 (sphere) inside.
  std::int64_t link_euler = 0;
};

struct Singularities {
  std::vector<SingularEdge> edges;       // sorted by (a, b)
  std::vector<SingularVertex> vertices;  // sorted by vertex

  [[nodiscard]] bool empty() const { return edges.empty() && vertices.empty(); }
};

// Preconditions: every tet has 4 distinct vertices < #V, and no face belongs to more than two
// tets (repair establishes these first). Components list tets in increasing index order, and the
// components are ordered by their first tet. O(#T log #T).
Singularities find_singularities(const RawMesh& mesh);

}  // namespace tetcut::generators
