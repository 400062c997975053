// `tetcut replay` and `tetcut minimize`, run as a user runs them (design: fuzzing and triage):
// a fuzz input of a sequence target reads as a scenario that `tetcut run` accepts; a failing
// scenario shrinks to fewer operations that fail the same way.
#include <gtest/gtest.h>
#include <stdlib.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "cli_fixture.hpp"

namespace tetcut::test {
namespace {

const std::string kMeshDir = std::string(TETCUT_CORPUS_DIR) + "/meshes";

// The command-line fixture, with the bundled meshes where a fuzz input names them and no
// planted failure unless a test asks for one.
class ReplayMinimize : public Cli {
 protected:
  void SetUp() override {
    Cli::SetUp();
    ::setenv("TETCUT_MESH_DIR", kMeshDir.c_str(), 1);
    ::unsetenv("TETCUT_FUZZ_FAIL_AT");
  }
  void TearDown() override {
    ::unsetenv("TETCUT_FUZZ_FAIL_AT");
    Cli::TearDown();
  }

  std::string write_bytes(const std::string& name, const std::vector<unsigned char>& bytes) const {
    return write(name, std::string(bytes.begin(), bytes.end()));
  }

  static std::string read(const std::string& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  }
};

// Operation lines of a scenario: neither blank nor comments.
std::vector<std::string> operations(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    if (!line.empty() && line[0] != '#') out.push_back(line);
  return out;
}

// Inputs whose decoding depends only on the input and the mesh file: parameters, a sweep from
// the mesh as read, and points of the bounding box (no choice depends on what a cut did).
const std::vector<unsigned char> kSheetCut = {0x01, 0xff, 0x10, 0x20, 0x30, 0x40, 0x50, 0x60, 0x70};
const std::vector<unsigned char> kCylinderSweep = {0x01, 0x00, 0x01, 0x02, 0x03, 0x04, 0x05, 0x06, 0x07,
                                                   0x08, 0x09, 0x0a, 0x0b, 0x0c, 0x0d, 0x0e, 0x0f};

TEST_F(ReplayMinimize, ReplayPrintsTheInputAsAScenarioAndSaysItPasses) {
  const ProcessResult r = tetcut({"replay", write_bytes("in", kSheetCut), "--target", "cut_sequence"});
  ASSERT_TRUE(r.exited) << "signal " << r.signal;
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(r.out.starts_with("# tetcut replay --target cut_sequence (input version 1)\n"
                                "mesh " + kMeshDir + "/sheet.msh\n"
                                "max_tets_created 3350\n"  // the target's budget: the mesh's tets
                                "depth 1\n"
                                "iterations 1\n"
                                "sweep 2.19,5.31,-0.44 1.9,5.02,-0.73 0.5\n"
                                "# replay: passes"))
      << r.out;
  EXPECT_NE(r.out.find("# replay: passes"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("# scenario: passes under tetcut run"), std::string::npos) << r.out;

  const ProcessResult sweep = tetcut({"replay", write_bytes("sweep", kCylinderSweep), "--target", "cut_sequence"});
  EXPECT_EQ(sweep.exit_code, 0) << sweep.err;
  EXPECT_TRUE(sweep.out.starts_with("# tetcut replay --target cut_sequence (input version 1)\n"
                                    "mesh " + kMeshDir + "/cylinder.msh\n"
                                    "max_tets_created 3466\n"
                                    "cut -0.719,0.423,2.364\n"
                                    "cut -1.162,-1.181,-0.4\n"
                                    "check full\n"))
      << sweep.out;
}

TEST_F(ReplayMinimize, TheWrittenScenarioRunsUnderTetcutRun) {
  const std::string out = path("sub/case.scn");
  fs::create_directories(dir_ / "sub");
  const ProcessResult r = tetcut({"replay", write_bytes("in", kCylinderSweep), "--target", "cut_sequence",
                                  "--scenario-out", out});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string text = read(out);
  const std::string mesh_line = operations(text).at(0);
  ASSERT_TRUE(mesh_line.starts_with("mesh ")) << mesh_line;
  // Relative to the scenario's folder when both are in one tree, absolute otherwise (here the
  // temporary folder and the checkout): either way it names the bundled cylinder.
  const fs::path mesh = fs::path(mesh_line.substr(5));
  const fs::path resolved = mesh.is_absolute() ? mesh : (dir_ / "sub" / mesh);
  EXPECT_TRUE(fs::equivalent(resolved, kMeshDir + "/cylinder.msh")) << mesh_line;
  const ProcessResult run = tetcut({"run", out});
  EXPECT_EQ(run.exit_code, 0) << run.out << run.err;
}

TEST_F(ReplayMinimize, ReplayOfARemovalInputWritesTetsAsPoints) {
  // strategy / remove choices: whatever they decode to, every request is a "remove X,Y,Z".
  std::vector<unsigned char> input = {0x01};
  for (int i = 0; i < 40; ++i) input.push_back(static_cast<unsigned char>(37 * i + 11));
  const ProcessResult r = tetcut({"replay", write_bytes("in", input), "--target", "removal_sequence"});
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  const std::vector<std::string> ops = operations(r.out);
  ASSERT_GE(ops.size(), 3u) << r.out;
  EXPECT_TRUE(ops[0].starts_with("mesh ")) << ops[0];
  EXPECT_EQ(ops.back(), "check full") << "the final full check";
  std::size_t removes = 0;
  for (const std::string& op : ops) {
    EXPECT_TRUE(op.starts_with("mesh ") || op.starts_with("max_tets_created ") || op.starts_with("remove ") ||
                op.starts_with("strategy ") || op == "check full")
        << op;
    if (op.starts_with("remove ")) {
      ++removes;
      EXPECT_EQ(std::count(op.begin(), op.end(), ','), 2) << op;
    }
  }
  EXPECT_GT(removes, 0u) << r.out;
  EXPECT_NE(r.out.find("# scenario: passes under tetcut run"), std::string::npos) << r.out;
}

TEST_F(ReplayMinimize, AFailingOperationIsNamedWithItsScenarioLineAndExitsOne) {
  ::setenv("TETCUT_FUZZ_FAIL_AT", "2", 1);  // operation 2 (the second cut) fails
  const ProcessResult r = tetcut({"replay", write_bytes("in", kCylinderSweep), "--target", "cut_sequence"});
  ASSERT_TRUE(r.exited) << "signal " << r.signal;
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("# replay: FAILS at operation 2 (cut), scenario line 5: injected violated"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.err.find("operation 2 (cut), scenario line 5: injected violated"), std::string::npos) << r.err;
}

TEST_F(ReplayMinimize, ReplayRefusesBadUsageAndUnreadableInputWithExitTwo) {
  const std::string input = write_bytes("in", kSheetCut);
  EXPECT_EQ(tetcut({"replay", input}).exit_code, 2) << "no --target";
  EXPECT_EQ(tetcut({"replay", "--target", "cut_sequence"}).exit_code, 2) << "no INPUT";
  const ProcessResult unknown = tetcut({"replay", input, "--target", "msh22"});
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_NE(unknown.err.find("removal_sequence"), std::string::npos) << "lists the replayable targets: " << unknown.err;
  EXPECT_EQ(tetcut({"replay", path("missing"), "--target", "cut_sequence"}).exit_code, 2);
  const ProcessResult version = tetcut({"replay", write_bytes("v7", {0x07, 0x10, 0x20}), "--target", "cut_sequence"});
  EXPECT_EQ(version.exit_code, 2);
  EXPECT_NE(version.err.find("input version 1 to 6"), std::string::npos) << version.err;
  EXPECT_EQ(tetcut({"replay", write("empty", ""), "--target", "removal_sequence"}).exit_code, 2);
}

// A scenario made to fail: six cuts through a box, then a wrong tet count.
class Minimize : public ReplayMinimize {
 protected:
  std::string failing_scenario() const {
    const std::string mesh = path("box.msh");
    const WriteResult w = write_mesh(mesh, make_box_mesh(4, 4, 4));
    EXPECT_TRUE(w.ok) << w.error;
    return write("failing.scn",
                 "# six cuts, then an expectation no mesh here meets\n"
                 "mesh box.msh\n"
                 "diameter 0.3\n"
                 "cut 0.1234,0.5,0.5\n"
                 "cut 0.9,0.5,0.5\n"
                 "sweep 0.5,0.1,0.5 0.5,0.9,0.5 0.4\n"
                 "strategy neighbours\n"
                 "cut 0.5,0.5,0.05\n"
                 "expect tets 1\n");
  }
};

TEST_F(Minimize, ShrinksAFailingScenarioAndKeepsTheFailingExpectation) {
  const std::string in = failing_scenario();
  const ProcessResult before = tetcut({"run", in});
  ASSERT_EQ(before.exit_code, 1) << before.out << before.err;

  const std::string out = path("min/minimal.scn");
  fs::create_directories(dir_ / "min");
  const ProcessResult r = tetcut({"minimize", in, "-o", out});
  ASSERT_TRUE(r.exited) << "signal " << r.signal;
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  const std::vector<std::string> ops = operations(read(out));
  EXPECT_LT(ops.size(), operations(read(in)).size()) << read(out);
  EXPECT_NE(std::find(ops.begin(), ops.end(), "expect tets 1"), ops.end()) << read(out);
  EXPECT_EQ(ops.front(), "mesh ../box.msh") << "mesh paths relative to the output's folder";
  // Nothing left that the failure does not need: the wrong count fails on the mesh as read.
  EXPECT_EQ(ops, (std::vector<std::string>{"mesh ../box.msh", "expect tets 1"})) << read(out);

  const ProcessResult after = tetcut({"run", out});
  EXPECT_EQ(after.exit_code, 1) << "still fails";
  EXPECT_NE(after.err.find("expected 1 tets"), std::string::npos) << after.err;
}

TEST_F(Minimize, KeepsWhatTheFailureNeedsAndSimplifiesIt) {
  // The expectation holds only after the cuts (a count read from the run), so the minimizer
  // must keep cuts; it may turn the sweep into one cut and round the coordinates.
  const std::string mesh = path("box.msh");
  ASSERT_TRUE(write_mesh(mesh, make_box_mesh(4, 4, 4)).ok);
  const std::string passing = write("passing.scn",
                                    "mesh box.msh\ndiameter 0.3\nsweep 0.5,0.1,0.5 0.5,0.9,0.5 0.4\n"
                                    "cut 0.1234,0.5,0.5\n");
  const ProcessResult run = tetcut({"run", passing});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  // "... N tets left": the count after the cuts, written as a wrong "expect components" would
  // be too easy; instead expect the box's own count, which only holds when nothing was cut.
  const std::string in = write("failing.scn",
                               "mesh box.msh\ndiameter 0.3\nsweep 0.5,0.1,0.5 0.5,0.9,0.5 0.4\n"
                               "cut 0.1234,0.5,0.5\nexpect tets 384\n");
  const ProcessResult before = tetcut({"run", in});
  ASSERT_EQ(before.exit_code, 1) << before.out << before.err;
  const std::string out = path("minimal.scn");
  const ProcessResult r = tetcut({"minimize", in, "-o", out});
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  const std::vector<std::string> ops = operations(read(out));
  ASSERT_EQ(ops.size(), 3u) << "mesh, one cut, the expectation:\n" << read(out);
  EXPECT_EQ(ops[0], "mesh box.msh");
  EXPECT_TRUE(ops[1].starts_with("cut ")) << ops[1];
  EXPECT_EQ(ops[1].find("0.1234"), std::string::npos) << "coordinates rounded: " << ops[1];
  EXPECT_EQ(ops[2], "expect tets 384");
  EXPECT_EQ(tetcut({"run", out}).exit_code, 1);
}

TEST_F(Minimize, RefusesAPassingScenarioAndBadUsageWithExitTwo) {
  const std::string mesh = path("box.msh");
  ASSERT_TRUE(write_mesh(mesh, make_box_mesh(2, 2, 2)).ok);
  const std::string passing = write("passing.scn", "mesh box.msh\nexpect tets 48\n");
  const ProcessResult r = tetcut({"minimize", passing, "-o", path("out.scn")});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("passes"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(path("out.scn"))) << "nothing written";
  const std::string failing = write("failing.scn", "mesh box.msh\nexpect tets 1\n");
  EXPECT_EQ(tetcut({"minimize", failing}).exit_code, 2) << "no -o";
  EXPECT_EQ(tetcut({"minimize", path("missing.scn"), "-o", path("out.scn")}).exit_code, 2);
  EXPECT_EQ(tetcut({"minimize", write("bad.scn", "mesh box.msh\nfly 1,2,3\n"), "-o", path("out.scn")}).exit_code, 2);
  EXPECT_EQ(tetcut({"minimize", failing, "-o", path("out.scn"), "--max-runs", "0"}).exit_code, 2);
}

}  // namespace
}  // namespace tetcut::test
