// What the tests of the structures that follow a mesh through its changes (the spatial index,
// the walking locator) share: one random change of the mesh inside an open transaction (split an
// edge of a random live tet with the templates, or, when `remove`, remove that tet: neither
// cares about manifoldness), and the reference answer they are held to, a scan.
#pragma once

#include <gtest/gtest.h>

#include <span>

#include "core/random.hpp"
#include "cut/spatial_index.hpp"
#include "refine/edge_split.hpp"
#include "test_meshes.hpp"
#include "tetcut/detail/local_tables.hpp"

namespace tetcut::testing {

// Every live tet meeting the tool, by a scan of the mesh.
inline std::vector<TetId> scanned(const TetMesh& mesh, const Tool& tool) {
  std::vector<TetId> out;
  scan_tets_meeting(mesh, tool, out);
  return out;
}

inline void change_randomly(TetMesh& mesh, SplitMix64& rng, EdgeSplitter& splitter, bool remove) {
  const TetId t = random_live_tet(mesh, rng);
  if (remove) {
    mesh.remove_tets(std::span<const TetId>(&t, 1));
    return;
  }
  const int e = static_cast<int>(rng.below(6));
  const Edge edge{mesh.vertex(t, kEdgeVerts[e][0]), mesh.vertex(t, kEdgeVerts[e][1])};
  ASSERT_TRUE(splitter.split(mesh, std::span<const Edge>(&edge, 1), SplitMethod::kTemplates).ok());
}

}  // namespace tetcut::testing
