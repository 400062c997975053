// `tetcut run SCENARIO [--check every|end|none] [--out M] [--report R.json]`: runs a scenario
// file (tools/scenario) and says which line failed, if any.
#include <ostream>

#include "args.hpp"
#include "command.hpp"
#include "cut_report_json.hpp"
#include "tetcut/io.hpp"
#include "tetcut/scenario/scenario.hpp"

namespace tetcut::cli {
namespace {
constexpr OptionSpec kSpecs[] = {{"--check", true}, {"--out", true}, {"--report", true}};
}  // namespace

int cmd_run(Args args, std::ostream& out, std::ostream& err) {
  const ArgParseResult parsed = parse_args(args, kSpecs);
  if (!parsed.ok() || parsed.args.positionals.size() != 1) {
    err << "tetcut run: " << (parsed.ok() ? "expected exactly one SCENARIO" : parsed.error) << "\n"
        << "usage: tetcut run SCENARIO [--check every|end|none] [--out M] [--report R.json]\n";
    return 2;
  }
  const ParsedArgs& a = parsed.args;
  scenario::RunOptions options;
  const std::string check = a.value("--check").value_or("every");
  if (check == "every") options.check = scenario::CheckMode::kEvery;
  else if (check == "end") options.check = scenario::CheckMode::kEnd;
  else if (check == "none") options.check = scenario::CheckMode::kNone;
  else {
    err << "tetcut run: --check must be every, end or none\n";
    return 2;
  }
  const scenario::ParseResult parsed_scenario = scenario::parse_file(a.positionals[0]);
  if (!parsed_scenario.scenario) {
    err << "tetcut: " << parsed_scenario.error << "\n";
    return 2;
  }
  TetMesh mesh;
  const scenario::RunResult r = scenario::run(*parsed_scenario.scenario, options, &mesh);
  out << r.cuts.size() << " cuts, " << r.removals << " tets removed, " << r.unresolved << " unresolved, " << r.tets
      << " tets left\n";
  if (!r.cuts.empty())
    out << "per cut (all cuts): p50 " << percentile_us(r.cuts, 0.5) << " us, p99 " << percentile_us(r.cuts, 0.99)
        << " us, max " << percentile_us(r.cuts, 1.0) << " us; first cut " << r.cuts.front().report.time.total_us << " us\n";
  if (!r.ok) {
    err << "tetcut: " << r.error << "\n";
    return r.exit_code;
  }
  out << "hash " << r.hash << "\n";
  if (const auto path = a.value("--out")) {
    const WriteResult w = write_mesh(*path, mesh);
    if (!w.ok) {
      err << "tetcut: " << w.error << "\n";
      return 2;
    }
  }
  if (const auto path = a.value("--report")) {
    const WriteResult w = write_file_atomically(*path, cut_report_json(r.cuts, r.hash, true));
    if (!w.ok) {
      err << "tetcut: " << w.error << "\n";
      return 2;
    }
  }
  return 0;
}

}  // namespace tetcut::cli
