// `undo` in scenarios (Cutter::undo()): with `undo_history N`, each `undo` line takes back the last
// cut, so a run that cuts A, cuts B and takes B back ends with the hash and the labels of the run
// that only cut A; a second `undo` takes A back too; one more has nothing to take back and fails
// at its line. Without `undo_history` the line fails with the reason. `tetcut simulate` refuses a
// scenario with an `undo` (its cuts are planned before they run).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "tetcut/box_mesh.hpp"
#include "tetcut/io.hpp"
#include "tetcut/scenario/scenario.hpp"

namespace tetcut::scenario {
namespace {

RunResult run_text(const std::string& text, const std::string& dir = TETCUT_CORPUS_DIR "/scenarios") {
  const ParseResult p = parse(text, "t.scn", dir);
  EXPECT_TRUE(p.scenario) << p.error;
  return p.scenario ? run(*p.scenario) : RunResult{};
}

const std::string kCylinder = "mesh ../meshes/cylinder.msh\ndiameter 0.4\nundo_history 4\n";
const std::string kCutA = "cut -0.4,0.1,2 0.6,-0.1,2.3\n", kCutB = "cut 0,0,3\n";

TEST(ScenarioUndo, AnUndoLineEndsWithTheHashOfTheRunWithoutTheCutItTookBack) {
  const RunResult none = run_text(kCylinder);
  const RunResult a = run_text(kCylinder + kCutA);
  const RunResult ab = run_text(kCylinder + kCutA + kCutB);
  ASSERT_TRUE(none.ok && a.ok && ab.ok) << none.error << a.error << ab.error;
  ASSERT_NE(a.hash, none.hash);
  ASSERT_NE(ab.hash, a.hash);
  const RunResult back_once = run_text(kCylinder + kCutA + kCutB + "undo\n");
  ASSERT_TRUE(back_once.ok) << back_once.error;
  EXPECT_EQ(back_once.undos, 1u);
  EXPECT_EQ(back_once.hash, a.hash);
  const RunResult back_twice = run_text(kCylinder + kCutA + kCutB + "undo\nundo\n");
  ASSERT_TRUE(back_twice.ok) << back_twice.error;
  EXPECT_EQ(back_twice.hash, none.hash);
  // B again after taking it back: the run that cut A then B.
  const RunResult again = run_text(kCylinder + kCutA + kCutB + "undo\n" + kCutB);
  ASSERT_TRUE(again.ok) << again.error;
  EXPECT_EQ(again.hash, ab.hash);
}

TEST(ScenarioUndo, AnUndoWithNothingToTakeBackFailsAtItsLine) {
  const RunResult r = run_text(kCylinder + kCutA + "undo\nundo\n");
  ASSERT_FALSE(r.ok);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.failed_line, 6u);
  EXPECT_NE(r.error.find("t.scn:6: undo refused: no cut to undo"), std::string::npos) << r.error;
  const RunResult unasked = run_text("mesh ../meshes/cylinder.msh\ndiameter 0.4\n" + kCutA + "undo\n");
  ASSERT_FALSE(unasked.ok);
  EXPECT_NE(unasked.error.find("undo_history is 0"), std::string::npos) << unasked.error;
  const ParseResult bad = parse("undo now\n", "t.scn", ".");
  EXPECT_FALSE(bad.scenario);
  EXPECT_EQ(bad.error, "t.scn:1: expected: undo");
  const ParseResult too_many = parse("undo_history 5000\n", "t.scn", ".");
  EXPECT_FALSE(too_many.scenario);
  EXPECT_NE(too_many.error.find("undo_history must be an integer between 0 and 4096"), std::string::npos) << too_many.error;
}

// A box whose tets carry two labels (a vessel along x): the labels the run ends with after cutting
// across the vessel twice and taking both cuts back are the file's, tet for tet.
TEST(ScenarioUndo, TheLabelsComeBackWithTheTets) {
  RawMesh box = make_box_mesh(6, 6, 6);
  box.labels.resize(box.tets.size(), 1);
  for (std::size_t t = 0; t < box.tets.size(); ++t) {
    Vec3 c{};
    for (std::uint32_t v : box.tets[t]) c = c + 0.25 * box.positions[v];
    if (std::hypot(c.y - 0.5, c.z - 0.5) < 0.2) box.labels[t] = 2;
  }
  const std::string dir = ::testing::TempDir() + "/undo_scenario";
  std::filesystem::create_directories(dir);
  ASSERT_TRUE(write_mesh(dir + "/vessel.msh", box).ok);
  const std::string head = "mesh vessel.msh\ndiameter 0.3\nundo_history 2\n";
  // The middle cut misses the box: it changes nothing, so neither the Cutter nor the labels keep it,
  // and the two undos take back the cuts either side of it.
  const std::string cuts = "cut 0.3,0.5,0.6\ncut 5,5,5\ncut 0.7,0.5,0.5\n";
  const RunResult none = run_text(head, dir);
  const RunResult one = run_text(head + "cut 0.3,0.5,0.6\n", dir);
  const RunResult back = run_text(head + cuts + "undo\n", dir);
  const RunResult all_back = run_text(head + cuts + "undo\nundo\n", dir);
  ASSERT_TRUE(none.ok && one.ok && back.ok && all_back.ok) << back.error << all_back.error;
  ASSERT_FALSE(none.labels.empty());
  EXPECT_EQ(back.hash, one.hash);
  EXPECT_EQ(all_back.hash, none.hash);
  // The meshes are bit for bit the same, so the ids are: compare the labels of the live tets.
  auto live_labels = [](const RunResult& r, const RunResult& reference) {
    std::vector<std::uint32_t> out;
    for (std::size_t t = 0; t < reference.labels.size(); ++t)
      if (reference.labels[t] != 0xFFFFFFFFu) out.push_back(t < r.labels.size() ? r.labels[t] : 0xFFFFFFFFu);
    return out;
  };
  EXPECT_EQ(live_labels(back, one), live_labels(one, one));
  EXPECT_EQ(live_labels(all_back, none), live_labels(none, none));
  std::uint32_t vessel = 0;
  for (std::uint32_t l : live_labels(all_back, none)) vessel += l == 2 ? 1 : 0;
  EXPECT_GT(vessel, 0u);
}

}  // namespace
}  // namespace tetcut::scenario
