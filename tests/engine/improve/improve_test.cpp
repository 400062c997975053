// The improvement pass (engine/src/improve): each operation keeps the mesh a valid manifold and
// never lowers the worst tet it touches; the pass lifts what a cut made to I7's floor, which the
// independent checker then confirms, and without it the same cuts break the floor.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <string>

#include "checked.hpp"
#include "core/quality.hpp"
#include "improve/collapse.hpp"
#include "improve/flips.hpp"
#include "improve/improver.hpp"
#include "improve_test_support.hpp"
#include "tetcut/cut.hpp"
#include "tetcut/invariants/check.hpp"

namespace tetcut::testing {
namespace {

TEST(Improve, EveryFlipAndCollapseKeepsTheMeshValidAndLiftsTheWorstTetItTouches) {
  Refined r = refined_liver({95, 100, 100}, 1.5);
  TetMesh& mesh = r.mesh;
  invariants::LocalChecker local(mesh.raw_view());
  detail::Flipper flipper;
  detail::Collapser collapser;
  detail::Plan plan, collapse;
  std::vector<TetId> created, removed, made;
  int flips = 0, collapses = 0;
  for (TetId t : made_since(mesh, r.start)) {
    if (!mesh.is_live(t) || quality(mesh, t) >= 0.3) continue;
    // The best flip of the tet's edges and faces, else a collapse of one of its new vertices.
    bool applied = false;
    const TetMesh::Savepoint before = mesh.savepoint();
    for (int e = 0; e < 6 && !applied; ++e)
      if (flipper.plan_edge_removal(mesh, t, e, 1e-6, plan) == detail::Refusal::kNone) {
        EXPECT_GT(plan.worst_after, plan.worst_before);
        plan.apply(mesh, created);
        applied = true;
        ++flips;
      }
    for (int f = 0; f < 4 && !applied; ++f)
      if (flipper.plan_face_flip(mesh, t, f, 1e-6, plan) == detail::Refusal::kNone) {
        EXPECT_GT(plan.worst_after, plan.worst_before);
        plan.apply(mesh, created);
        applied = true;
        ++flips;
      }
    for (VertId v : mesh.tet(t)) {
      if (applied || !mesh.made_in_transaction(v)) continue;
      for (VertId w : mesh.tet(t))
        if (!applied && w != v && collapser.plan(mesh, v, w, 1e-6, 0.0, collapse) == detail::Refusal::kNone) {
          EXPECT_GT(collapse.worst_after, collapse.worst_before);
          collapse.apply(mesh, created);
          applied = true;
          ++collapses;
        }
    }
    if (!applied) continue;
    // The operation alone, as the local checker sees it: valid. I7's floors bind the transaction
    // (the pass's end), each created tet to its own host's: one operation lifts the worst tet it
    // touches (asserted above) but may leave a new tet below a better host's floor for the next.
    mesh.changes_since(before, removed, made);
    invariants::CheckOptions options;
    options.quality_rule = invariants::QualityRule::kReportOnly;
    const invariants::CheckReport report = local.after_operation(mesh.raw_view(), removed, made, options);
    ASSERT_TRUE(report.ok()) << invariants::to_string(report);
  }
  EXPECT_GT(flips, 0);
  EXPECT_GT(collapses + flips, 3);
  mesh.commit();
  EXPECT_TRUE(mesh_is_valid(mesh, invariants::CheckLevel::kExact));
}

TEST(Improve, ThePassLiftsWhatARefinementMadeToTheFloorAndMovesNoVertexThatWasThere) {
  Refined r = refined_liver({95, 100, 100}, 1.5);
  TetMesh& mesh = r.mesh;
  const TetMesh before_pass = mesh;
  double worst_made = 1.0;
  for (TetId t : made_since(mesh, r.start)) worst_made = std::min(worst_made, quality(mesh, t));
  ASSERT_LT(worst_made, 0.1) << "the refinement makes slivers: something to improve";
  detail::Improver improver;
  const detail::ImproveOutcome outcome = improver.run(mesh, r.start, {.floor = 0.1});
  EXPECT_TRUE(outcome.met);
  EXPECT_GE(outcome.worst_after, outcome.floor);
  EXPECT_GT(outcome.flips + outcome.collapses + outcome.moves + outcome.insertions, 0u);
  for (TetId t : made_since(mesh, r.start)) EXPECT_GE(quality(mesh, t), outcome.floor) << "tet " << t.value;
  // Only vertices the transaction made moved.
  for (std::uint32_t v = 0; v < before_pass.vertex_capacity(); ++v) {
    if (mesh.is_live(VertId{v}) && !mesh.made_in_transaction(VertId{v})) {
      EXPECT_EQ(mesh.position(VertId{v}), before_pass.position(VertId{v})) << "vertex " << v;
    }
  }
  mesh.commit();
  EXPECT_TRUE(mesh_is_valid(mesh, invariants::CheckLevel::kExact));
}

// A sweep through the liver whose cuts make slivers: with the pass off, the checker's floor (I7,
// on by default) is broken on some cut; with it on, on none, and every report says it was met.
TEST(Improve, WithoutThePassTheCheckerFindsSliversAndWithItNone) {
  for (const bool improve : {false, true}) {
    SCOPED_TRACE(improve ? "improve on" : "improve off");
    TetMesh mesh = corpus_mesh("liver.msh");
    const TetMesh original = mesh;
    Cutter cutter(mesh, {.tool_diameter = 8.0, .improve = improve});
    invariants::LocalChecker local(mesh.raw_view());
    int broken = 0, cuts = 0;
    for (double z : {60.0, 105.0, 150.0})
      for (double y = 40; y <= 180; y += 4) {
        const CutReport report = cutter.cut({95, y, z});
        ASSERT_TRUE(report.ok) << report.failure;
        ++cuts;
        const invariants::CheckReport check = local.after_operation(mesh.raw_view(), cutter.last_removed(), cutter.last_created());
        const bool floor_broken = check.find(invariants::Invariant::kI7Quality) != nullptr;
        broken += floor_broken;
        EXPECT_EQ(report.quality_met, !floor_broken) << "the engine and the checker agree on the floor";
        if (!improve) {
          EXPECT_EQ(report.improvement_flips + report.improvement_collapses + report.improvement_moves, 0u);
          EXPECT_EQ(report.min_radius_ratio, report.min_radius_ratio_before_improvement);
        } else {
          ASSERT_TRUE(check.ok()) << invariants::to_string(check);
        }
      }
    EXPECT_GT(cuts, 100);
    if (improve) {
      EXPECT_EQ(broken, 0);
      // Input vertices never move.
      for (std::uint32_t v = 0; v < original.vertex_capacity(); ++v) {
        if (mesh.is_live(VertId{v})) {
          EXPECT_EQ(mesh.position(VertId{v}), original.position(VertId{v}));
        }
      }
    } else {
      EXPECT_GT(broken, 0) << "the paper's algorithm alone makes tets below the floor on this sweep";
    }
    EXPECT_TRUE(mesh_is_valid(mesh));
  }
}

TEST(Improve, ACutThePassCannotLiftIsRefusedAndLeavesTheMeshAndTheStatisticsAsTheyWere) {
  // A floor no tet can reach (a radius ratio of 1 is the regular tet's): the pass cannot meet
  // min(1, the worst tet replaced) for every child, so the cut is refused, bit for bit.
  TetMesh mesh = corpus_mesh("liver.msh");
  const TetMesh before = mesh;
  Cutter cutter(mesh, {.tool_diameter = 8.0, .quality_floor = 1.0});
  CutReport report;
  for (double y = 40; y <= 180 && report.ok; y += 4) {
    const TetMesh snapshot = mesh;
    const RemovalReport statistics = cutter.removal_report();
    report = cutter.cut({95, y, 100});
    if (!report.ok) {
      EXPECT_NE(report.failure.find("quality floor"), std::string::npos) << report.failure;
      EXPECT_EQ(report.refusal, CutRefusal::kQualityFloor);
      EXPECT_GT(report.requests, 0u) << "the refused cut made removal requests before the pass";
      EXPECT_EQ(cutter.removal_report(), statistics) << "a refused cut counts none of its requests";
      EXPECT_EQ(mesh.raw_tets().size(), snapshot.raw_tets().size());
      EXPECT_TRUE(std::equal(mesh.raw_tets().begin(), mesh.raw_tets().end(), snapshot.raw_tets().begin()));
      EXPECT_TRUE(std::equal(mesh.positions().begin(), mesh.positions().end(), snapshot.positions().begin()));
    }
  }
  EXPECT_FALSE(report.ok) << "some cut of the sweep makes a child worse than its parent";
  // Off, the same floor is only reported.
  TetMesh again = before;
  Cutter off(again, {.tool_diameter = 8.0, .improve = false, .quality_floor = 1.0});
  for (double y = 40; y <= 180; y += 4) EXPECT_TRUE(off.cut({95, y, 100}).ok);
}

TEST(Improve, AnInvalidFloorIsRefusedWithAMessage) {
  for (const double floor : {-0.1, 1.5, std::numeric_limits<double>::quiet_NaN()}) {
    const auto message = validate(CutParams{.quality_floor = floor});
    ASSERT_TRUE(message.has_value());
    EXPECT_NE(message->find("quality floor"), std::string::npos);
  }
  EXPECT_FALSE(validate(CutParams{.quality_floor = 0.0}).has_value());
}

}  // namespace
}  // namespace tetcut::testing
