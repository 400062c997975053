// Every `tetcut` command owns its parser and its help (tools/tetcut/cmd_NAME.cpp): --help lists
// the command's options, a bad number or an unknown option is one line naming it plus the usage,
// exit 2. And the commands that share a runner agree with it: `tetcut cut` is the scenario
// sweep `tetcut run` runs, `tetcut remove --at` removes the tet `remove X,Y,Z` does.
#include <gtest/gtest.h>

#include <cstdint>
#include <algorithm>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "cli_fixture.hpp"

namespace tetcut::test {
namespace {

struct CommandCase {
  std::string name;
  std::vector<std::string> options;  // each must appear in the help
  std::vector<std::string> bad_number;  // arguments with one malformed number; empty: none
  std::string bad_option;              // the option the bad number is given to
};

// Arguments are completed by the test: "BOX" is a box mesh, "OUT" a path in the temp dir.
const std::vector<CommandCase>& cases() {
  static const std::vector<CommandCase> kCases = {
      {"info", {"MESH", "--json"}, {}, ""},
      {"check", {"MESH", "--level", "--min-radius-ratio", "--json"}, {"BOX", "--min-radius-ratio", "0.5x"}, "--min-radius-ratio"},
      {"convert", {"IN", "OUT", "--format", "--binary", "--compress", "--reorient"}, {}, ""},
      {"gen",
       {"cylinder", "--radius", "--segments", "sheet", "--thickness", "box", "--spacing", "surface",
        "--preserve-boundary", "liver", "--tets", "--seed", "-o"},
       {"cylinder", "--radius", "nan", "-o", "OUT"},
       "--radius"},
      {"repair", {"IN", "-o", "--verbose"}, {}, ""},
      {"refine",
       {"MESH", "--uniform", "--random-edges", "--seed", "--ball", "--dref", "--p", "--max-iterations", "--strategy",
        "-o", "--report"},
       {"BOX", "--random-edges", "-1", "-o", "OUT"},
       "--random-edges"},
      {"remove",
       {"MESH", "--at", "--random", "--seed", "--strategy", "--check", "-o", "--report"},
       {"BOX", "--random", "all", "--seed", "1e3", "-o", "OUT"},
       "--seed"},
      {"cut",
       {"MESH", "--diameter", "--from", "--to", "--step", "--swept", "--ids-along-curve", "--strategy", "--split", "--refinement", "--dref-factor", "--p",
        "--depth", "--debris-volume", "--check", "--out", "--report", "--frames"},
       {"BOX", "--diameter", "1e3x", "--from", "0,0,0", "--to", "1,1,1", "--step", "0.5"},
       "--diameter"},
      {"run", {"SCENARIO", "--refinement", "--debris-volume", "--check", "--out", "--report"}, {}, ""},
      {"stats", {"--corpus", "--mesh", "--check", "--json", "--html", "--pictures"}, {}, ""},
      {"replay", {"INPUT", "--target", "--scenario-out"}, {}, ""},
      {"minimize", {"SCENARIO", "-o", "--max-runs"}, {"BOX", "-o", "OUT", "--max-runs", "inf"}, "--max-runs"},
      {"simulate",
       {"INPUT", "--sweep", "--swept", "--diameter", "--strategy", "--debris-volume", "--fix", "--gravity", "--young", "--poisson", "--density",
        "--unit", "--damping", "--dt", "--steps", "--settle", "--frames", "--frame-every", "--report"},
       {"BOX", "--diameter", "1e3x", "--sweep", "0,0,0", "1,1,1", "0.5"},
       "--diameter"},
  };
  return kCases;
}

// Two lines on stderr, "tetcut NAME: ..." naming `what`, then "usage: tetcut NAME ...", exit 2.
::testing::AssertionResult usage_error(const ProcessResult& r, const std::string& name, const std::string& what) {
  auto failure = [&](const std::string& why) { return ::testing::AssertionFailure() << "tetcut " << name << ": " << why << "\n" << r.out << r.err; };
  if (!r.exited) return failure("did not exit");
  if (r.exit_code != 2) return failure("exit code " + std::to_string(r.exit_code) + ", not 2");
  if (!r.err.starts_with("tetcut " + name + ": ")) return failure("not prefixed with the command");
  if (r.err.find(what) == std::string::npos) return failure("does not name '" + what + "'");
  if (r.err.find("\nusage: tetcut " + name) == std::string::npos) return failure("no usage line");
  if (std::count(r.err.begin(), r.err.end(), '\n') != 2) return failure("not one line and the usage");
  return ::testing::AssertionSuccess();
}

TEST_F(Cli, EveryCommandsHelpListsItsOptions) {
  for (const CommandCase& c : cases()) {
    SCOPED_TRACE(c.name);
    const ProcessResult help = tetcut({c.name, "--help"});
    EXPECT_EQ(help.exit_code, 0) << help.err;
    EXPECT_TRUE(help.err.empty()) << help.err;
    EXPECT_TRUE(help.out.starts_with("usage: tetcut " + c.name)) << help.out;
    EXPECT_NE(help.out.find("exit: 0"), std::string::npos) << help.out;
    for (const std::string& option : c.options) EXPECT_NE(help.out.find(option), std::string::npos) << option;
    EXPECT_EQ(tetcut({"help", c.name}).out, help.out);
  }
}

TEST_F(Cli, EveryCommandRefusesAnUnknownOptionInOneLine) {
  for (const CommandCase& c : cases()) {
    SCOPED_TRACE(c.name);
    EXPECT_TRUE(usage_error(tetcut({c.name, "--no-such-option"}), c.name, "--no-such-option"));
  }
}

TEST_F(Cli, EveryCommandRefusesAMalformedNumberNamingTheOption) {
  const std::string box = write_box("box.msh", 1, 1, 1);
  for (const CommandCase& c : cases()) {
    if (c.bad_number.empty()) continue;
    SCOPED_TRACE(c.name);
    std::vector<std::string> args = {c.name};
    for (const std::string& a : c.bad_number) args.push_back(a == "BOX" ? box : a == "OUT" ? path("out.msh") : a);
    EXPECT_TRUE(usage_error(tetcut(args), c.name, c.bad_option + ": expects"));
    EXPECT_FALSE(fs::exists(path("out.msh")));
  }
}

TEST_F(Cli, CutRefusesNumbersThatAreNotWhatTheUserWrote) {
  const std::string box = write_box("box.msh", 1, 1, 1);
  for (const char* bad : {"nan", "inf", "", " 1", "0x10", "1e999", "1e3x"}) {
    const ProcessResult r =
        tetcut({"cut", box, "--diameter", bad, "--from", "0,0,0", "--to", "1,1,1", "--step", "0.5"});
    EXPECT_TRUE(usage_error(r, "cut", std::string("--diameter: expects a finite number, not '") + bad + "'"));
  }
  EXPECT_TRUE(usage_error(tetcut({"cut", box, "--diameter", "-1", "--from", "0,0,0", "--to", "1,1,1", "--step", "0.5"}),
                          "cut", "diameter"));
  EXPECT_TRUE(usage_error(tetcut({"cut", box, "--diameter", "0.5", "--from", "0,0,0", "--to", "1,1,1", "--step", "0.5",
                                  "--depth", "99999999999999999999"}),
                          "cut", "--depth: expects a non-negative integer"));
}

std::string read_text(const std::string& p) {
  std::ifstream in(p);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// A report file that is JSON with a summary, or nothing (with a failure saying why).
std::optional<Json> report_summary(const std::string& p) {
  const std::string text = read_text(p);
  const auto json = parse_json(text);
  EXPECT_TRUE(json && json->contains("summary")) << p << ":\n" << text;
  return json && json->contains("summary") ? json : std::nullopt;
}

// The part of a run's report that does not depend on time.
Json counts_of(const Json& report) {
  Json s = report.at("summary");
  for (const char* t : {"first_us", "p50_us", "p90_us", "p99_us", "max_us"}) s.erase(t);
  return s;
}

TEST_F(Cli, CutIsTheScenarioSweepThatRunRuns) {
  write_box("box.msh", 5, 5, 5);
  const ProcessResult cut = tetcut({"cut", path("box.msh"), "--diameter", "0.3", "--from", "0.1,0.5,0.5", "--to",
                                    "0.9,0.5,0.5", "--step", "0.2", "--strategy", "neighbours", "--split", "bisection",
                                    "--out", path("cut.msh"), "--report", path("cut.json")});
  ASSERT_EQ(cut.exit_code, 0) << cut.err;
  write("sweep.scn",
        "mesh box.msh\ndiameter 0.3\nstrategy neighbours\nsplit bisection\nsweep 0.1,0.5,0.5 0.9,0.5,0.5 0.2\n");
  const ProcessResult run = tetcut({"run", path("sweep.scn"), "--out", path("run.msh"), "--report", path("run.json")});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto cut_report = parse_json(read_text(path("cut.json")));
  const auto run_report = parse_json(read_text(path("run.json")));
  ASSERT_TRUE(cut_report && run_report);
  EXPECT_EQ(counts_of(*cut_report), counts_of(*run_report));
  EXPECT_EQ(cut_report->at("summary").at("cuts").get<int>(), 5);
  EXPECT_GT(cut_report->at("summary").at("tets_removed").get<int>(), 0);
  EXPECT_EQ(read_text(path("cut.msh")), read_text(path("run.msh")));
}

// `tetcut cut --ids-along-curve` is the scenario's `compact` after `mesh`: the same mesh, file for
// file, and a valid one; the file's order otherwise, which a shuffled box shows apart.
TEST_F(Cli, CutIdsAlongCurveIsTheScenarioCompactAfterTheMesh) {
  write_box("box.msh", 4, 4, 4);
  const auto cut = [&](const std::string& name, bool along_curve) {
    std::vector<std::string> args = {"cut", path("box.msh"), "--diameter", "0.3", "--from", "0.1,0.5,0.5", "--to",
                                     "0.9,0.5,0.5", "--step", "0.2", "--out", path(name + ".msh")};
    if (along_curve) args.push_back("--ids-along-curve");
    const ProcessResult r = tetcut(args);
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;  // every cut checked locally
    return r;
  };
  cut("file-order", false);
  cut("along-curve", true);
  write("curve.scn", "mesh box.msh\ncompact\ndiameter 0.3\nsweep 0.1,0.5,0.5 0.9,0.5,0.5 0.2\n");
  ASSERT_EQ(tetcut({"run", path("curve.scn"), "--out", path("run.msh")}).exit_code, 0);
  EXPECT_EQ(read_text(path("run.msh")), read_text(path("along-curve.msh")));
  write("kept.scn", "mesh box.msh\ncompact kept\ndiameter 0.3\nsweep 0.1,0.5,0.5 0.9,0.5,0.5 0.2\n");
  ASSERT_EQ(tetcut({"run", path("kept.scn"), "--out", path("kept.msh")}).exit_code, 0);
  EXPECT_EQ(read_text(path("kept.msh")), read_text(path("file-order.msh")));  // a fresh box has no gaps
  EXPECT_NE(read_text(path("along-curve.msh")), read_text(path("file-order.msh")));  // the ids differ
  EXPECT_EQ(tetcut({"check", path("along-curve.msh")}).exit_code, 0);
  write("bad.scn", "mesh box.msh\ncompact sideways\n");
  const ProcessResult bad = tetcut({"run", path("bad.scn")});
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("bad.scn:2: expected: compact [kept]"), std::string::npos) << bad.err;
}

// `tetcut cut --swept` joins the cut points by capsules: one cut fewer, each from one point to the
// next (its JSON record gives both: "centre" and "end"; a ball's record has no "end"), taking the
// tissue the balls leave between points two diameters apart; and it is the scenario's `sweep ...
// swept`, as `tetcut cut` is the scenario sweep.
TEST_F(Cli, CutSweptJoinsTheCutPointsByCapsulesAndTheReportGivesBothEnds) {
  write_box("box.msh", 5, 5, 5);
  auto cut = [&](const std::string& name, bool swept) {
    std::vector<std::string> args = {"cut", path("box.msh"), "--diameter", "0.15", "--from", "0.2,0.5,0.5", "--to",
                                     "0.8,0.5,0.5", "--step", "0.3", "--out", path(name + ".msh"), "--report",
                                     path(name + ".json")};
    if (swept) args.push_back("--swept");
    const ProcessResult r = tetcut(args);
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;  // every cut checked locally, at its capsule
    return report_summary(path(name + ".json")).value_or(Json{});
  };
  const Json balls = cut("balls", false), capsules = cut("capsules", true);
  ASSERT_EQ(balls.at("cuts").size(), 3u);
  ASSERT_EQ(capsules.at("cuts").size(), 2u);
  // In the file's order: a ball's record keeps its keys, index, line, centre, ok, ...; a capsule's
  // has its end after its centre.
  const auto ordered = [&](const std::string& name) { return nlohmann::ordered_json::parse(read_text(path(name))); };
  // Named: a range-for over a temporary's member outlives the temporary.
  const nlohmann::ordered_json ordered_balls = ordered("balls.json"), ordered_capsules = ordered("capsules.json");
  for (const auto& c : ordered_balls.at("cuts")) {
    EXPECT_FALSE(c.contains("end"));
    EXPECT_EQ(std::next(c.begin(), 3).key(), "ok");
  }
  for (const auto& c : ordered_capsules.at("cuts")) EXPECT_EQ(std::next(c.begin(), 3).key(), "end");
  for (std::size_t k = 0; k < 2; ++k) {
    const Json& c = capsules.at("cuts").at(k);
    EXPECT_EQ(c.at("centre"), balls.at("cuts").at(k).at("centre"));
    EXPECT_EQ(c.at("end"), balls.at("cuts").at(k + 1).at("centre"));
  }
  EXPECT_GT(balls.at("summary").at("volume_removed").get<double>(), 0);
  EXPECT_GT(capsules.at("summary").at("volume_removed").get<double>(),
            1.5 * balls.at("summary").at("volume_removed").get<double>());
  write("swept.scn", "mesh box.msh\ndiameter 0.15\nsweep 0.2,0.5,0.5 0.8,0.5,0.5 0.3 swept\n");
  ASSERT_EQ(tetcut({"run", path("swept.scn"), "--out", path("run.msh")}).exit_code, 0);
  EXPECT_EQ(read_text(path("run.msh")), read_text(path("capsules.msh")));
  EXPECT_NE(read_text(path("balls.msh")), read_text(path("capsules.msh")));
}

// A stroke through a plate detaches the side it cuts off: the cut's record says so after its other
// keys ("fragments": 1 and the piece's size and place, never its tets' ids), and the summary and
// stdout count it; --debris-volume removes the piece in the same cut, counted apart from the
// tissue, as `tetcut run --debris-volume` and a scenario's `debris_volume` line do.
TEST_F(Cli, CutThroughAPlateReportsThePieceItDetachedAndDebrisVolumeRemovesIt) {
  // The plate of the engine's fragments test, coarser: 4 x 2 x 0.2 in 16 x 8 x 2 cells.
  const WriteResult w = write_mesh(path("plate.msh"), make_box_mesh(16, 8, 2, {0, 0, -0.1}, {4, 2, 0.2}));
  ASSERT_TRUE(w.ok) << w.error;
  auto cut = [&](const std::string& name, const std::vector<std::string>& extra) {
    std::vector<std::string> args = {"cut", path("plate.msh"), "--diameter", "0.5", "--from", "1,-0.3,0", "--to",
                                     "1,2.3,0", "--step", "2.6", "--swept", "--out", path(name + ".msh"), "--report",
                                     path(name + ".json")};
    args.insert(args.end(), extra.begin(), extra.end());
    const ProcessResult r = tetcut(args);
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
    return r;
  };
  const ProcessResult kept = cut("kept", {});
  const auto ordered = nlohmann::ordered_json::parse(read_text(path("kept.json")));
  ASSERT_EQ(ordered.at("cuts").size(), 1u);  // one capsule across the plate
  const auto& record = ordered.at("cuts").at(0);
  // The keys there before keep their places: the new ones follow "retries".
  std::vector<std::string> keys;
  for (auto it = record.begin(); it != record.end(); ++it) keys.push_back(it.key());
  const auto after_retries = std::find(keys.begin(), keys.end(), "retries");
  ASSERT_NE(after_retries, keys.end());
  EXPECT_EQ(std::vector<std::string>(after_retries + 1, keys.end()),
            (std::vector<std::string>{"pieces_us", "fragments", "fragment_tets_visited", "fragment_search_bounded",
                                      "debris_pieces_removed", "debris_tets_removed", "debris_volume_removed", "pieces"}));
  EXPECT_EQ(record.at("fragments"), 1);
  EXPECT_EQ(record.at("fragment_search_bounded"), false);
  EXPECT_GT(record.at("fragment_tets_visited").get<int>(), 0);
  EXPECT_EQ(record.at("debris_pieces_removed"), 0);
  ASSERT_EQ(record.at("pieces").size(), 1u);
  const auto& piece = record.at("pieces").at(0);
  std::vector<std::string> piece_keys;
  for (auto it = piece.begin(); it != piece.end(); ++it) piece_keys.push_back(it.key());
  EXPECT_EQ(piece_keys, (std::vector<std::string>{"tets", "volume", "centroid", "removed"}));
  EXPECT_GT(piece.at("tets").get<int>(), 0);
  EXPECT_NEAR(piece.at("volume").get<double>(), 0.75 * 2 * 0.2, 0.075);  // the side x < 0.75
  EXPECT_LT(piece.at("centroid").at(0).get<double>(), 0.75);
  EXPECT_EQ(piece.at("removed"), false);
  EXPECT_EQ(ordered.at("summary").at("fragments"), 1);
  EXPECT_EQ(ordered.at("summary").at("debris_pieces_removed"), 0);
  EXPECT_NE(kept.out.find("pieces: 1 detached by 1 cuts, 0 removed as debris (0 tets, volume 0)\n"), std::string::npos)
      << kept.out;

  const ProcessResult debris = cut("debris", {"--debris-volume", "0.5"});
  const Json report = parse_json(read_text(path("debris.json"))).value_or(Json{});
  const Json& r = report.at("cuts").at(0);
  EXPECT_EQ(r.at("fragments"), 1);
  EXPECT_EQ(r.at("debris_pieces_removed"), 1);
  EXPECT_EQ(r.at("debris_tets_removed").get<std::int64_t>(), piece.at("tets").get<std::int64_t>());
  EXPECT_DOUBLE_EQ(r.at("debris_volume_removed").get<double>(), piece.at("volume").get<double>());
  EXPECT_EQ(r.at("pieces").at(0).at("removed"), true);
  // Debris is not tissue: the cut's tissue counts are the ones it had without.
  EXPECT_EQ(r.at("tets_removed").get<std::int64_t>(), record.at("tets_removed").get<std::int64_t>());
  EXPECT_EQ(report.at("summary").at("tets_removed").get<std::int64_t>(), ordered.at("summary").at("tets_removed").get<std::int64_t>());
  EXPECT_EQ(report.at("summary").at("debris_pieces_removed"), 1);
  EXPECT_NE(debris.out.find("pieces: 1 detached by 1 cuts, 1 removed as debris ("), std::string::npos) << debris.out;
  EXPECT_NE(read_text(path("debris.msh")), read_text(path("kept.msh")));
  // The same from a scenario: `tetcut run --debris-volume` and the scenario's own line.
  write("plate.scn", "mesh plate.msh\ndiameter 0.5\nsweep 1,-0.3,0 1,2.3,0 2.6 swept\nexpect components 1\n");
  ASSERT_EQ(tetcut({"run", path("plate.scn"), "--debris-volume", "0.5", "--out", path("run.msh")}).exit_code, 0);
  EXPECT_EQ(read_text(path("run.msh")), read_text(path("debris.msh")));
  write("line.scn", "mesh plate.msh\ndiameter 0.5\ndebris_volume 0.5\nsweep 1,-0.3,0 1,2.3,0 2.6 swept\n");
  ASSERT_EQ(tetcut({"run", path("line.scn"), "--out", path("line.msh")}).exit_code, 0);
  EXPECT_EQ(read_text(path("line.msh")), read_text(path("debris.msh")));
  EXPECT_TRUE(usage_error(tetcut({"cut", path("plate.msh"), "--diameter", "0.5", "--from", "1,-0.3,0", "--to", "1,2.3,0",
                                  "--step", "2.6", "--debris-volume", "-1"}),
                          "cut", "debris volume"));
}

// The graded rule reaches the engine from each place a user chooses it: `tetcut cut
// --refinement graded`, a scenario's `refinement graded` line and `tetcut run --refinement graded`
// give one mesh, which the paper's rule does not.
TEST_F(Cli, TheGradedRefinementIsTheSameRuleFromCutRunAndAScenarioLine) {
  write_box("box.msh", 3, 3, 3);
  const std::vector<std::string> sweep = {"--diameter", "0.08", "--from", "0.2,0.45,0.5", "--to", "0.8,0.45,0.5",
                                          "--step", "0.2"};
  auto cut = [&](const std::string& rule, const std::string& out) {
    std::vector<std::string> args = {"cut", path("box.msh")};
    args.insert(args.end(), sweep.begin(), sweep.end());
    for (const std::string& a : {std::string("--refinement"), rule, std::string("--out"), path(out)}) args.push_back(a);
    return tetcut(args);
  };
  ASSERT_EQ(cut("graded", "graded.msh").exit_code, 0);
  ASSERT_EQ(cut("paper", "paper.msh").exit_code, 0);
  write("line.scn", "mesh box.msh\ndiameter 0.08\nrefinement graded\nsweep 0.2,0.45,0.5 0.8,0.45,0.5 0.2\n");
  write("plain.scn", "mesh box.msh\ndiameter 0.08\nsweep 0.2,0.45,0.5 0.8,0.45,0.5 0.2\n");
  ASSERT_EQ(tetcut({"run", path("line.scn"), "--out", path("line.msh")}).exit_code, 0);
  ASSERT_EQ(tetcut({"run", path("plain.scn"), "--refinement", "graded", "--out", path("option.msh")}).exit_code, 0);
  EXPECT_EQ(read_text(path("line.msh")), read_text(path("graded.msh")));
  EXPECT_EQ(read_text(path("option.msh")), read_text(path("graded.msh")));
  EXPECT_NE(read_text(path("paper.msh")), read_text(path("graded.msh")));
  EXPECT_TRUE(usage_error(cut("coarse", "x.msh"), "cut", "--refinement"));
  write("bad.scn", "mesh box.msh\nrefinement coarse\n");
  const ProcessResult bad = tetcut({"run", path("bad.scn")});
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("refinement must be auto, paper or graded"), std::string::npos) << bad.err;
}

TEST_F(Cli, RemoveAtAPointRemovesTheTetTheScenarioRemoves) {
  write_box("box.msh", 3, 3, 3);
  // On a face and on a vertex shared by several tets: the one rule picks the same tet.
  const std::vector<std::string> points = {"0.5,0.5,0.5", "0.3333333333333333,0.5,0.5", "0,0,0", "0.1,0.1,0.95"};
  std::string scenario = "mesh box.msh\n";
  std::vector<std::string> args = {"remove", path("box.msh"), "-o", path("removed.msh"), "--at", points[0]};
  for (const std::string& p : points) scenario += "remove " + p + "\n";
  args.insert(args.end(), points.begin() + 1, points.end());
  const ProcessResult remove = tetcut(args);
  ASSERT_EQ(remove.exit_code, 0) << remove.err;
  write("remove.scn", scenario);
  const ProcessResult run = tetcut({"run", path("remove.scn"), "--out", path("run.msh")});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(read_text(path("removed.msh")), read_text(path("run.msh")));
  EXPECT_NE(remove.out.find("removed "), std::string::npos) << remove.out;
}

// ---- refine, cut, run ---------------------------------------------------------------------

TEST_F(Cli, RefineUniformGivesEightTimesTheTetsAndAReport) {
  const std::string box = write_box("box.msh", 2, 2, 2);
  const ProcessResult r = tetcut({"refine", box, "--uniform", "-o", path("fine.msh"), "--report", path("r.json")});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto json = report_summary(path("r.json"));
  ASSERT_TRUE(json);
  const Json& summary = json->at("summary");
  for (const char* key : {"iterations", "edges_split", "tets_created", "min_radius_ratio", "hash"})
    EXPECT_TRUE(summary.contains(key)) << key;
  EXPECT_EQ(summary.at("tets").get<double>(), 8 * 48);
  EXPECT_EQ(tetcut({"check", path("fine.msh")}).exit_code, 0);
}

TEST_F(Cli, CutSweepReportsPercentilesAndLeavesAValidMesh) {
  const std::string box = write_box("box.msh", 6, 6, 6);
  const ProcessResult r = tetcut({"cut", box, "--diameter", "0.3", "--from", "0.1,0.5,0.5", "--to", "0.9,0.5,0.5", "--step",
                                  "0.1", "--out", path("cut.msh"), "--report", path("cut.json")});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto json = report_summary(path("cut.json"));
  ASSERT_TRUE(json);
  const Json& summary = json->at("summary");
  for (const char* key : {"cuts", "first_us", "p50_us", "p90_us", "p99_us", "max_us", "tets_removed", "tets_created",
                          "unresolved", "min_radius_ratio", "hash"})
    ASSERT_TRUE(summary.contains(key)) << key;
  // The first cut is reported on its own and counted in the percentiles (the max is over all).
  EXPECT_EQ(summary.at("first_us").get<double>(), json->at("cuts").at(0).at("time_us").get<double>());
  EXPECT_LE(summary.at("first_us").get<double>(), summary.at("max_us").get<double>());
  EXPECT_EQ(summary.at("cuts").get<double>(), 9);
  EXPECT_GT(summary.at("tets_removed").get<double>(), 0);
  EXPECT_EQ(summary.at("unresolved").get<double>(), 0);
  EXPECT_LE(summary.at("p50_us").get<double>(), summary.at("p99_us").get<double>());
  ASSERT_TRUE(json->contains("cuts"));
  EXPECT_EQ(json->at("cuts").size(), 9u);
  EXPECT_EQ(tetcut({"check", path("cut.msh"), "--level", "exact"}).exit_code, 0);
}

TEST_F(Cli, CutRefusesBadParametersWithAMessage) {
  const std::string box = write_box("box.msh", 2, 2, 2);
  for (const std::vector<std::string>& bad :
       {std::vector<std::string>{"--diameter", "-1", "--from", "0,0,0", "--to", "1,1,1", "--step", "0.1"},
        std::vector<std::string>{"--diameter", "nan", "--from", "0,0,0", "--to", "1,1,1", "--step", "0.1"},
        std::vector<std::string>{"--diameter", "0.2", "--from", "0,0,0", "--to", "1,1,1", "--step", "0"},
        std::vector<std::string>{"--diameter", "0.2", "--from", "0,0", "--to", "1,1,1", "--step", "0.1"},
        std::vector<std::string>{"--diameter", "0.2", "--from", "0,0,0", "--to", "1,1,1", "--step", "0.1", "--strategy", "x"}}) {
    std::vector<std::string> args = {"cut", box};
    args.insert(args.end(), bad.begin(), bad.end());
    const ProcessResult r = tetcut(args);
    EXPECT_TRUE(r.exited);
    EXPECT_EQ(r.exit_code, 2) << r.out;
    EXPECT_NE(r.err.find("tetcut cut:"), std::string::npos) << r.err;
  }
}

TEST_F(Cli, RunNamesTheLineOfAFailedExpectation) {
  write_box("box.msh", 3, 3, 3);
  const std::string scenario = write("s.scn",
                                     "mesh box.msh\n"
                                     "diameter 0.3\n"
                                     "cut 0.5,0.5,0.5\n"
                                     "expect tets 1\n");
  const ProcessResult r = tetcut({"run", scenario});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("s.scn:4: expected 1 tets"), std::string::npos) << r.err;
  const std::string broken = write("b.scn", "mesh box.msh\ncut 1,2\n");
  const ProcessResult p = tetcut({"run", broken});
  EXPECT_EQ(p.exit_code, 2);
  EXPECT_NE(p.err.find("b.scn:2:"), std::string::npos) << p.err;
}

