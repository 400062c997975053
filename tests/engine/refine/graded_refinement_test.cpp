// The refinement graded to the tool (RefinementRule::kGraded, refine/longest_edge_bisection.hpp):
// what it promises on its own (every tet meeting the ball within D_ref, a valid mesh of the same
// volume, created tets not much worse than the ones they replace, the same bits every run, the
// budget) and inside a Cutter (cuts that keep the checker's rules, a refused cut rolled back).
//
// COST: 1.0 s of CPU in Release, 3.0 s under ASan (1.5 s and 5.1 s of wall time on the 2-core
// machine at load 6); the fine sweep with the checker after every cut is half of it.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "checked.hpp"
#include "core/random.hpp"
#include "core/tool.hpp"
#include "refine/refine.hpp"
#include "test_meshes.hpp"
#include "tetcut/canonical_hash.hpp"
#include "tetcut/cut.hpp"
#include "tetcut/detail/local_tables.hpp"
#include "tetcut/generators/shapes.hpp"
#include "tetcut/invariants/check.hpp"

namespace tetcut {
namespace {

double longest_edge(const TetMesh& mesh, TetId t) {
  double longest = 0.0;
  for (int e = 0; e < 6; ++e)
    longest = std::max(longest, norm(mesh.position(mesh.vertex(t, kEdgeVerts[e][1])) - mesh.position(mesh.vertex(t, kEdgeVerts[e][0]))));
  return longest;
}

// Every live tet meeting the ball, by a scan (the test's own locate, not the spatial index).
std::vector<TetId> tets_meeting(const TetMesh& mesh, const Tool& ball) {
  std::vector<TetId> out;
  for (std::uint32_t t = 0; t < mesh.tet_capacity(); ++t)
    if (mesh.is_live(TetId{t}) && tet_meets_tool(mesh, TetId{t}, ball)) out.push_back(TetId{t});
  return out;
}

double median_edge(const TetMesh& mesh) {
  std::vector<double> lengths;
  for (std::uint32_t t = 0; t < mesh.tet_capacity(); ++t) {
    if (!mesh.is_live(TetId{t})) continue;
    for (int e = 0; e < 6; ++e)
      lengths.push_back(norm(mesh.position(mesh.vertex(TetId{t}, kEdgeVerts[e][1])) -
                             mesh.position(mesh.vertex(TetId{t}, kEdgeVerts[e][0]))));
  }
  std::nth_element(lengths.begin(), lengths.begin() + static_cast<std::ptrdiff_t>(lengths.size() / 2), lengths.end());
  return lengths[lengths.size() / 2];
}

// The TetGen icosphere the fine-tool sweeps cut (3,088 tets, median edge about 0.23).
const TetMesh& sphere() {
  static const TetMesh mesh = [] {
    generators::GenResult made = generators::generate_sphere({.subdivisions = 2});
    if (!made.ok()) {
      ADD_FAILURE() << made.error;
      return TetMesh{};
    }
    return testing::build_or_fail(*made.mesh);
  }();
  return mesh;
}

struct Refined {
  RefineReport report;
  std::vector<TetId> removed, created;  // net, over the refinement's transaction
  double worst_replaced = 1.0, worst_created = 1.0;  // the checker's radius ratio
};

// One graded refinement around `ball`, in a transaction so that what it made is known.
Refined refine_graded(TetMesh& mesh, const Tool& ball, double d_ref, std::uint32_t budget = UINT32_MAX) {
  const TetMesh before = mesh;
  Refined out;
  const std::vector<TetId> hit = tets_meeting(mesh, ball);
  Refiner refiner;
  refiner.reserve(mesh.tet_capacity() * 2);
  std::vector<TetId> region;
  mesh.begin_transaction();
  out.report = refiner.refine(
      mesh, hit, {.rule = RefinementRule::kGraded, .d_ref = d_ref, .focus = ball, .max_tets_created = budget}, region);
  mesh.transaction_changes(out.removed, out.created);
  mesh.commit();
  if (!out.removed.empty()) out.worst_replaced = invariants::quality_of(before.raw_view(), out.removed).min_radius_ratio;
  if (!out.created.empty()) out.worst_created = invariants::quality_of(mesh.raw_view(), out.created).min_radius_ratio;
  return out;
}

struct ToolCase {
  const char* name;
  double edge_fraction;  // the tool's diameter over the mesh's median edge
};
const ToolCase kTools[] = {{"0.05", 0.05}, {"0.1", 0.1}, {"0.3", 0.3}, {"1", 1.0}};

// Balls at seeded random points of the sphere's bounding box (some reach the surface, some
// outside it meet nothing), for each tool size.
template <class Body>
void for_each_ball_in_the_sphere(int balls, Body body) {
  const double median = median_edge(sphere());
  SplitMix64 rng(45);
  for (const ToolCase& tool : kTools)
    for (int k = 0; k < balls; ++k) {
      const Vec3 centre{2 * rng.unit() - 1, 2 * rng.unit() - 1, 2 * rng.unit() - 1};
      const double diameter = tool.edge_fraction * median;
      SCOPED_TRACE(std::string("tool ") + tool.name + " x median edge, ball " + std::to_string(k));
      body(Tool::ball(centre, diameter / 2), 1.5 * diameter);
    }
}

TEST(GradedRefinement, EveryLiveTetMeetingTheBallEndsWithAllEdgesWithinDref) {
  int refined = 0;
  for_each_ball_in_the_sphere(4, [&](const Tool& ball, double d_ref) {
    TetMesh mesh = sphere();
    const Refined r = refine_graded(mesh, ball, d_ref);
    ASSERT_EQ(r.report.refusal, SplitRefusal::kNone);
    refined += r.report.edges_split > 0 ? 1 : 0;
    for (TetId t : tets_meeting(mesh, ball)) EXPECT_LE(longest_edge(mesh, t), d_ref) << "tet " << t.value;
  });
  EXPECT_GE(refined, 10) << "most balls are inside the sphere and need refining";
}

TEST(GradedRefinement, LeavesAValidMeshOfTheSameVolume) {
  for_each_ball_in_the_sphere(2, [](const Tool& ball, double d_ref) {
    TetMesh mesh = sphere();
    const double volume = mesh.total_volume();
    refine_graded(mesh, ball, d_ref);
    EXPECT_TRUE(testing::mesh_is_valid(mesh, invariants::CheckLevel::kFull, volume));
  });
}

// Rivara's bisection has no proved bound on the shape of tetrahedra; what it gives here, measured
// over these 64 balls: created tets at 0.147 of the worst radius ratio the refinement replaced or
// better (0.033 at worst, against 0.17-0.28 replaced). The paper's loop on the same balls: 0.003
// (0.001 at worst). The bound asserted keeps a margin below the measure.
TEST(GradedRefinement, CreatedTetsKeepATenthOfTheWorstRadiusRatioTheyReplace) {
  constexpr double kFactor = 0.1;
  for_each_ball_in_the_sphere(16, [&](const Tool& ball, double d_ref) {
    TetMesh mesh = sphere();
    const Refined r = refine_graded(mesh, ball, d_ref);
    if (r.created.empty()) return;
    EXPECT_GE(r.worst_created, kFactor * r.worst_replaced) << "replaced worst " << r.worst_replaced;
  });
}

TEST(GradedRefinement, TheSameInputGivesTheSameMeshBitForBit) {
  const Tool ball = Tool::ball({0.1, -0.2, 0.3}, 0.05 * median_edge(sphere()) / 2);
  TetMesh first = sphere(), second = sphere();
  const Refined a = refine_graded(first, ball, 3 * ball.radius), b = refine_graded(second, ball, 3 * ball.radius);
  ASSERT_GT(a.report.edges_split, 0u);
  EXPECT_EQ(a.report.edges_split, b.report.edges_split);
  EXPECT_EQ(canonical_hash(first), canonical_hash(second));
  EXPECT_EQ(first.raw_tets().size(), second.raw_tets().size());
  EXPECT_TRUE(std::equal(first.raw_tets().begin(), first.raw_tets().end(), second.raw_tets().begin()))
      << "the same ids too, not only the same shape";
}

// As the paper's loop: the budget is net, checked before each bisection, and a bisection over it
// is refused before it is applied.
TEST(GradedRefinement, ABudgetEqualToTheNetResultIsNeverRefusedAndOneLessIs) {
  const Tool ball = Tool::ball({-0.3, 0.2, 0.1}, 0.1 * median_edge(sphere()) / 2);
  TetMesh free_mesh = sphere();
  const Refined free = refine_graded(free_mesh, ball, 3 * ball.radius);
  ASSERT_EQ(free.report.refusal, SplitRefusal::kNone);
  ASSERT_GT(free.report.tets_created, free.report.net_tets_created) << "children bisected again: gross exceeds net";
  EXPECT_EQ(free.report.net_tets_created, free.created.size()) << "net: what the transaction made and kept";

  TetMesh fits_mesh = sphere();
  const Refined fits = refine_graded(fits_mesh, ball, 3 * ball.radius, free.report.net_tets_created);
  EXPECT_EQ(fits.report.refusal, SplitRefusal::kNone);
  EXPECT_EQ(canonical_hash(fits_mesh), canonical_hash(free_mesh));

  TetMesh short_mesh = sphere();
  const Refined over = refine_graded(short_mesh, ball, 3 * ball.radius, free.report.net_tets_created - 1);
  EXPECT_EQ(over.report.refusal, SplitRefusal::kOverBudget);
  EXPECT_LT(over.report.net_tets_created, free.report.net_tets_created);
  EXPECT_TRUE(testing::mesh_is_valid(short_mesh)) << "the bisections before the refused one stand, conforming";
}

// A sweep of the fine tool that the paper's rule cannot always serve (its coarse neighbours'
// children defeat the improvement pass): every graded cut keeps the checker's rules, I7 at the
// cut's floor and I10 with its tool, and leaves no tet meeting the tool with an edge over D_ref.
TEST(GradedRefinement, AFineSweepOnTheSphereCutsEveryTimeWithinTheCheckersRules) {
  TetMesh mesh = sphere();
  const double diameter = 0.05 * median_edge(mesh);
  const CutParams params{.tool_diameter = diameter, .refinement = RefinementRule::kGraded};
  Cutter cutter(mesh, params);
  invariants::LocalChecker local(mesh.raw_view());
  const Vec3 from{-0.9, 0.1, 0.05}, to{0.9, -0.1, 0.0};
  const int steps = 60;  // one cut every 0.03, about 2.6 tool diameters
  int cut = 0;
  for (int k = 0; k <= steps; ++k) {
    const Vec3 centre = from + (static_cast<double>(k) / steps) * (to - from);
    const CutReport r = cutter.cut(centre);
    ASSERT_TRUE(r.ok) << "cut " << k << ": " << r.failure;
    cut += r.tets_removed > 0 ? 1 : 0;
    const invariants::CheckReport report = local.after_operation(mesh.raw_view(), cutter.last_removed(),
                                                                 cutter.last_created(), testing::cut_check(cutter, centre));
    ASSERT_TRUE(report.ok()) << "cut " << k << ": " << invariants::to_string(report);
    for (TetId t : tets_meeting(mesh, Tool::ball(centre, diameter / 2)))
      EXPECT_LE(longest_edge(mesh, t), 1.5 * diameter) << "cut " << k << ", tet " << t.value;
  }
  EXPECT_GT(cut, steps / 2);
}

TEST(GradedRefinement, ACutOverItsBudgetIsRefusedSayingWhyAndRolledBackBitForBit) {
  TetMesh mesh = sphere();
  const auto before = canonical_hash(mesh);
  const std::vector<std::array<std::uint32_t, 4>> tets_before(mesh.raw_tets().begin(), mesh.raw_tets().end());
  Cutter cutter(mesh, {.tool_diameter = 0.05 * median_edge(mesh), .max_tets_created = 50,
                       .refinement = RefinementRule::kGraded});
  const CutReport r = cutter.cut({0.1, -0.2, 0.3});
  ASSERT_FALSE(r.ok);
  EXPECT_EQ(r.refusal, CutRefusal::kTetBudget);
  EXPECT_NE(r.failure.find("budget"), std::string::npos) << r.failure;
  EXPECT_EQ(canonical_hash(mesh), before);
  EXPECT_TRUE(std::equal(tets_before.begin(), tets_before.end(), mesh.raw_tets().begin(), mesh.raw_tets().end()));
}

// The same bits on every run and with every compiler: the hash is pinned, and ctest runs this
// in Release (GCC) and under ASan (clang).
TEST(GradedRefinement, TheSameSweepGivesThePinnedHashAndThePaperRuleAnother) {
  auto sweep = [](RefinementRule rule) {
    TetMesh mesh = sphere();
    Cutter cutter(mesh, {.tool_diameter = 0.3 * median_edge(mesh), .refinement = rule});
    for (int k = 0; k <= 12; ++k) cutter.cut(Vec3{-0.8 + 0.13 * k, 0.1, 0.05});
    return canonical_hash(mesh);
  };
  const std::uint64_t graded = sweep(RefinementRule::kGraded);
  EXPECT_EQ(graded, 0xaf2634dec9efaff0ull);
  EXPECT_EQ(graded, sweep(RefinementRule::kGraded));
  EXPECT_NE(graded, sweep(RefinementRule::kPaper));
  // The default, auto, takes the graded rule for a tool this fine for the mesh (D_ref 0.45 of
  // its median edge).
  EXPECT_EQ(CutParams{}.refinement, RefinementRule::kAuto);
  EXPECT_EQ(sweep(RefinementRule::kAuto), graded);
}

}  // namespace
}  // namespace tetcut
