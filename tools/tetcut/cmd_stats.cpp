// `tetcut stats`: the paper's Tables 1 and 2 on our five meshes with its figures beside ours, the
// strategy comparison, and the JSON and HTML reports (tools/stats).
#include <ostream>

#include "args.hpp"
#include "command.hpp"
#include "stats_json.hpp"
#include "tetcut/io.hpp"
#include "tetcut/stats/html_report.hpp"
#include "tetcut/stats/paper_stats.hpp"
#include "tetcut/stats/report_pictures.hpp"
#include "tetcut/stats/text_report.hpp"

namespace tetcut::cli {
namespace {
constexpr OptionSpec kSpecs[] = {
    {"--corpus", true}, {"--mesh", true}, {"--check", true}, {"--json", true}, {"--html", true}, {"--pictures", true}};

// The command line as given, for the report's "reproduce with" line.
std::string command_line(Args args) {
  std::string s = "tetcut stats";
  for (const std::string& a : args) s += " " + a;
  return s;
}
}  // namespace

int cmd_stats(Args args, std::ostream& out, std::ostream& err) {
  const ArgParseResult parsed = parse_args(args, kSpecs);
  if (!parsed.ok()) return usage_error("stats", parsed.error, err);
  const ParsedArgs& a = parsed.args;
  if (!a.positionals.empty()) return usage_error("stats", "unexpected argument '" + a.positionals[0] + "'", err);

  stats::StatsOptions options;
  options.corpus_dir = a.value("--corpus").value_or("corpus");
  options.comparison_mesh = a.value("--mesh").value_or("liver-refined");
  bool known = false;
  for (const stats::PaperMesh& m : stats::paper_meshes()) known = known || options.comparison_mesh == m.name;
  if (!known)
    return usage_error("stats", "--mesh: one of cylinder, sheet, liver-coarse, liver-refined, liver-local", err);
  const std::string check = a.value("--check").value_or("every");
  if (check != "every" && check != "end") return usage_error("stats", "--check must be every or end", err);
  options.check_every_cut = check == "every";

  const stats::StatsResult result = stats::compute_stats(options);
  if (!result.report) {
    err << "tetcut: " << result.error << "\n";
    return kExitBadInput;
  }
  const stats::StatsReport& report = *result.report;
  out << stats::text_report(report);

  if (const auto path = a.value("--json")) {
    const WriteResult w = write_file_atomically(*path, stats_json(report));
    if (!w.ok) {
      err << "tetcut: " << w.error << "\n";
      return kExitBadInput;
    }
  }
  if (const auto path = a.value("--html")) {
    const WriteResult w = write_file_atomically(*path, stats::html_report(report, command_line(args)));
    if (!w.ok) {
      err << "tetcut: " << w.error << "\n";
      return kExitBadInput;
    }
  }

  if (const auto dir = a.value("--pictures"); dir && report.resection) {
    for (const stats::Picture& p : stats::resection_pictures(*report.resection)) {
      const WriteResult w = write_file_atomically(*dir + "/" + p.id + ".svg", p.svg + "\n");
      if (!w.ok) {
        err << "tetcut: " << w.error << "\n";
        return kExitBadInput;
      }
    }
  }

  // The combined strategy must remove every requested tet, and every scenario must pass its checks.
  int code = kExitOk;
  for (const stats::MeshStats& m : report.meshes) {
    if (!m.ok) {
      err << "tetcut: " << m.error << "\n";
      code = kExitViolated;
    } else if (m.removal.unresolved != 0) {
      err << "tetcut: " << m.mesh.scenario << ": the combined strategy left " << m.removal.unresolved
          << " tet(s) unresolved\n";
      code = kExitViolated;
    }
  }
  if (report.resection && !report.resection->run.result.ok) {
    err << "tetcut: " << report.resection->run.result.error << "\n";
    code = kExitViolated;
  }
  return code;
}

}  // namespace tetcut::cli