// ---- labels through cut --frames and refine ------------------------------------------------

// A 4x4x4 unit box labelled 3 left of x = 0.5 and 7 right of it: no cube straddles the plane and
// a child lies inside its parent, so every tet a cut or a refinement leaves must carry the label
// of the side its centroid is on.
std::uint32_t side_label(const RawMesh& m, std::size_t t) {
  double x = 0;
  for (std::uint32_t v : m.tets[t]) x += m.positions[v].x;
  return x / 4 < 0.5 ? 3 : 7;
}

RawMesh two_region_box() {
  RawMesh m = make_box_mesh(4, 4, 4);
  for (std::size_t t = 0; t < m.tets.size(); ++t) m.labels.push_back(side_label(m, t));
  return m;
}

::testing::AssertionResult labels_follow_the_sides(const std::string& file) {
  const ReadResult r = read_mesh(file);
  if (!r.mesh) return ::testing::AssertionFailure() << file << ": " << r.error->message();
  const RawMesh& m = *r.mesh;
  if (m.labels.size() != m.tets.size())
    return ::testing::AssertionFailure() << file << ": " << m.labels.size() << " labels for " << m.tets.size() << " tets";
  std::size_t wrong = 0, left = 0;
  for (std::size_t t = 0; t < m.tets.size(); ++t) {
    wrong += m.labels[t] != side_label(m, t);
    left += m.labels[t] == 3;
  }
  if (wrong != 0) return ::testing::AssertionFailure() << file << ": " << wrong << " tets with the other side's label";
  if (left == 0 || left == m.tets.size()) return ::testing::AssertionFailure() << file << ": one side only";
  return ::testing::AssertionSuccess();
}

