#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "checked.hpp"
#include "cut/spatial_index.hpp"
#include "refine/refine.hpp"
#include "test_meshes.hpp"
#include "tetcut/canonical_hash.hpp"
#include "tetcut/detail/local_tables.hpp"

namespace tetcut {
namespace {

// The tets whose centroid lies within `radius` of `centre`: a stand-in for the tool query.
std::vector<TetId> tets_near(const TetMesh& mesh, Vec3 centre, double radius) {
  std::vector<TetId> out;
  for (std::uint32_t t = 0; t < mesh.tet_capacity(); ++t) {
    if (!mesh.is_live(TetId{t})) continue;
    Vec3 c{};
    for (VertId v : mesh.tet(TetId{t})) c = c + 0.25 * mesh.position(v);
    if (norm(c - centre) <= radius) out.push_back(TetId{t});
  }
  return out;
}

double longest_edge(const TetMesh& mesh, std::span<const TetId> tets) {
  double longest = 0;
  for (TetId t : tets)
    for (int e = 0; e < 6; ++e)
      longest = std::max(longest, norm(mesh.position(mesh.vertex(t, kEdgeVerts[e][1])) - mesh.position(mesh.vertex(t, kEdgeVerts[e][0]))));
  return longest;
}

TEST(Refine, ParametersAreValidated) {
  EXPECT_TRUE(validate({.d_ref = 0.1}) == std::nullopt);
  EXPECT_TRUE(validate({.d_ref = 0.0}).has_value());
  EXPECT_TRUE(validate({.d_ref = -1.0}).has_value());
  EXPECT_TRUE(validate({.d_ref = std::numeric_limits<double>::quiet_NaN()}).has_value());
  EXPECT_TRUE(validate({.d_ref = 0.1, .p = 1.0}).has_value());
  EXPECT_TRUE(validate({.d_ref = 0.1, .p = std::numeric_limits<double>::infinity()}).has_value());
  EXPECT_TRUE(validate({.d_ref = 0.1, .max_iterations = 0}).has_value());
}

TEST(Refine, RefinesUntilEveryEdgeOfTheNewTetsIsShorterThanDref) {
  for (SplitMethod method : {SplitMethod::kTemplates, SplitMethod::kBisection}) {
    TetMesh mesh = testing::build_or_fail(make_box_mesh(4, 4, 4));
    const double volume = mesh.total_volume();
    const std::vector<TetId> hit = tets_near(mesh, {0.5, 0.5, 0.5}, 0.2);
    ASSERT_FALSE(hit.empty());
    Refiner refiner;
    std::vector<TetId> region;
    const RefineParams params{.d_ref = 0.1, .p = 1.5, .max_iterations = 10, .method = method, .focus = Tool::ball({0.5, 0.5, 0.5}, 0.2)};
    const RefineReport r = refiner.refine(mesh, hit, params, region);
    EXPECT_TRUE(r.converged);
    EXPECT_GE(r.iterations, 2u) << "edges of 0.25 to 0.43 need two halvings to get under 0.1";
    EXPECT_LE(r.iterations, 6u);
    EXPECT_GT(r.tets_created, 0u);
    EXPECT_GT(r.min_radius_ratio, 0.0);
    EXPECT_LT(r.min_radius_ratio, 1.0) << "the box's tets and their children are not regular";
    EXPECT_TRUE(testing::mesh_is_valid(mesh, invariants::CheckLevel::kFull, volume));
    // Every live tet of the region that meets the tool is short; the region holds only live tets.
    std::vector<TetId> in_tool;
    for (TetId t : region) {
      EXPECT_TRUE(mesh.is_live(t));
      if (tet_meets_tool(mesh, t, *params.focus)) in_tool.push_back(t);
    }
    EXPECT_FALSE(in_tool.empty());
    EXPECT_LE(longest_edge(mesh, in_tool), 0.1);
  }
}

TEST(Refine, TheQualityFigureIsOnlyMeasuredWhenAskedAndChangesNothing) {
  auto refine = [](bool measure, TetMesh& mesh) {
    const std::vector<TetId> hit = tets_near(mesh, {0.5, 0.5, 0.5}, 0.2);
    Refiner refiner;
    std::vector<TetId> region;
    RefineParams params{.d_ref = 0.1, .focus = Tool::ball({0.5, 0.5, 0.5}, 0.2)};
    params.measure_quality = measure;
    return refiner.refine(mesh, hit, params, region);
  };
  TetMesh measured = testing::build_or_fail(make_box_mesh(4, 4, 4));
  TetMesh unmeasured = measured;
  const RefineReport with = refine(true, measured);
  const RefineReport without = refine(false, unmeasured);
  EXPECT_LT(with.min_radius_ratio, 1.0);
  EXPECT_EQ(without.min_radius_ratio, 1.0) << "not measured: the documented neutral value";
  EXPECT_EQ(with.tets_created, without.tets_created);
  EXPECT_EQ(canonical_hash(measured), canonical_hash(unmeasured));
}

// A request on the tets near the centre of a 2x2x2 box.
class RefineTheCentreOfABox : public ::testing::Test {
 protected:
  void SetUp() override { ASSERT_FALSE(hit.empty()); }

