// `tetcut simulate` as a user runs it, for what a first use tripped on: a second
// --sweep, a run that only settles, its summary, its messages' numbers, and the sweep's end,
// which `tetcut cut`, a scenario and `simulate` place the same way (scenario::sweep_centres);
// --swept, whose frames cut the capsules between sweep points; --debris-volume; and --haptic,
// a reader thread on the frames published, with each frame's reaction force.
#include <cmath>
#include <regex>
#include <utility>

#include "cli_fixture.hpp"

namespace tetcut::test {
namespace {

class Simulate : public Cli {
 protected:
  // A 4 x 4 x 4 box of side 1, in metres (--unit 1 keeps the numbers plain).
  std::string box() { return write_box("box.vtu", 4, 4, 4); }

  Json report_of(std::vector<std::string> args) {
    args.insert(args.begin(), "simulate");
    args.insert(args.end(), {"--report", path("r.json")});
    const ProcessResult r = tetcut(args);
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
    std::ifstream in(path("r.json"));
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    return parse_json(text).value_or(Json{});
  }
};

TEST_F(Simulate, ASecondSweepRunsAfterTheFirst) {
  const std::string mesh = box();
  const Json one = report_of({mesh, "--diameter", "0.2", "--unit", "1", "--steps", "1", "--sweep", "0.1,0.5,1", "0.9,0.5,1", "0.2"});
  const Json two = report_of({mesh, "--diameter", "0.2", "--unit", "1", "--steps", "1", "--sweep", "0.1,0.5,1", "0.9,0.5,1", "0.2",
                              "--fix", "x<0.01", "--sweep", "0.5,0.1,1", "0.5,0.9,1", "0.4"});
  ASSERT_EQ(one["frames"].size(), 5u);
  ASSERT_EQ(two["frames"].size(), 5u + 3u);
  EXPECT_EQ(two["frames"][5]["centre"], Json({0.5, 0.1, 1.0}));
  EXPECT_NEAR(two["frames"][7]["centre"][1].get<double>(), 0.9, 1e-12);
}

TEST_F(Simulate, SettlingAloneNeedsNoDiameterAndItsSummaryMeasuresTheSag) {
  const std::string mesh = box();
  const Json r = report_of({mesh, "--unit", "0.01", "--fix", "x<0.01", "--gravity", "0,0,-9.81", "--settle", "300"});
  EXPECT_EQ(r["summary"]["frames"], 0);
  EXPECT_GT(r["summary"]["max_displacement_m"].get<double>(), 1e-6) << "the cantilever sagged under gravity";
  // Cutting still needs the tool.
  const ProcessResult cut = tetcut({"simulate", mesh, "--unit", "0.01", "--sweep", "0.1,0.5,1", "0.9,0.5,1", "0.2"});
  EXPECT_EQ(cut.exit_code, 2);
  EXPECT_NE(cut.err.find("--diameter is required to cut"), std::string::npos) << cut.err;
}

TEST_F(Simulate, TheDefaultStepIsHalfTheStableStepEstimate) {
  const Json r = report_of({box(), "--unit", "0.01", "--fix", "x<0.01", "--settle", "1"});
  const double estimate = r["summary"]["stable_dt_initial"].get<double>();
  EXPECT_GT(estimate, 0.0);
  EXPECT_EQ(r["summary"]["dt_factor"].get<double>(), 0.5);
  EXPECT_DOUBLE_EQ(r["summary"]["dt"].get<double>(), 0.5 * estimate);
  const Json given = report_of({box(), "--unit", "0.01", "--fix", "x<0.01", "--settle", "1", "--dt", "1e-5"});
  EXPECT_TRUE(given["summary"]["dt_factor"].is_null());
  EXPECT_EQ(given["summary"]["dt"].get<double>(), 1e-5);
}

TEST_F(Simulate, ABlowUpSaysItsNumbersInScientificNotation) {
  const ProcessResult r = tetcut({"simulate", box(), "--diameter", "0.2", "--unit", "0.01", "--fix", "x<0.01", "--gravity",
                                  "0,0,-9.81", "--sweep", "0.1,0.5,1", "0.9,0.5,1", "0.2", "--dt", "0.01"});
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  const std::regex message(R"(blow-up at frame \d+: the energy went from -?\d\.\d{3}e[-+]\d+ J to -?\d\.\d{3}e[-+]\d+ J )"
                           R"(in 10 steps of 1\.000e-02 s \(stable step estimate \d\.\d{3}e[-+]\d+ s\))");
  EXPECT_TRUE(std::regex_search(r.err, message)) << r.err;
  EXPECT_EQ(r.err.find("0.000000"), std::string::npos) << r.err;
}

TEST_F(Simulate, TheEndOfASweepIsCutByCutRunAndSimulateWithinABillionthOfAStep) {
  // 0.7 / 0.1 is 6.999999999999999 in doubles: the end, 7 steps away, is the 8th cut.
  const std::string mesh = write_box("cube.vtu", 4, 4, 4);
  const std::vector<std::string> sweep = {"0.05,0.5,0.9", "0.75,0.5,0.9", "0.1"};
  ASSERT_LT(norm(Vec3{0.75, 0.5, 0.9} - Vec3{0.05, 0.5, 0.9}) / 0.1, 7.0);
  const Json simulated =
      report_of({mesh, "--diameter", "0.1", "--unit", "1", "--steps", "1", "--sweep", sweep[0], sweep[1], sweep[2]});
  EXPECT_EQ(simulated["frames"].size(), 8u);
  EXPECT_NEAR(simulated["frames"].back()["centre"][0].get<double>(), 0.75, 1e-12);
  const ProcessResult cut = tetcut({"cut", mesh, "--diameter", "0.1", "--from", sweep[0], "--to", sweep[1], "--step",
                                    sweep[2], "--report", path("cut.json")});
  ASSERT_EQ(cut.exit_code, 0) << cut.err;
  std::ifstream in(path("cut.json"));
  const Json cut_report = Json::parse(in);
  EXPECT_EQ(cut_report["summary"]["cuts"], 8);
  const std::string scenario = write("sweep.scn", "mesh cube.vtu\ndiameter 0.1\nsweep " + sweep[0] + " " + sweep[1] + " " +
                                                      sweep[2] + "\nexpect hash " +
                                                      cut_report["summary"]["hash"].get<std::string>() + "\n");
  const ProcessResult run = tetcut({"run", scenario});
  EXPECT_EQ(run.exit_code, 0) << run.out << run.err;
}

// --swept: a frame cuts the capsule from one sweep point to the next (one frame fewer), its
// record giving both ends; a scenario's `sweep ... swept` and `cut A B` are capsules too.
TEST_F(Simulate, SweptFramesCutFromEachSweepPointToTheNext) {
  const std::string mesh = box();
  const std::vector<std::string> sweep = {mesh, "--diameter", "0.2", "--unit", "1", "--steps", "1", "--sweep", "0.1,0.5,1",
                                          "0.9,0.5,1", "0.2"};
  const Json balls = report_of(sweep);
  std::vector<std::string> swept_args = sweep;
  swept_args.push_back("--swept");
  const Json swept = report_of(swept_args);
  ASSERT_EQ(balls["frames"].size(), 5u);
  ASSERT_EQ(swept["frames"].size(), 4u);
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_FALSE(balls["frames"][k].contains("end"));
    EXPECT_EQ(swept["frames"][k]["centre"], balls["frames"][k]["centre"]);
    EXPECT_EQ(swept["frames"][k]["end"], balls["frames"][k + 1]["centre"]);
  }
  EXPECT_EQ(swept["summary"]["cuts_refused"], 0);
  const std::string scenario = write("swept.scn", "mesh box.vtu\ndiameter 0.2\nsweep 0.1,0.5,1 0.9,0.5,1 0.2 swept\n"
                                                  "cut 0.5,0.1,1 0.5,0.9,1\n");
  const Json from_scenario = report_of({scenario, "--unit", "1", "--steps", "1"});
  ASSERT_EQ(from_scenario["frames"].size(), 5u);
  const std::vector<double> last_point = {0.9, 0.5, 1.0};  // the sweep's end, a whole number of steps away
  for (std::size_t i = 0; i < 3; ++i) EXPECT_NEAR(from_scenario["frames"][3]["end"][i].get<double>(), last_point[i], 1e-12);
  EXPECT_EQ(from_scenario["frames"][4]["end"], Json({0.5, 0.9, 1.0}));
  // Nothing to join: --swept without --sweep is a usage error.
  const ProcessResult alone = tetcut({"simulate", mesh, "--diameter", "0.2", "--swept"});
  EXPECT_EQ(alone.exit_code, 2);
  EXPECT_NE(alone.err.find("--swept"), std::string::npos) << alone.err;
}

// --debris-volume (a scenario's `debris_volume` line): the piece a stroke cuts off the plate goes in
// the frame that detached it, and the frame's record and the summary count it.
TEST_F(Simulate, DebrisVolumeRemovesThePieceAFrameDetachesAndTheReportCountsIt) {
  const WriteResult w = write_mesh(path("plate.msh"), make_box_mesh(16, 8, 2, {0, 0, -0.1}, {4, 2, 0.2}));
  ASSERT_TRUE(w.ok) << w.error;
  const std::vector<std::string> args = {path("plate.msh"), "--diameter", "0.5", "--unit", "1", "--steps", "1",
                                         "--fix", "x>3.9", "--sweep", "1,-0.3,0", "1,2.3,0", "2.6", "--swept"};
  auto debris_of = [](const Json& report) {
    return std::pair{report["summary"]["fragments"].get<int>(), report["summary"]["debris_pieces_removed"].get<int>()};
  };
  std::vector<std::string> with_debris = args;
  with_debris.insert(with_debris.end(), {"--debris-volume", "0.5"});
  const Json removed = report_of(with_debris);
  ASSERT_EQ(removed["frames"].size(), 1u);
  EXPECT_EQ(removed["frames"][0]["fragments"], 1);
  EXPECT_EQ(removed["frames"][0]["debris_pieces_removed"], 1);
  EXPECT_NEAR(removed["frames"][0]["debris_volume_removed"].get<double>(), 0.75 * 2 * 0.2, 0.075);
  EXPECT_EQ(debris_of(removed), std::pair(1, 1));
  EXPECT_EQ(debris_of(report_of(args)), std::pair(1, 0));  // detached, reported, left
  write("plate.scn", "mesh plate.msh\ndiameter 0.5\ndebris_volume 0.5\nsweep 1,-0.3,0 1,2.3,0 2.6 swept\n");
  EXPECT_EQ(debris_of(report_of({path("plate.scn"), "--unit", "1", "--steps", "1", "--fix", "x>3.9"})), std::pair(1, 1));
}

TEST_F(Simulate, AHapticThreadReadsWholeFramesWhileTheToolCutsAndEachFrameSaysTheToolsReaction) {
  // The cantilever sagging under gravity while the tool cuts across it: 2,000 steps a frame, so
  // that the run lasts tens of milliseconds and the reader, every millisecond, reads many frames.
  const std::vector<std::string> run = {box(),  "--diameter", "0.3",        "--unit",     "0.01",       "--fix", "x<0.01",
                                        "--gravity", "0,0,-9.81", "--steps", "2000", "--sweep", "0.3,0.5,1", "0.9,0.5,1",
                                        "0.15"};
  std::vector<std::string> with_reader = run;
  with_reader.push_back("--haptic");
  const Json r = report_of(with_reader);
  ASSERT_TRUE(r["summary"].contains("haptic")) << r.dump();
  const Json& haptic = r["summary"]["haptic"];
  EXPECT_GE(haptic["reads"].get<int>(), 1);
  EXPECT_EQ(haptic["torn"], 0);
  EXPECT_EQ(haptic["backwards"], 0);
  EXPECT_EQ(haptic["publishes"].get<std::size_t>(), r["frames"].size() + 1) << "the state before the first frame, then each";
  // The tissue pushes on the tool where the tool holds sagging tissue, and the figures do not
  // depend on the reader: the run without one gives the same forces.
  const Json alone = report_of(run);
  EXPECT_FALSE(alone["summary"].contains("haptic"));
  ASSERT_EQ(alone["frames"].size(), r["frames"].size());
  double largest = 0;
  for (std::size_t k = 0; k < r["frames"].size(); ++k) {
    const Json& f = r["frames"][k]["reaction_force_n"];
    ASSERT_EQ(f.size(), 3u);
    EXPECT_EQ(f, alone["frames"][k]["reaction_force_n"]) << "frame " << k;
    largest = std::max(largest, std::hypot(f[0].get<double>(), f[1].get<double>(), f[2].get<double>()));
  }
  EXPECT_GT(largest, 0.0);
}

}  // namespace
}  // namespace tetcut::test
