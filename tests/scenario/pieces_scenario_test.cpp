// Detached pieces in scenarios: `expect components N` takes the count the Cutter keeps
// (Cutter::pieces()) with a scan of the mesh as its witness, a cut's record carries the pieces it
// detached, and `debris_volume V` removes the small ones in the cut that detached them.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <unistd.h>

#include "tetcut/box_mesh.hpp"
#include "tetcut/io.hpp"
#include "tetcut/scenario/scenario.hpp"

namespace tetcut::scenario {
namespace {

// The plate of the engine's fragments test, coarser: 4 x 2 x 0.2 in 16 x 8 x 2 cells (1,536 tets).
// A capsule of diameter 0.5 across it at x = 1 cuts it through and detaches the side x < 0.75
// (volume about 0.3).
class ScenarioPieces : public ::testing::Test {
 protected:
  void SetUp() override {
    plate_ = (std::filesystem::temp_directory_path() / ("tetcut_pieces_" + std::to_string(::getpid()) + ".msh")).string();
    const WriteResult w = write_mesh(plate_, make_box_mesh(16, 8, 2, {0, 0, -0.1}, {4, 2, 0.2}));
    ASSERT_TRUE(w.ok) << w.error;
  }
  void TearDown() override { std::filesystem::remove(plate_); }

  // The plate, the tool, `settings`, the cut through it, then `after`.
  RunResult run_text(const std::string& settings, const std::string& after, const RunOptions& options = {}) const {
    const ParseResult p =
        parse("mesh " + plate_ + "\ndiameter 0.5\n" + settings + "cut 1,-0.3,0 1,2.3,0\n" + after, "t.scn", ".");
    EXPECT_TRUE(p.scenario) << p.error;
    return p.scenario ? run(*p.scenario, options) : RunResult{};
  }

  std::string plate_;
};

TEST_F(ScenarioPieces, ACutThroughThePlateLeavesTwoComponentsAndItsRecordHasThePiece) {
  const RunResult r = run_text("", "expect components 2\n");
  ASSERT_TRUE(r.ok) << r.error;
  ASSERT_EQ(r.cuts.size(), 1u);
  const CutRecord& cut = r.cuts[0];
  EXPECT_EQ(cut.report.fragments, 1u);
  ASSERT_EQ(cut.pieces.size(), 1u);
  EXPECT_GT(cut.pieces[0].tets, 0u);
  EXPECT_NEAR(cut.pieces[0].volume, 0.3, 0.075);
  EXPECT_LT(cut.pieces[0].centroid.x, 0.75);
  EXPECT_FALSE(cut.pieces[0].removed);
  const RunResult wrong = run_text("", "expect components 1\n");
  EXPECT_FALSE(wrong.ok);
  EXPECT_EQ(wrong.failed_line, 4u);
  EXPECT_EQ(wrong.reason, "expected 1 connected pieces, got 2");
}

TEST_F(ScenarioPieces, ADebrisVolumeRemovesThePieceInTheCutThatDetachedIt) {
  const RunResult r = run_text("debris_volume 0.5\n", "expect components 1\ncheck full\n");
  ASSERT_TRUE(r.ok) << r.error;  // the cut's local check, with the debris gone, and the full one
  const CutRecord& cut = r.cuts.at(0);
  EXPECT_EQ(cut.report.debris_pieces_removed, 1u);
  ASSERT_EQ(cut.pieces.size(), 1u);
  EXPECT_TRUE(cut.pieces[0].removed);
  EXPECT_EQ(cut.report.debris_tets_removed, cut.pieces[0].tets);
  // Debris is not tissue: the run's removals are the cut's tissue alone, as without debris.
  const RunResult kept = run_text("", "");
  EXPECT_EQ(r.removals, kept.removals);
  EXPECT_EQ(r.tets + cut.pieces[0].tets, kept.tets);
  // A piece above the volume stays.
  EXPECT_TRUE(run_text("debris_volume 0.1\n", "expect components 2\n").ok);
}

TEST_F(ScenarioPieces, AfterABoundedSearchTheScanCountsAndTheKeptCountMayBeShort) {
  RunOptions options;
  options.initial_params = CutParams{.fragment_search_bound = 10};
  const RunResult r = run_text("", "expect components 2\n", options);
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_TRUE(r.cuts.at(0).report.fragment_search_bounded);
  EXPECT_EQ(r.cuts.at(0).report.fragments, 0u);
  EXPECT_TRUE(r.cuts.at(0).pieces.empty());
}

TEST(ScenarioPiecesParse, DebrisVolumeIsAParameterLineCheckedAsTheOthers) {
  const ParseResult ok = parse("debris_volume 0.25\n", "t.scn", ".");
  ASSERT_TRUE(ok.scenario) << ok.error;
  EXPECT_EQ(ok.scenario->ops.at(0).kind, OpKind::kParam);
  EXPECT_EQ(ok.scenario->ops.at(0).text, "debris_volume");
  const ParseResult negative = parse("debris_volume -1\n", "t.scn", ".");
  EXPECT_FALSE(negative.scenario);
  EXPECT_NE(negative.error.find("t.scn:1: the debris volume must be"), std::string::npos) << negative.error;
  EXPECT_FALSE(parse("debris_volume x\n", "t.scn", ".").scenario);
}

}  // namespace
}  // namespace tetcut::scenario
