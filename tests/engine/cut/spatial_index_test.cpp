#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/random.hpp"
#include "cut/spatial_index.hpp"
#include "changing_mesh.hpp"
#include "test_meshes.hpp"

namespace tetcut {
namespace {

using testing::scanned;

TEST(ToolBall, DistanceToTetIsZeroInsideAndEuclideanOutside) {
  const Vec3 a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0}, d{0, 0, 1};
  EXPECT_EQ(distance_to_tet({0.1, 0.1, 0.1}, a, b, c, d), 0.0);
  EXPECT_EQ(distance_to_tet({0.5, 0.5, 0.0}, a, b, c, d), 0.0) << "on a face";
  EXPECT_NEAR(distance_to_tet({0.2, 0.2, -2.0}, a, b, c, d), 2.0, 1e-15) << "below a face";
  EXPECT_NEAR(distance_to_tet({-1, -1, -1}, a, b, c, d), std::sqrt(3.0), 1e-15) << "off a corner";
  EXPECT_NEAR(distance_to_tet({2, 0, 0}, a, b, c, d), 1.0, 1e-15) << "beyond a vertex";
  EXPECT_NEAR(distance_to_tet({1, 1, 1}, a, b, c, d), std::sqrt(3.0) - 1.0 / std::sqrt(3.0), 1e-12) << "above the slanted face";
}

TEST(ToolBall, IntersectsAgreesWithTheDistanceBeyondRounding) {
  // intersects() decides a ball in plain floating point (face planes, then the nearest face);
  // distance_to_tet() is the reference. On random positively oriented tets (as the mesh holds
  // them) and balls from tiny to larger than the tet, the two agree whenever the distance is not
  // within rounding of the radius, and a ball of radius 0 (a point) keeps the exact answer.
  SplitMix64 rng(11);
  auto coordinate = [&] { return 4.0 * rng.unit() - 2.0; };
  int meets = 0, misses = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    Vec3 q[4];
    for (Vec3& x : q) x = {coordinate(), coordinate(), coordinate()};
    if (dot(q[1] - q[0], cross(q[2] - q[0], q[3] - q[0])) < 0) std::swap(q[2], q[3]);
    const Tool ball = Tool::ball({coordinate(), coordinate(), coordinate()}, trial % 10 == 0 ? 0.0 : 2.0 * rng.unit() * rng.unit());
    const double distance = distance_to_tet(ball.a, q[0], q[1], q[2], q[3]);
    if (std::abs(distance - ball.radius) <= 1e-9 * (1.0 + ball.radius)) continue;
    const bool expected = distance <= ball.radius;
    ASSERT_EQ(intersects(ball, q[0], q[1], q[2], q[3]), expected) << "trial " << trial;
    (expected ? meets : misses)++;
  }
  EXPECT_GT(meets, 2000);
  EXPECT_GT(misses, 2000);
}

TEST(SpatialIndex, QueriesMatchAScanThroughSplitsAndRemovals) {
  TetMesh mesh = testing::build_or_fail(make_box_mesh(6, 5, 4, {0, 0, 0}, {6, 5, 4}));
  SpatialIndex index(1.0);
  index.build(mesh);
  SplitMix64 rng(5);
  EdgeSplitter splitter;
  std::vector<TetId> got;
  for (int round = 0; round < 40; ++round) {
    for (int q = 0; q < 10; ++q) {
      const Tool ball = Tool::ball({rng.unit() * 7 - 0.5, rng.unit() * 6 - 0.5, rng.unit() * 5 - 0.5}, rng.unit() * 1.5);
      index.query(mesh, ball, got);
      ASSERT_EQ(got, scanned(mesh, ball)) << "round " << round;
    }
    ChangeLog log;
    mesh.begin_transaction();
    testing::change_randomly(mesh, rng, splitter, round % 3 == 2);
    if (::testing::Test::HasFatalFailure()) return;
    mesh.commit(&log);
    index.apply(mesh, log);
  }
}

