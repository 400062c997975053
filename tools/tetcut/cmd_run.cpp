// `tetcut run SCENARIO [--refinement auto|paper|graded] [--debris-volume V] [--check every|end|none]
// [--out M] [--report R.json]`: runs a scenario file (tools/scenario) and says which line failed, if any.
#include <ostream>

#include "command.hpp"
#include "command_parser.hpp"
#include "run_report.hpp"
#include "tetcut/scenario/scenario.hpp"

namespace tetcut::cli {

int cmd_run(Args args, std::ostream& out, std::ostream& err) {
  std::optional<std::string> path;
  std::optional<scenario::CheckMode> check;
  std::optional<RefinementRule> refinement;
  std::optional<double> debris_volume;
  RunOutputs outputs;
  CommandParser parser(
      "run",
      "tetcut run SCENARIO [--refinement auto|paper|graded] [--debris-volume V] [--check every|end|none] [--out M] "
      "[--report R.json]",
      "Runs a scenario file: one operation a line (mesh, diameter, strategy, cut, sweep, remove,\n"
      "compact, undo, check, expect hash|tets|unresolved|components), tets and tools addressed by points\n"
      "so that scenarios survive changes of internal ids. See corpus/scenarios/ and\n"
      "tools/scenario/include/tetcut/scenario/scenario.hpp.\n",
      "exit: 0 passed, 1 a check or expectation failed (its line is named), 2 unusable input");
  CLI::App& app = parser.app();
  opt::text(app, "SCENARIO", path, "the scenario file", "")->required();
  opt::refinement(app, refinement,
                  "the refinement rule the scenario starts with (default paper); its own `refinement` line wins");
  opt::debris_volume(app, debris_volume)->description(
      "the debris volume the scenario starts with (mesh units cubed; default 0: detached pieces are only reported); "
      "its own `debris_volume` line wins");
  opt::check_mode(app, check, "the local check after every operation (default), the full one at the end, or none");
  opt::text(app, "--out", outputs.mesh_path, "the final mesh (where the run stopped, if a check failed)", "M");
  opt::text(app, "--report", outputs.report_path, "the cuts and their summary as JSON (see tetcut cut)", "R.json");
  if (const auto code = parser.parse(args, out, err)) return *code;

  const scenario::ParseResult parsed = scenario::parse_file(*path);
  if (!parsed.scenario) {
    err << "tetcut: " << parsed.error << "\n";
    return kExitBadInput;
  }
  scenario::RunOptions options;
  options.check = check.value_or(scenario::CheckMode::kEvery);
  if (refinement || debris_volume) {
    options.initial_params.emplace();
    if (refinement) options.initial_params->refinement = *refinement;
    if (debris_volume) options.initial_params->debris_volume = *debris_volume;
    if (const auto bad = validate(*options.initial_params)) return parser.usage_error(*bad, err);
  }
  TetMesh mesh;
  const scenario::RunResult r = scenario::run(*parsed.scenario, options, &mesh);
  if (!r.ok) err << "tetcut: " << r.error << "\n";
  return report_run(r, mesh, outputs, out, err);
}

}  // namespace tetcut::cli
