#include <gtest/gtest.h>

#include <algorithm>

#include "core/random.hpp"
#include "cut/spatial_index.hpp"
#include "cut/walking_locator.hpp"
#include "changing_mesh.hpp"
#include "test_meshes.hpp"

namespace tetcut {
namespace {

using testing::scanned;

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
  WalkingLocator locator;
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
    mesh.begin_transaction();
    testing::change_randomly(mesh, rng, splitter, round % 3 == 2);
    if (::testing::Test::HasFatalFailure()) return;
    commit_and_update(mesh, locator);
  }
  EXPECT_GT(nonempty, 300);
  EXPECT_EQ(locator.scans(), 0u);
}

// A point walk from every tet of a box to random points reaches the tet that holds the point,
// and says no tet for a point outside.
TEST(WalkingLocator, APointWalkFromAnyTetFindsTheTetHoldingThePoint) {
  TetMesh mesh = testing::build_or_fail(make_box_mesh(4, 3, 3, {0, 0, 0}, {4, 3, 3}));
  WalkingLocator locator;
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

// Removes, in one committed operation, the tets whose centroid `carve` accepts, and tells the
// locator.
template <class Carve>
void carve(TetMesh& mesh, WalkingLocator& locator, Carve carve) {
  std::vector<TetId> gone;
  for (std::uint32_t i = 0; i < mesh.tet_capacity(); ++i) {
    if (!mesh.is_live(TetId{i})) continue;
    const auto v = mesh.tet(TetId{i});
    const Vec3 c = 0.25 * (mesh.position(v[0]) + mesh.position(v[1]) + mesh.position(v[2]) + mesh.position(v[3]));
    if (carve(c)) gone.push_back(TetId{i});
  }
  mesh.begin_transaction();
  mesh.remove_tets(gone);
  commit_and_update(mesh, locator);
}

// A U: a notch of whole cubes cut from the top of a bar. A walk from one arm to a point in the
// other is blocked by the notch's wall; the segment's last crossing of the boundary enters the
// other arm, and the walk goes on from there, without a scan. A point in the notch is outside.
TEST(WalkingLocator, AWalkTheBoundaryBlocksGoesOnPastTheSegmentsLastCrossing) {
  TetMesh mesh = testing::build_or_fail(make_box_mesh(6, 2, 2, {0, 0, 0}, {6, 2, 2}));
  WalkingLocator locator;
  locator.build(mesh, 1.0);
  carve(mesh, locator, [](const Vec3& c) { return c.x > 2 && c.x < 4 && c.z > 1; });
  TetId left = kNoTet;
  for (std::uint32_t i = 0; i < mesh.tet_capacity() && !left.valid(); ++i) {
    if (!mesh.is_live(TetId{i})) continue;
    const auto v = mesh.tet(TetId{i});
    const Vec3 c = 0.25 * (mesh.position(v[0]) + mesh.position(v[1]) + mesh.position(v[2]) + mesh.position(v[3]));
    if (c.x < 1 && c.z > 1) left = TetId{i};
  }
  ASSERT_TRUE(left.valid());
  const Vec3 right_arm{5.3, 1.1, 1.7}, notch{3.0, 1.1, 1.5};
  const TetId found = locator.locate_point(mesh, right_arm, left);
  const std::vector<TetId> holding = scanned(mesh, Tool::ball(right_arm, 0.0));
  ASSERT_FALSE(holding.empty());
  EXPECT_TRUE(std::find(holding.begin(), holding.end(), found) != holding.end());
  EXPECT_GE(locator.blocked_walks(), 1u) << "the walk was meant to meet the notch";
  EXPECT_FALSE(locator.locate_point(mesh, notch, left).valid()) << "the notch is outside the mesh";
  EXPECT_EQ(locator.scans(), 0u);
}

// Two pieces, a slab of cubes apart: a ball across the gap finds the tets of both (each piece's
// boundary seeds its part), and a point inside the far piece is found by a walk from the near
// piece that the gap blocks.
TEST(WalkingLocator, AToolAcrossTwoPiecesFindsBoth) {
  TetMesh mesh = testing::build_or_fail(make_box_mesh(6, 3, 3, {0, 0, 0}, {6, 3, 3}));
  WalkingLocator locator;
  locator.build(mesh, 1.0);
  carve(mesh, locator, [](const Vec3& c) { return c.x > 2 && c.x < 3; });
  std::vector<TetId> got;
  const Tool across = Tool::ball({2.5, 1.5, 1.5}, 0.9);
  locator.query(mesh, across, got);
  ASSERT_EQ(got, scanned(mesh, across));
  bool near = false, far = false;
  for (TetId t : got) {
    const Vec3 p = mesh.position(mesh.tet(t)[0]);
    (p.x <= 2 ? near : far) = true;
  }
  EXPECT_TRUE(near && far) << "the ball meets both pieces";
  const Tool in_near = Tool::ball({1.5, 1.5, 1.5}, 0.3), in_far = Tool::ball({4.5, 1.5, 1.5}, 0.3);
  locator.query(mesh, in_near, got);
  ASSERT_EQ(got, scanned(mesh, in_near));
  ASSERT_FALSE(got.empty());
  // From the near piece's answer (the coarse grid would start the query in the far piece).
  const std::uint64_t blocked = locator.blocked_walks();
  const TetId found = locator.locate_point(mesh, in_far.a, got.front());
  const std::vector<TetId> holding = scanned(mesh, Tool::ball(in_far.a, 0.0));
  EXPECT_TRUE(std::find(holding.begin(), holding.end(), found) != holding.end());
  EXPECT_GT(locator.blocked_walks(), blocked) << "the walk from the near piece was meant to meet the gap";
  locator.query(mesh, in_far, got);
  ASSERT_EQ(got, scanned(mesh, in_far));
  EXPECT_FALSE(got.empty());
  EXPECT_EQ(locator.scans(), 0u);
}

}  // namespace
}  // namespace tetcut