  TetMesh mesh = testing::build_or_fail(make_box_mesh(2, 2, 2));
  const std::vector<TetId> hit = tets_near(mesh, {0.5, 0.5, 0.5}, 0.5);
  Refiner refiner;
  std::vector<TetId> region;
};

TEST_F(RefineTheCentreOfABox, NothingToDoWhenTheTetsAreAlreadySmall) {
  const RefineReport r = refiner.refine(mesh, hit, {.d_ref = 10.0}, region);
  EXPECT_EQ(r.iterations, 0u);
  EXPECT_EQ(r.tets_created, 0u);
  EXPECT_EQ(region.size(), hit.size());
}

TEST_F(RefineTheCentreOfABox, IterationBoundStopsTheLoop) {
  const RefineReport r = refiner.refine(mesh, hit, {.d_ref = 0.01, .max_iterations = 1}, region);
  EXPECT_EQ(r.iterations, 1u);
  EXPECT_FALSE(r.converged);
  EXPECT_TRUE(testing::mesh_is_valid(mesh));
}

// Paper 3.2: p close to 1 refines more widely, a large p adds no extra edges.
TEST(Refine, SmallerPSplitsMoreEdges) {
  auto run = [](double p) {
    TetMesh mesh = testing::build_or_fail(make_box_mesh(4, 4, 4));
    Refiner refiner;
    std::vector<TetId> region;
    return refiner.refine(mesh, tets_near(mesh, {0.5, 0.5, 0.5}, 0.3), {.d_ref = 0.2, .p = p, .focus = Tool::ball({0.5, 0.5, 0.5}, 0.2)},
                          region);
  };
  const RefineReport tight = run(1.05), loose = run(3.0);
  EXPECT_GT(tight.edges_split, loose.edges_split);
  EXPECT_GT(tight.tets_created, loose.tets_created);
}

// The budget is net. A loop needing several rounds makes children that it splits
// again; counting them twice would refuse a loop whose result fits.
TEST(Refine, ABudgetEqualToTheNetResultIsNeverRefusedAndOneLessIs) {
  auto run = [](std::uint32_t budget, RefineReport& report) {
    TetMesh mesh = testing::build_or_fail(make_box_mesh(4, 4, 4));
    Refiner refiner;
    std::vector<TetId> region;
    const RefineParams params{.d_ref = 0.1, .focus = Tool::ball({0.5, 0.5, 0.5}, 0.2), .max_tets_created = budget};
    report = refiner.refine(mesh, tets_near(mesh, {0.5, 0.5, 0.5}, 0.2), params, region);
    return mesh;
  };
  RefineReport free{};
  const TetMesh unbounded = run(UINT32_MAX, free);
  ASSERT_EQ(free.refusal, SplitRefusal::kNone);
  ASSERT_GE(free.iterations, 2u);
  ASSERT_GT(free.tets_created, free.net_tets_created) << "children split again: gross exceeds net";

  RefineReport exact{};
  const TetMesh fits = run(free.net_tets_created, exact);
  EXPECT_EQ(exact.refusal, SplitRefusal::kNone) << "a loop whose result fits its budget is not refused";
  EXPECT_EQ(exact.net_tets_created, free.net_tets_created);
  EXPECT_EQ(canonical_hash(fits), canonical_hash(unbounded));

  RefineReport tight{};
  const TetMesh refused = run(free.net_tets_created - 1, tight);
  EXPECT_EQ(tight.refusal, SplitRefusal::kOverBudget);
  EXPECT_LE(tight.net_tets_created, free.net_tets_created - 1);
  EXPECT_LT(tight.iterations, free.iterations) << "the round that would cross the budget is not applied";
  EXPECT_TRUE(testing::mesh_is_valid(refused)) << "stopped between rounds: a valid mesh for the caller to roll back";
}

TEST(Refine, ARefusedLoopCreatesAtMostItsBudget) {
  TetMesh mesh = testing::build_or_fail(make_box_mesh(4, 4, 4));
  const std::uint32_t before = mesh.num_tets();
  Refiner refiner;
  std::vector<TetId> region;
  // D_ref 0.002 on edges of 0.25: millions of tets without a budget.
  const RefineParams params{.d_ref = 0.002, .max_iterations = 20, .focus = Tool::ball({0.5, 0.5, 0.5}, 0.3), .max_tets_created = 300};
  const RefineReport r = refiner.refine(mesh, tets_near(mesh, {0.5, 0.5, 0.5}, 0.3), params, region);
  EXPECT_EQ(r.refusal, SplitRefusal::kOverBudget);
  EXPECT_LE(r.net_tets_created, 300u);
  EXPECT_LE(mesh.num_tets() - before, 300u);
  EXPECT_TRUE(validate(RefineParams{.d_ref = 1, .max_tets_created = 0}).has_value()) << "a zero budget is refused";
}

}  // namespace
}  // namespace tetcut