TEST(SpatialIndex, ABallOutsideTheMeshFindsNothing) {
  TetMesh mesh = testing::build_or_fail(make_box_mesh(2, 2, 2));
  SpatialIndex index(0.5);
  index.build(mesh);
  std::vector<TetId> got;
  index.query(mesh, {{5, 5, 5}, 1.0}, got);
  EXPECT_TRUE(got.empty());
  index.query(mesh, {{0.5, 0.5, 0.5}, 10.0}, got);
  EXPECT_EQ(got.size(), mesh.num_tets()) << "a ball swallowing the mesh finds every tet";
}

// A query walks the cells the index holds, not every cell of the ball's box: a ball larger than
// the mesh (a 1e6 tool on the liver) costs the same as one just engulfing it.
TEST(SpatialIndex, AQueryCostsWhatTheIndexHoldsNotWhatTheBallSpans) {
  TetMesh mesh = testing::build_or_fail(make_box_mesh(6, 5, 4, {0, 0, 0}, {6, 5, 4}));
  SpatialIndex index(1.0);
  index.build(mesh);
  std::vector<TetId> got;
  std::vector<std::uint64_t> cost;
  for (double radius : {10.0, 1e3, 1e6, 1e12}) {
    const std::uint64_t before = index.cells_visited();
    const Tool ball = Tool::ball({3, 2.5, 2}, radius);
    index.query(mesh, ball, got);
    cost.push_back(index.cells_visited() - before);
    ASSERT_EQ(got, scanned(mesh, ball));
    ASSERT_EQ(got.size(), mesh.num_tets());
    ASSERT_TRUE(std::is_sorted(got.begin(), got.end()));
  }
  // 7 x 6 x 5 cells are occupied (a tet on a cell boundary also lists the next cell).
  EXPECT_LE(cost.front(), 7u * 6u * 5u);
  for (std::uint64_t c : cost) EXPECT_EQ(c, cost.front()) << "the cost must not grow with the ball";
  // A ball centred far away whose box still covers the mesh, and one whose box misses it.
  index.query(mesh, {{1e9, 1e9, 1e9}, 2e9}, got);
  EXPECT_EQ(got.size(), mesh.num_tets());
  const std::uint64_t before = index.cells_visited();
  index.query(mesh, {{1e9, 1e9, 1e9}, 1e3}, got);
  EXPECT_TRUE(got.empty());
  EXPECT_EQ(index.cells_visited(), before) << "a box beyond the occupied bounds visits nothing";
}

// A mesh that fills little of its bounding box (a thin slab along the diagonal, here: a few
// tets at two far corners) must not make an engulfing query pay for the empty cells between.
TEST(SpatialIndex, ASparseIndexWalksItsCellsInsteadOfTheBox) {
  TetMesh mesh = testing::build_or_fail(make_box_mesh(16, 16, 16, {0, 0, 0}, {16, 16, 16}));
  SpatialIndex index(0.5);
  // Index the tets touching two opposite corners only, one at a time: the occupied bounds grow
  // with each insert, and every query sees what was inserted so far.
  std::vector<TetId> indexed;
  for (std::uint32_t t = 0; t < mesh.tet_capacity(); ++t) {
    const auto v = mesh.tet(TetId{t});
    bool near_corner = false;
    for (VertId x : v) {
      const Vec3 p = mesh.position(x);
      near_corner = near_corner || (p.x <= 1 && p.y <= 1 && p.z <= 1) || (p.x >= 15 && p.y >= 15 && p.z >= 15);
    }
    if (!near_corner) continue;
    index.insert(mesh, TetId{t});
    indexed.push_back(TetId{t});
  }
  ASSERT_FALSE(indexed.empty());
  std::vector<TetId> got;
  const std::uint64_t before = index.cells_visited();
  index.query(mesh, {{8, 8, 8}, 100}, got);
  EXPECT_EQ(got, indexed) << "sorted by id, exactly the indexed tets";
  EXPECT_LT(index.cells_visited() - before, 33u * 33u * 33u / 8) << "walked the table, not the 33^3 box";
}

}  // namespace
}  // namespace tetcut