TEST_F(Cli, CutFramesCarryTheLabelsAfterEveryCut) {
  ASSERT_TRUE(write_mesh(path("box.mesh"), two_region_box()).ok);
  fs::create_directories(path("frames"));
  // Five cuts across the plane x = 0.5: children on both sides.
  const ProcessResult r = tetcut({"cut", path("box.mesh"), "--diameter", "0.3", "--from", "0.1,0.5,0.5", "--to",
                                  "0.9,0.5,0.5", "--step", "0.2", "--frames", path("frames"), "--out", path("out.vtu")});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (int k = 0; k < 5; ++k) {
    const std::string frame = path("frames/frame_0000" + std::to_string(k) + ".vtu");
    EXPECT_TRUE(labels_follow_the_sides(frame));
  }
  EXPECT_FALSE(fs::exists(path("frames/frame_00005.vtu")));
  // The last frame is the final mesh, labels included.
  const ReadResult last = read_mesh(path("frames/frame_00004.vtu"));
  const ReadResult out = read_mesh(path("out.vtu"));
  ASSERT_TRUE(last.mesh && out.mesh);
  EXPECT_EQ(last.mesh->tets, out.mesh->tets);
  EXPECT_EQ(last.mesh->labels, out.mesh->labels);
  EXPECT_LT(out.mesh->tets.size(), two_region_box().tets.size());

  // An unlabelled mesh's frames have no labels.
  ASSERT_TRUE(write_mesh(path("plain.vtu"), make_box_mesh(4, 4, 4)).ok);
  const ProcessResult p = tetcut({"cut", path("plain.vtu"), "--diameter", "0.3", "--from", "0.5,0.5,0.5", "--to",
                                  "0.5,0.5,0.5", "--step", "1", "--frames", path("frames")});
  ASSERT_EQ(p.exit_code, 0) << p.err;
  const ReadResult plain = read_mesh(path("frames/frame_00000.vtu"));
  ASSERT_TRUE(plain.mesh.has_value());
  EXPECT_FALSE(plain.mesh->labelled());
}

