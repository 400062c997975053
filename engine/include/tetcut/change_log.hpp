// What an operation did to the mesh, for a FEM simulator to apply to its own arrays (design:
// the ChangeLog). Entries are appended in the order they happened: within one operation a tet
// may be created and later removed again (refinement splits its own children), so apply the
// removals and creations of each step in order, or simply take the final state of each id.
#pragma once

#include <cstddef>
#include <vector>

#include "tetcut/ids.hpp"

namespace tetcut {

struct CreatedTet {
  TetId tet;
  TetId parent;  // the tet it subdivides, kNoTet when it has none
};

struct CreatedVertex {
  VertId vertex;
  VertId a, b;  // the edge it was put on
  double t = 0.5;  // position and attributes: (1 - t) * a + t * b
};

struct ChangeLog {
  std::vector<TetId> removed;
  std::vector<CreatedTet> created;
  std::vector<CreatedVertex> vertices;

  // Room for this many entries of each kind (a caller that must not allocate per operation).
  void reserve(std::size_t n) {
    removed.reserve(n);
    created.reserve(n);
    vertices.reserve(n);
  }

  void clear() {
    removed.clear();
    created.clear();
    vertices.clear();
  }
};

}  // namespace tetcut
