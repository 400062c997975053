// The capsule in scenarios: `cut A B` is the engine's Cutter::cut_segment, `cut C C` is `cut C`,
// `sweep ... swept` joins the sweep's centres by capsules, and the local check after each of
// these cuts holds it to the tissue rule at its capsule (cut_check_options, ToolRule::end).
#include <gtest/gtest.h>

#include <string>

#include "tetcut/canonical_hash.hpp"
#include "tetcut/io.hpp"
#include "tetcut/mesh_builder.hpp"
#include "tetcut/scenario/scenario.hpp"

namespace tetcut::scenario {
namespace {

// The cylinder (radius 1, z from 0 to 4, 3,466 tets) and a tool of 0.4: each cut takes a few tets.
const std::string kCylinder = "mesh ../meshes/cylinder.msh\ndiameter 0.4\n";
const Vec3 kA{-0.4, 0.1, 2.0}, kB{0.6, -0.1, 2.3};

RunResult run_text(const std::string& text) {
  const ParseResult p = parse(text, "t.scn", TETCUT_CORPUS_DIR "/scenarios");
  EXPECT_TRUE(p.scenario) << p.error;
  return p.scenario ? run(*p.scenario) : RunResult{};
}

TetMesh cylinder() {
  ReadResult read = read_mesh(TETCUT_CORPUS_DIR "/meshes/cylinder.msh");
  EXPECT_TRUE(read.mesh);
  BuildResult built = build_mesh(*read.mesh);
  EXPECT_TRUE(built.ok());
  return std::move(*built.mesh);
}

CutParams tool_of_0_4() {
  CutParams params;
  params.tool_diameter = 0.4;
  return params;
}

TEST(ScenarioCapsule, ACutBetweenTwoPointsIsTheEnginesCutSegment) {
  const RunResult capsule = run_text(kCylinder + "cut -0.4,0.1,2 0.6,-0.1,2.3\n");
  ASSERT_TRUE(capsule.ok) << capsule.error;  // the local check after the cut, at its capsule
  ASSERT_EQ(capsule.cuts.size(), 1u);
  EXPECT_EQ(capsule.cuts[0].centre, kA);
  ASSERT_TRUE(capsule.cuts[0].end);
  EXPECT_EQ(*capsule.cuts[0].end, kB);

  TetMesh mesh = cylinder();
  Cutter cutter(mesh, tool_of_0_4());
  const CutReport r = cutter.cut_segment(kA, kB);
  ASSERT_TRUE(r.ok) << r.failure;
  EXPECT_EQ(capsule.hash, hash_to_hex(canonical_hash(mesh)));
  EXPECT_EQ(capsule.cuts[0].report.tets_removed, r.tets_removed);

  // Not the ball at either end: the capsule takes the tissue between them.
  const RunResult ball = run_text(kCylinder + "cut -0.4,0.1,2\n");
  ASSERT_TRUE(ball.ok) << ball.error;
  EXPECT_FALSE(ball.cuts[0].end);
  ASSERT_GT(ball.cuts[0].report.volume_removed, 0) << "the ball takes nothing: the comparison shows nothing";
  EXPECT_NE(ball.hash, capsule.hash);
  EXPECT_GT(capsule.cuts[0].report.volume_removed, 2 * ball.cuts[0].report.volume_removed);
}

TEST(ScenarioCapsule, AZeroLengthCapsuleIsTheBall) {
  const RunResult capsule = run_text(kCylinder + "cut 0.1,0.2,1.5 0.1,0.2,1.5\n");
  const RunResult ball = run_text(kCylinder + "cut 0.1,0.2,1.5\n");
  ASSERT_TRUE(capsule.ok) << capsule.error;
  ASSERT_TRUE(ball.ok) << ball.error;
  ASSERT_GT(ball.cuts.at(0).report.tets_removed, 0u) << "the ball takes nothing: the comparison shows nothing";
  EXPECT_EQ(capsule.hash, ball.hash);
  EXPECT_TRUE(capsule.cuts.at(0).end);  // recorded as written: a capsule, of zero length
  // A swept sweep of one centre is that ball too.
  const RunResult one = run_text(kCylinder + "sweep 0.1,0.2,1.5 0.1,0.2,1.5 0.1 swept\n");
  ASSERT_TRUE(one.ok) << one.error;
  ASSERT_EQ(one.cuts.size(), 1u);
  EXPECT_FALSE(one.cuts[0].end);
  EXPECT_EQ(one.hash, ball.hash);
}

// Samples two diameters apart: balls leave bridges of tissue between them, capsules do not.
TEST(ScenarioCapsule, ASweptSweepJoinsItsCentresAndTakesTheTissueBetweenThem) {
  const std::string sweep = "sweep -0.8,-0.3,2 0.8,-0.3,2 0.8";
  const RunResult balls = run_text(kCylinder + sweep + "\n");
  const RunResult swept = run_text(kCylinder + sweep + " swept\ncheck full\n");
  ASSERT_TRUE(balls.ok) << balls.error;
  ASSERT_TRUE(swept.ok) << swept.error;  // every cut's local check at its capsule, and the full check
  ASSERT_EQ(balls.cuts.size(), 3u);
  ASSERT_EQ(swept.cuts.size(), 2u);  // centre 0 to 1, 1 to 2
  for (std::size_t k = 0; k < swept.cuts.size(); ++k) {
    EXPECT_EQ(swept.cuts[k].centre, balls.cuts[k].centre);
    ASSERT_TRUE(swept.cuts[k].end);
    EXPECT_EQ(*swept.cuts[k].end, balls.cuts[k + 1].centre);
  }
  double ball_volume = 0, swept_volume = 0;
  for (const CutRecord& c : balls.cuts) ball_volume += c.report.volume_removed;
  for (const CutRecord& c : swept.cuts) swept_volume += c.report.volume_removed;
  EXPECT_GT(ball_volume, 0);
  EXPECT_GT(swept_volume, 1.5 * ball_volume);
  // The same cuts written one by one: the same mesh.
  const RunResult by_hand = run_text(kCylinder + "cut -0.8,-0.3,2 0,-0.3,2\ncut 0,-0.3,2 0.8,-0.3,2\n");
  ASSERT_TRUE(by_hand.ok) << by_hand.error;
  EXPECT_EQ(by_hand.hash, swept.hash);
}

// The checker gets the capsule: a ball cut at one end, checked as the capsule, leaves the tissue
// of the rest of the capsule (I10); the capsule cut passes the same check.
TEST(ScenarioCapsule, TheCutCheckOptionsCarryTheCapsule) {
  for (const bool capsule : {true, false}) {
    SCOPED_TRACE(capsule ? "capsule cut" : "ball cut");
    TetMesh mesh = cylinder();
    Cutter cutter(mesh, tool_of_0_4());
    invariants::LocalChecker local(mesh.raw_view());
    const CutReport r = capsule ? cutter.cut_segment(kA, kB) : cutter.cut(kA);
    ASSERT_TRUE(r.ok) << r.failure;
    const invariants::CheckOptions o = cut_check_options(cutter, kA, kB);
    ASSERT_TRUE(o.tool);
    ASSERT_TRUE(o.tool->end);
    EXPECT_EQ(*o.tool->end, kB);
    EXPECT_FALSE(cut_check_options(cutter, kA).tool->end);  // a ball, as before
    const invariants::CheckReport check = local.after_operation(mesh.raw_view(), cutter.last_removed(), cutter.last_created(), o);
    EXPECT_EQ(check.ok(), capsule) << (check.ok() ? "" : invariants::id_string(check.violations.front().id));
  }
}

}  // namespace
}  // namespace tetcut::scenario
