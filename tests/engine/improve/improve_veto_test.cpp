// The caller's acceptance hook (engine/src/improve/plan_veto.hpp): every operator's plan passes
// through it before the mesh changes, it sees the new tets where they will be, and a veto is
// honoured: nothing vetoed is applied, and the pass says how many it was refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <vector>

#include "checked.hpp"
#include "core/quality.hpp"
#include "improve/improver.hpp"
#include "improve/operation.hpp"
#include "improve/plan_veto.hpp"
#include "improve_test_support.hpp"

namespace tetcut::testing {
namespace {

// Near the coarse liver's surface, so that some children the pass cannot lift lie on it: every
// operator, sliver removal included, has something to plan.
constexpr Vec3 kNearSurface{125.5, 115.4, 110.7};
constexpr double kRadius = 1.5;

::testing::AssertionResult same_mesh(const TetMesh& a, const TetMesh& b) {
  if (!std::equal(a.raw_tets().begin(), a.raw_tets().end(), b.raw_tets().begin(), b.raw_tets().end()))
    return ::testing::AssertionFailure() << "the tets differ";
  if (!std::equal(a.positions().begin(), a.positions().end(), b.positions().begin(), b.positions().end()))
    return ::testing::AssertionFailure() << "the positions differ";
  return ::testing::AssertionSuccess();
}

// Counts the plans it is shown, by operator, and answers `verdict` to all of them.
struct CountingHook {
  detail::Refusal verdict = detail::Refusal::kNone;
  mutable std::array<int, detail::kOperatorCount> seen{};
  detail::Refusal operator()(const TetMesh&, const detail::Plan& plan) const {
    ++seen[static_cast<std::size_t>(plan.op)];
    return verdict;
  }
};

TEST(PlanVeto, AHookThatVetoesEverythingLeavesTheMeshBitForBitAndTheOutcomeSaysSo) {
  // Two refinements, near the surface and deep inside: between them every operator has a plan
  // that lifts a tet (a 2-3 flip rarely does near the surface).
  const CountingHook hook{.verdict = detail::Refusal::kVetoed};
  for (const Vec3& centre : {kNearSurface, Vec3{95, 100, 100}}) {
    Refined r = refined_liver(centre, kRadius);
    const TetMesh before = r.mesh;
    detail::Improver improver;
    const detail::ImproveOutcome outcome = improver.run(r.mesh, r.start, {.floor = 0.1, .veto = hook});
    EXPECT_TRUE(same_mesh(r.mesh, before));
    EXPECT_EQ(outcome.flips + outcome.collapses + outcome.moves + outcome.insertions + outcome.removed, 0u);
    EXPECT_GT(outcome.vetoed, 0u);
    EXPECT_EQ(outcome.refused[static_cast<std::size_t>(detail::Refusal::kVetoed)], outcome.vetoed);
    EXPECT_FALSE(outcome.met) << "the refinement made slivers and nothing was let through to lift them";
    EXPECT_EQ(outcome.worst_after, outcome.worst_before);
  }
  // Every operator was asked, and refused.
  for (std::size_t op = 0; op < detail::kOperatorCount; ++op)
    EXPECT_GT(hook.seen[op], 0) << to_string(static_cast<detail::Operator>(op)) << " never reached the hook";
}

TEST(PlanVeto, AHookThatLetsEverythingThroughChangesNothingAndSeesEachPlanAsItWillBe) {
  Refined with_hook = refined_liver(kNearSurface, kRadius);
  Refined without = refined_liver(kNearSurface, kRadius);
  // What a caller measures from a plan, without applying it, is what the pass measured.
  int shown = 0, mismatched = 0;
  auto measure = [&](const TetMesh& mesh, const detail::Plan& plan) {
    double worst = 1.0;
    for (const TetMesh::TetVerts& t : plan.added_tets()) {
      const std::array<Vec3, 4> x = plan.corners(mesh, t);
      worst = std::min(worst, quality(x[0], x[1], x[2], x[3]));
    }
    ++shown;
    mismatched += worst != plan.worst_after;
    return detail::Refusal::kNone;
  };
  detail::Improver a, b;
  const detail::ImproveOutcome hooked = a.run(with_hook.mesh, with_hook.start, {.floor = 0.1, .veto = measure});
  const detail::ImproveOutcome plain = b.run(without.mesh, without.start, {.floor = 0.1});
  EXPECT_GT(shown, 0);
  EXPECT_EQ(mismatched, 0);
  EXPECT_EQ(hooked.vetoed, 0u);
  EXPECT_TRUE(same_mesh(with_hook.mesh, without.mesh));
  EXPECT_EQ(hooked.flips, plain.flips);
  EXPECT_EQ(hooked.collapses, plain.collapses);
  EXPECT_EQ(hooked.moves, plain.moves);
  EXPECT_EQ(hooked.insertions, plain.insertions);
  EXPECT_EQ(hooked.worst_after, plain.worst_after);
}

TEST(PlanVeto, AVetoedOperatorIsNeverAppliedAndThePassLiftsByTheOthers) {
  Refined r = refined_liver(kNearSurface, kRadius);
  auto no_flips = [](const TetMesh&, const detail::Plan& plan) {
    const bool flip = plan.op == detail::Operator::kEdgeRemoval || plan.op == detail::Operator::kFaceRemoval;
    return flip ? detail::Refusal::kVetoed : detail::Refusal::kNone;
  };
  detail::Improver improver;
  const detail::ImproveOutcome outcome = improver.run(r.mesh, r.start, {.floor = 0.1, .veto = no_flips});
  EXPECT_EQ(outcome.flips, 0u);
  EXPECT_GT(outcome.vetoed, 0u) << "flips were planned, and refused";
  EXPECT_GT(outcome.collapses + outcome.moves + outcome.insertions, 0u);
  EXPECT_GT(outcome.worst_after, outcome.worst_before);
  r.mesh.commit();
  EXPECT_TRUE(mesh_is_valid(r.mesh, invariants::CheckLevel::kExact));
}

}  // namespace
}  // namespace tetcut::testing
