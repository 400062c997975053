// `tetcut replay INPUT --target NAME [--scenario-out FILE]`: a fuzz input of a sequence target
// (fuzz/operations/removal_sequence_decoder.hpp, cut_sequence_decoder.hpp) decoded into a
// scenario, printed, and run through the target's own entry point with every check it makes;
// names the first failing operation and its scenario line. The scenario is then also run as
// `tetcut run` would, to say whether it reproduces the failure on its own (the input for
// `tetcut minimize`).
#include <filesystem>
#include <iterator>
#include <ostream>
#include <string>

#include "command.hpp"
#include "command_parser.hpp"
#include "tetcut/io.hpp"
#include "tetcut/scenario/scenario.hpp"

#ifdef TETCUT_HAVE_FUZZ_DECODERS
#include "operations/sequence_target.hpp"
#endif

namespace tetcut::cli {
namespace {

namespace fs = std::filesystem;

// The scenario with its absolute mesh paths made relative to `dir`, where it will be written.
std::string relocate(const std::string& text, const fs::path& dir) {
  std::string out;
  std::size_t begin = 0;
  while (begin < text.size()) {
    std::size_t end = text.find('\n', begin);
    if (end == std::string::npos) end = text.size();
    std::string line = text.substr(begin, end - begin);
    if (line.rfind("mesh /", 0) == 0) line = "mesh " + scenario::mesh_path_from(line.substr(5), dir.string());
    out += line + "\n";
    begin = end + 1;
  }
  return out;
}

}  // namespace

int cmd_replay(Args args, std::ostream& out, std::ostream& err) {
  std::optional<std::string> input, target_name, scenario_out;
  CommandParser parser(
      "replay", "tetcut replay INPUT --target NAME [--scenario-out FILE]",
      "Decodes an input of a sequence fuzz target (removal_sequence, cut_sequence) into a scenario,\n"
      "prints it, and runs it through the target's own entry point with every check the target\n"
      "makes (local check after every operation, full checks, every request resolved under the\n"
      "combined strategy, rolled back cuts leaving the mesh as it was). Names the first failing\n"
      "operation and its scenario line, then says whether the scenario alone reproduces it under\n"
      "`tetcut run` (the input of `tetcut minimize`).\n",
      "exit: 0 the input passes, 1 an operation fails, 2 unreadable input, not the target's\n"
      "input version, or bad usage");
  CLI::App& app = parser.app();
  opt::text(app, "INPUT", input, "the fuzz input", "")->required();
  opt::text(app, "--target", target_name, "removal_sequence or cut_sequence", "NAME")->required();
  opt::text(app, "--scenario-out", scenario_out, "also write the scenario (mesh paths relative to FILE's folder)",
            "FILE");
  if (const auto code = parser.parse(args, out, err)) return *code;
#ifndef TETCUT_HAVE_FUZZ_DECODERS
  err << "tetcut: replay: this build has no fuzz decoders (fuzzer/FuzzedDataProvider.h was not found)\n";
  return kExitBadInput;
#else
  const fuzz::SequenceTarget* target = fuzz::find_sequence_target(*target_name);
  if (target == nullptr) {
    std::string names;
    for (const fuzz::SequenceTarget& t : fuzz::sequence_targets()) names += std::string(names.empty() ? "" : ", ") + std::string(t.name);
    return parser.usage_error("--target: unknown target '" + *target_name + "' (replayable: " + names + ")", err);
  }
  const std::string& input_path = *input;
  std::string bytes;
  if (const auto error = read_file(input_path, bytes)) {
    err << "tetcut: " << error->message() << "\n";
    return kExitBadInput;
  }
  const auto* data = reinterpret_cast<const std::uint8_t*>(bytes.data());
  fuzz::SequenceOptions options;
  options.record_scenario = true;
  options.capture_failures = true;
  const fuzz::SequenceResult result = target->run(data, bytes.size(), options);
  if (result.finding && result.finding->property == "bundled-mesh") {
    err << "tetcut: " << result.finding->detail << "\n";
    return kExitBadInput;
  }
  if (!result.accepted) {
    err << "tetcut: " << input_path << ":1: not a " << target->name << " input (the first byte must be the input version "
        << int{fuzz::kSequenceVersionBundled} << " to " << int{fuzz::kSequenceVersion} << ")\n";
    return kExitBadInput;
  }
  out << result.scenario;

  if (const auto& path = scenario_out) {
    const fs::path dir = fs::path(*path).parent_path().empty() ? fs::path(".") : fs::path(*path).parent_path();
    const WriteResult w = write_file_atomically(*path, relocate(result.scenario, dir));
    if (!w.ok) {
      err << "tetcut: " << w.error << "\n";
      return kExitBadInput;
    }
  }

  // The same text through the scenario runner: does it reproduce on its own?
  const scenario::ParseResult scenario = scenario::parse(result.scenario, input_path + " (as a scenario)", ".");
  std::string as_scenario;
  if (!scenario.scenario) {
    as_scenario = "does not parse: " + scenario.error;
  } else {
    const scenario::RunResult r = scenario::run(*scenario.scenario);
    as_scenario = r.ok ? "passes under tetcut run" : "fails under tetcut run at line " + std::to_string(r.failed_line) + ": " + r.error;
  }

  if (result.finding) {
    const fuzz::Finding& f = *result.finding;
    out << "# replay: FAILS at operation " << f.operation_index << " (" << f.operation << "), scenario line "
        << result.finding_line << ": " << f.property << " violated: " << f.detail << "\n";
    out << "# scenario: " << as_scenario << "\n";
    err << "tetcut: " << input_path << ": operation " << f.operation_index << " (" << f.operation << "), scenario line "
        << result.finding_line << ": " << f.property << " violated\n";
    return kExitViolated;
  }
  out << "# replay: passes (" << target->name << ", every check)\n";
  out << "# scenario: " << as_scenario << "\n";
  return kExitOk;
#endif
}

}  // namespace tetcut::cli