TEST_F(Cli, RefineCarriesTheLabelsAndRefinesTheSameMesh) {
  ASSERT_TRUE(write_mesh(path("box.mesh"), two_region_box()).ok);
  ASSERT_TRUE(write_mesh(path("plain.vtu"), make_box_mesh(4, 4, 4)).ok);
  const std::vector<std::vector<std::string>> modes = {
      {"--uniform"}, {"--random-edges", "40", "--seed", "5"}, {"--ball", "0.5,0.5,0.5,0.1", "--dref", "0.2"}};
  for (const std::vector<std::string>& mode : modes) {
    SCOPED_TRACE(mode.front());
    std::vector<std::string> labelled = {"refine", path("box.mesh"), "-o", path("fine.vtu")};
    std::vector<std::string> plain = {"refine", path("plain.vtu"), "-o", path("plain_fine.vtu")};
    labelled.insert(labelled.end(), mode.begin(), mode.end());
    plain.insert(plain.end(), mode.begin(), mode.end());
    const ProcessResult r = tetcut(labelled);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(labels_follow_the_sides(path("fine.vtu")));
    // Tracking the labels (a transaction) refines the same mesh as without them.
    const ProcessResult p = tetcut(plain);
    ASSERT_EQ(p.exit_code, 0) << p.err;
    const std::size_t at = r.out.find("hash ");
    ASSERT_NE(at, std::string::npos) << r.out;
    EXPECT_EQ(r.out.substr(at), p.out.substr(p.out.find("hash "))) << r.out << p.out;
    EXPECT_GT(read_mesh(path("fine.vtu")).mesh->tets.size(), two_region_box().tets.size());
  }
}

}  // namespace
}  // namespace tetcut::test
