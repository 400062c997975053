// `tetcut stats`: the paper's Tables 1 and 2 on our five meshes with its figures beside ours, the
// strategy comparison, and the JSON and HTML reports (tools/stats).
#include <filesystem>
#include <ostream>

#include "command.hpp"
#include "command_parser.hpp"
#include "stats_json.hpp"
#include "tetcut/io.hpp"
#include "tetcut/stats/html_report.hpp"
#include "tetcut/stats/paper_stats.hpp"
#include "tetcut/stats/report_pictures.hpp"
#include "tetcut/stats/text_report.hpp"

namespace tetcut::cli {
namespace {
// The command line as given, for the report's "reproduce with" line.
std::string command_line(Args args) {
  std::string s = "tetcut stats";
  for (const std::string& a : args) s += " " + a;
  return s;
}
}  // namespace

int cmd_stats(Args args, std::ostream& out, std::ostream& err) {
  std::optional<std::string> corpus, mesh, json, html, pictures;
  std::optional<scenario::CheckMode> check;
  bool no_improve = false, improve = false;
  std::uint32_t sweeps = 10;
  CommandParser parser(
      "stats",
      "tetcut stats [--corpus DIR] [--mesh NAME] [--check every|end] [--improve] [--sweeps N] [--json FILE] "
      "[--html FILE] [--pictures DIR]",
      "Redoes the paper's experiment (section 3.6): five meshes of its kinds (cylinder, sheet, coarse\n"
      "liver, finer liver, locally refined liver), each cut by the cautery scenario in\n"
      "CORPUS/scenarios/paper/ with the combined strategy, and prints Tables 1 and 2 with the paper's\n"
      "figures and the difference beside ours, and Table 2 again for our wider search (strategy wide)\n"
      "beside the paper's, and Tables 1 and 2 once more for each other reading of what the paper\n"
      "leaves open: the orders surface-first-by-id and revisit in place of ours (directly removable tets\n"
      "first), and 3.5 stopping at its first removable set. Each Table's scenario is run N times\n"
      "(--sweeps), its tool path shifted by a seeded offset each time (the first as written), and every\n"
      "cell is the pooled estimate with its 95 % interval and raw counts, each rate with Fisher's exact\n"
      "test against the paper's counts (docs/paper.md says how). Then compares the strategies (basic, neighbours, combined, wide; templates\n"
      "and bisection) on one of those scenarios, and runs the liver resection\n"
      "(CORPUS/scenarios/liver-resection.scn) for the report's plots and pictures.\n"
      "\n"
      "Only the times (p50_us, p99_us, cut_us) vary between runs; every other figure is\n"
      "deterministic.\n",
      "exit: 0 done, 1 a scenario failed a check or the combined or wide strategy left a tet unresolved,\n"
      "2 unusable corpus or bad usage");
  CLI::App& app = parser.app();
  opt::text(app, "--corpus", corpus,
            "the corpus folder (default: the corpus/ of the source tree tetcut was built from, " TETCUT_DEFAULT_CORPUS_DIR
            ", whatever the working folder)",
            "DIR");
  opt::text(app, "--mesh", mesh, "the strategy comparison's mesh (default liver-refined)", "NAME");
  opt::check_mode(app, check, "the local checker after every cut (default) or the full one at the end");
  opt::flag(app, "--improve", improve,
            "the Tables' runs and the strategy comparison with the improvement pass (default: without, as the "
            "paper's algorithm; a cut the pass cannot lift then stops its run)");
  opt::flag(app, "--no-improve", no_improve, "without the improvement pass (the default)")->excludes("--improve");
  opt::count_into(app, "--sweeps", sweeps, 1000,
                  "runs of each Table's scenario at seeded offsets (default 10; the first is the scenario as written)");
  opt::text(app, "--json", json,
            "everything as JSON: keys table1, table2 (one row per mesh, with paper and diff), table2_wide (our "
            "wider search's rows), strategies (one row per strategy), resection",
            "FILE");
  opt::text(app, "--html", html,
            "a self-contained HTML report: tables, latency plot, quality histograms, the liver before and after "
            "the resection as SVG",
            "FILE");
  opt::text(app, "--pictures", pictures,
            "the report's pictures as DIR/latency-plot.svg, quality-histogram.svg, liver-before.svg and "
            "liver-after.svg (DIR must exist)",
            "DIR");
  if (const auto code = parser.parse(args, out, err)) return *code;

  stats::StatsOptions options;
  // Found from any working folder: the build records where its source tree's corpus is. The
  // reports name it "corpus" as before, so that they read the same from wherever they were made.
  options.corpus_dir = corpus.value_or(TETCUT_DEFAULT_CORPUS_DIR);
  options.corpus_label = corpus.value_or("corpus");
  if (!corpus && !std::filesystem::is_directory(options.corpus_dir)) {
    err << "tetcut: no corpus at " << options.corpus_dir << " (the source tree this tetcut was built from): give "
        << "the bundled corpus folder with --corpus DIR\n";
    return kExitBadInput;
  }
  options.comparison_mesh = mesh.value_or("liver-refined");
  bool known = false;
  for (const stats::PaperMesh& m : stats::paper_meshes()) known = known || options.comparison_mesh == m.name;
  if (!known)
    return parser.usage_error("--mesh: one of cylinder, sheet, liver-coarse, liver-refined, liver-local", err);
  if (check == scenario::CheckMode::kNone) return parser.usage_error("--check: must be every or end", err);
  options.check_every_cut = check.value_or(scenario::CheckMode::kEvery) == scenario::CheckMode::kEvery;
  options.improve = improve && !no_improve;
  if (sweeps < 1) return parser.usage_error("--sweeps: at least 1", err);
  options.sweeps = static_cast<int>(sweeps);

  const stats::StatsResult result = stats::compute_stats(options);
  if (!result.report) {
    err << "tetcut: " << result.error << "\n";
    return kExitBadInput;
  }
  const stats::StatsReport& report = *result.report;
  out << stats::text_report(report);

  if (json && !write_json_file(*json, stats_json(report), err)) return kExitBadInput;
  if (const auto& path = html) {
    const WriteResult w = write_file_atomically(*path, stats::html_report(report, command_line(args)));
    if (!w.ok) {
      err << "tetcut: " << w.error << "\n";
      return kExitBadInput;
    }
  }

  if (const auto& dir = pictures; dir && report.resection) {
    for (const stats::Picture& p : stats::resection_pictures(*report.resection)) {
      const WriteResult w = write_file_atomically(*dir + "/" + p.id + ".svg", p.svg + "\n");
      if (!w.ok) {
        err << "tetcut: " << w.error << "\n";
        return kExitBadInput;
      }
    }
  }

  // The combined and wide strategies must remove every requested tet, and every scenario must
  // pass its checks.
  int code = kExitOk;
  auto must_complete = [&](const std::vector<stats::MeshStats>& runs, const char* strategy) {
    for (const stats::MeshStats& m : runs) {
      if (!m.ok) {
        err << "tetcut: " << m.error << "\n";
        code = kExitViolated;
      } else if (m.removal.unresolved != 0) {
        err << "tetcut: " << m.mesh.scenario << ": the " << strategy << " strategy left " << m.removal.unresolved
            << " tet(s) unresolved\n";
        code = kExitViolated;
      }
    }
  };
  must_complete(report.meshes, "combined");
  must_complete(report.wide_meshes, "wide");
  must_complete(report.paper_order_meshes, "combined (surface-first-by-id order)");
  must_complete(report.revisit_meshes, "combined (revisit order)");
  must_complete(report.first_set_meshes, "combined (3.5's first set)");
  if (report.resection && !report.resection->run.result.ok) {
    err << "tetcut: " << report.resection->run.result.error << "\n";
    code = kExitViolated;
  }
  return code;
}

}  // namespace tetcut::cli
