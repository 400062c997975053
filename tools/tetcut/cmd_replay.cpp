// `tetcut replay INPUT --target NAME [--scenario-out FILE]`: a fuzz input of a sequence target
// (fuzz/removal_sequence.hpp, fuzz/cut_sequence.hpp) decoded into a scenario, printed, and run
// through the target's own entry point with every check it makes; names the first failing
// operation and its scenario line. The scenario is then also run as `tetcut run` would, to say
// whether it reproduces the failure on its own (the input for `tetcut minimize`).
#include <filesystem>
#include <iterator>
#include <ostream>
#include <string>

#include "args.hpp"
#include "command.hpp"
#include "tetcut/io.hpp"
#include "tetcut/scenario/scenario.hpp"

#ifdef TETCUT_HAVE_FUZZ_DECODERS
#include "operations/sequence_target.hpp"
#endif

namespace tetcut::cli {
namespace {

namespace fs = std::filesystem;

constexpr OptionSpec kSpecs[] = {{"--target", true}, {"--scenario-out", true}};

// The scenario with its absolute mesh paths made relative to `dir`, where it will be written.
std::string relocate(const std::string& text, const fs::path& dir) {
  std::string out;
  std::size_t begin = 0;
  while (begin < text.size()) {
    std::size_t end = text.find('\n', begin);
    if (end == std::string::npos) end = text.size();
    std::string line = text.substr(begin, end - begin);
    if (line.rfind("mesh /", 0) == 0) {
      const fs::path mesh = fs::path(line.substr(5)).lexically_normal();
      const fs::path base = fs::absolute(dir).lexically_normal();
      const fs::path relative = mesh.lexically_relative(base);
      // Relative when both lie in one tree (a checkout), so that the pair can move together.
      const auto top = [](const fs::path& p) { return std::next(p.begin()) == p.end() ? fs::path() : *std::next(p.begin()); };
      if (!relative.empty() && top(mesh) == top(base)) line = "mesh " + relative.generic_string();
    }
    out += line + "\n";
    begin = end + 1;
  }
  return out;
}

}  // namespace

int cmd_replay(Args args, std::ostream& out, std::ostream& err) {
  const ArgParseResult parsed = parse_args(args, kSpecs);
  if (!parsed.ok()) return usage_error("replay", parsed.error, err);
  const ParsedArgs& a = parsed.args;
  if (a.positionals.size() != 1) return usage_error("replay", "expected exactly one INPUT", err);
  const auto target_name = a.value("--target");
  if (!target_name) return usage_error("replay", "--target NAME is required", err);
#ifndef TETCUT_HAVE_FUZZ_DECODERS
  err << "tetcut: replay: this build has no fuzz decoders (fuzzer/FuzzedDataProvider.h was not found)\n";
  return kExitBadInput;
#else
  const fuzz::SequenceTarget* target = fuzz::find_sequence_target(*target_name);
  if (target == nullptr) {
    std::string names;
    for (const fuzz::SequenceTarget& t : fuzz::sequence_targets()) names += std::string(names.empty() ? "" : ", ") + std::string(t.name);
    return usage_error("replay", "unknown target '" + *target_name + "' (replayable: " + names + ")", err);
  }
  const std::string& input_path = a.positionals[0];
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
        << target->versions << ")\n";
    return kExitBadInput;
  }
  out << result.scenario;

  if (const auto path = a.value("--scenario-out")) {
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
