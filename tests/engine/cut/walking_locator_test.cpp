#include <gtest/gtest.h>

#include <algorithm>

#include "core/random.hpp"
#include "cut/spatial_index.hpp"
#include "cut/walking_locator.hpp"
#include "refine/edge_split.hpp"
#include "test_meshes.hpp"
#include "tetcut/detail/local_tables.hpp"

namespace tetcut {
namespace {

std::vector<TetId> scanned(const TetMesh& mesh, const Tool& tool) {
  std::vector<TetId> out;
  scan_tets_meeting(mesh, tool, out);
  return out;
}

// Applies one committed operation to the locator as the Cutter does: net removed and created
// from the log, rewired from the journal before the commit.
void commit_and_update(TetMesh& mesh, WalkingLocator& locator) {
  std::vector<TetId> rewired, removed, created;
  mesh.rewired_tets(rewired);
  mesh.transaction_changes(removed, created);
  mesh.commit();
  locator.update(mesh, removed, created, rewired);
}

// The walk's answers equal a scan's through splits and removals that open cavities and leave
// the mesh's boundary far from convex: balls and capsules inside, across the boundary, outside,
// and points (radius 0: the tets holding a point, as Cutter::tet_containing() asks).
TEST(WalkingLocator, AnswersEqualAScanThroughSplitsAndRemovals) {
  TetMesh mesh = testing::build_or_fail(make_box_mesh(6, 5, 4, {0, 0, 0}, {6, 5, 4}));
  WalkingLocator locator(1.0);
  locator.build(mesh, 1.0);
  SplitMix64 rng(5);
  EdgeSplitter splitter;
  std::vector<TetId> got;
  int nonempty = 0;
  for (int round = 0; round < 60; ++round) {
    for (int q = 0; q < 12; ++q) {
      const Vec3 a{rng.unit() * 7 - 0.5, rng.unit() * 6 - 0.5, rng.unit() * 5 - 0.5};
      const double r = q % 4 == 0 ? 0.0 : rng.unit() * 1.2;
      const Tool tool = q % 3 == 1 ? Tool::capsule(a, a + Vec3{rng.unit() - 0.5, rng.unit() - 0.5, rng.unit() - 0.5}, r)
                                   : Tool::ball(a, r);
      locator.query(mesh, tool, got);
      ASSERT_EQ(got, scanned(mesh, tool)) << "round " << round << " query " << q;
      nonempty += !got.empty();
    }
    const TetId t = testing::random_live_tet(mesh, rng);
    mesh.begin_transaction();
    if (round % 3 == 2) {
      mesh.remove_tets(std::span<const TetId>(&t, 1));
    } else {
      const int e = static_cast<int>(rng.below(6));
      const Edge edge{mesh.vertex(t, kEdgeVerts[e][0]), mesh.vertex(t, kEdgeVerts[e][1])};
      ASSERT_TRUE(splitter.split(mesh, std::span<const Edge>(&edge, 1), SplitMethod::kTemplates).ok());
    }
    commit_and_update(mesh, locator);
  }
  EXPECT_GT(nonempty, 300);
  EXPECT_EQ(locator.scans(), 0u);
}

// A point walk from every tet of a box to random points reaches the tet that holds the point,
// and says no tet for a point outside.
TEST(WalkingLocator, APointWalkFromAnyTetFindsTheTetHoldingThePoint) {
  TetMesh mesh = testing::build_or_fail(make_box_mesh(4, 3, 3, {0, 0, 0}, {4, 3, 3}));
  WalkingLocator locator(1.0);
  locator.build(mesh, 1.0);
  SplitMix64 rng(9);
  for (std::uint32_t start = 0; start < mesh.tet_capacity(); ++start) {
    const Vec3 p{rng.unit() * 5 - 0.5, rng.unit() * 4 - 0.5, rng.unit() * 4 - 0.5};
    const TetId found = locator.locate_point(mesh, p, TetId{start});
    const std::vector<TetId> holding = scanned(mesh, Tool::ball(p, 0.0));
    if (holding.empty()) {
      EXPECT_FALSE(found.valid()) << "start " << start;
    } else {
      EXPECT_TRUE(std::find(holding.begin(), holding.end(), found) != holding.end()) << "start " << start;
    }
  }
  EXPECT_EQ(locator.scans(), 0u);
}

}  // namespace
}  // namespace tetcut
