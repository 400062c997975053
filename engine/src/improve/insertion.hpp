// Vertex insertion: a new vertex at the midpoint of a tet's longest edge, every tet around the
// edge halved (refine/edge_split.hpp, the templates' one-edge case). Klingner and Shewchuk insert
// a vertex where no flip or smoothing lifts a tet, and smooth it into place; so does the pass
// (improver.hpp): this plans the split, the Smoother then places the new vertex, and the two are
// kept only together, when the worst tet of what was split ends better.
//
// Planned on the const mesh as any operation (Operator::kInsertion): the edge's shell removed,
// each of its tets added as its two halves around kPlannedVertex at the midpoint, computed as
// TetMesh::add_vertex_on_edge will compute it. Refused when a half is flat or inverted by the
// exact predicate, the test the splitter applies, so an accepted plan always splits.
#pragma once

#include <cstdint>
#include <vector>

#include "improve/operation.hpp"
#include "refine/edge_split.hpp"
#include "tetcut/mesh.hpp"

namespace tetcut::detail {

class Inserter {
 public:
  // Working sizes for meshes up to `tets` tet ids, allocated and touched now.
  void reserve(std::uint32_t tets);
  // The split of t's longest edge (the first of the longest, in local edge order).
  [[nodiscard]] Refusal plan(const TetMesh& mesh, TetId t, Plan& plan);

 private:
  EdgeSplitter splitter_;
  std::vector<TetId> shell_;
};

}  // namespace tetcut::detail
