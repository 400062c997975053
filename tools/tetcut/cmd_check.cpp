// `tetcut check MESH [--level local|full|exact] [--min-radius-ratio R] [--json]`: the
// independent checker on a file, naming every violated invariant (design: invariants I1-I9).
//
// The raw arrays are checked first (check_raw), so that a non-manifold or inverted file is
// diagnosed rather than refused. When the engine can also build its TetMesh from the file, the
// built mesh is checked too (check_mesh: adjacency I2 and bookkeeping I8), which tests the engine's
// builder against the checker on every file a user brings.
#include <cstdint>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "args.hpp"
#include "command.hpp"
#include "json_writer.hpp"
#include "mesh_input.hpp"
#include "tetcut/invariants/check.hpp"
#include "tetcut/mesh_builder.hpp"

namespace tetcut::cli {

namespace {

namespace inv = tetcut::invariants;

const char* level_name(inv::CheckLevel level) {
  switch (level) {
    case inv::CheckLevel::kLocal: return "local";
    case inv::CheckLevel::kFull: return "full";
    case inv::CheckLevel::kExact: return "exact";
  }
  return "?";
}

std::optional<inv::CheckLevel> parse_level(std::string_view s) {
  if (s == "local") return inv::CheckLevel::kLocal;
  if (s == "full") return inv::CheckLevel::kFull;
  if (s == "exact") return inv::CheckLevel::kExact;
  return std::nullopt;
}

struct CheckOutcome {
  inv::CheckLevel level_requested = inv::CheckLevel::kFull;
  inv::CheckLevel level_run = inv::CheckLevel::kFull;
  inv::CheckReport report;
  std::uint64_t vertices = 0;
  std::uint64_t tets = 0;
  double volume = 0.0;
  bool engine_built = false;
  std::uint64_t engine_problems = 0;
  std::string engine_first_problem;
  std::vector<std::string> notes;

  // The engine refusing a file the checker finds valid is a disagreement between the two, and
  // a mesh no tetcut operation can load: not valid either.
  [[nodiscard]] bool valid() const { return report.ok() && engine_built; }
};

// Adds the violations of `extra` whose invariant `into` does not name yet, keeping id order.
void merge_violations(inv::CheckReport& into, const inv::CheckReport& extra) {
  for (const inv::Violation& v : extra.violations) {
    if (into.find(v.id) != nullptr) continue;
    auto pos = into.violations.begin();
    while (pos != into.violations.end() && pos->id < v.id) ++pos;
    into.violations.insert(pos, v);
  }
}

CheckOutcome run_check(const RawMesh& raw, inv::CheckLevel level, double radius_ratio_floor) {
  CheckOutcome outcome;
  outcome.level_requested = level;
  outcome.vertices = raw.positions.size();
  outcome.tets = raw.tets.size();

  BuildResult built = build_mesh(raw);
  outcome.engine_built = built.ok();
  outcome.engine_problems = built.problems.size();
  if (!built.problems.empty()) outcome.engine_first_problem = built.problems.front().message;

  inv::CheckOptions options;
  options.radius_ratio_floor = radius_ratio_floor;

  if (level == inv::CheckLevel::kLocal) {
    if (built.ok()) {
      // A file has no "last operation": we pretend one operation replaced every tet by itself,
      // so that the code path the local checker runs after each cut sees the whole mesh.
      const TetMesh& mesh = *built.mesh;
      std::vector<TetId> all;
      all.reserve(mesh.num_tets());
      for (std::uint32_t t = 0; t < mesh.tet_capacity(); ++t) {
        if (mesh.is_live(TetId{t})) all.push_back(TetId{t});
      }
      inv::LocalChecker checker(mesh.raw_view());
      options.level = inv::CheckLevel::kLocal;
      outcome.report = checker.after_operation(mesh.raw_view(), all, all, options);
      // The local report's volume is that of the region it looked at; say the mesh's.
      outcome.volume = mesh.total_volume();
      outcome.level_run = inv::CheckLevel::kLocal;
      return outcome;
    }
    outcome.notes.push_back(
        "the engine cannot build this mesh, so the local checker cannot run on it: checked at "
        "level full on the raw arrays instead");
    level = inv::CheckLevel::kFull;
  }

  options.level = level;
  outcome.level_run = level;
  outcome.report = inv::check_raw(raw, options);
  outcome.volume = outcome.report.volume;
  if (built.ok()) {
    // The geometric tests of the exact level do not depend on the engine's structure: run them
    // once, on the raw arrays, and compare the built mesh at the full level.
    options.level = inv::CheckLevel::kFull;
    merge_violations(outcome.report, inv::check_mesh(built.mesh->raw_view(), options));
  }
  return outcome;
}

void write_list(std::ostream& out, const std::vector<std::uint32_t>& ids) {
  for (const std::uint32_t id : ids) out << ' ' << id;
}

void write_text(const std::string& path, const CheckOutcome& o, std::ostream& out) {
  for (const std::string& note : o.notes) out << "note: " << note << '\n';
  const std::size_t n = o.report.violations.size();
  out << path << ": ";
  if (o.valid()) {
    out << "valid";
  } else if (n > 0) {
    out << n << (n == 1 ? " invariant" : " invariants") << " violated";
  } else {
    out << "refused by the engine";
  }
  out << " at level " << level_name(o.level_run) << " (" << o.tets << " tets, " << o.vertices
      << " vertices)\n";
  for (const inv::Violation& v : o.report.violations) {
    out << inv::id_string(v.id) << " (" << inv::description(v.id) << "): count " << v.count
        << '\n';
    if (!v.tets.empty()) {
      out << "  first tets:";
      write_list(out, v.tets);
      out << '\n';
    }
    if (!v.vertices.empty()) {
      out << "  first vertices:";
      write_list(out, v.vertices);
      out << '\n';
    }
    if (!v.detail.empty()) out << "  detail: " << v.detail << '\n';
  }
  if (!o.engine_built) {
    out << "engine: refused the mesh: " << o.engine_problems
        << (o.engine_problems == 1 ? " problem" : " problems");
    if (!o.engine_first_problem.empty()) out << ", first: " << o.engine_first_problem;
    out << '\n';
  }
}

void write_json(const std::string& path, const CheckOutcome& o, std::ostream& out) {
  JsonWriter json(out);
  json.begin_object();
  json.field("file", path);
  json.field("level", level_name(o.level_requested));
  json.field("level_run", level_name(o.level_run));
  json.field("valid", o.valid());
  json.field("vertices", o.vertices);
  json.field("tets", o.tets);
  json.field("tets_checked", o.report.tets_checked);
  json.field("volume", o.volume);
  json.key("violations");
  json.begin_array();
  for (const inv::Violation& v : o.report.violations) {
    json.begin_object();
    json.field("id", inv::id_string(v.id));
    json.field("description", inv::description(v.id));
    json.field("count", v.count);
    json.key("tets");
    json.begin_array();
    for (const std::uint32_t t : v.tets) json.value(t);
    json.end_array();
    json.key("vertices");
    json.begin_array();
    for (const std::uint32_t x : v.vertices) json.value(x);
    json.end_array();
    json.field("detail", v.detail);
    json.end_object();
  }
  json.end_array();
  json.key("engine");
  json.begin_object();
  json.field("built", o.engine_built);
  json.field("problems", o.engine_problems);
  json.key("first_problem");
  if (o.engine_first_problem.empty()) {
    json.null();
  } else {
    json.value(o.engine_first_problem);
  }
  json.end_object();
  json.key("quality");
  json.begin_object();
  json.field("min_radius_ratio", o.report.quality.min_radius_ratio);
  json.field("mean_radius_ratio", o.report.quality.mean_radius_ratio);
  json.field("min_dihedral_deg", o.report.quality.min_dihedral_deg);
  json.end_object();
  json.key("notes");
  json.begin_array();
  for (const std::string& note : o.notes) json.value(note);
  json.end_array();
  json.end_object();
  json.finish();
}

}  // namespace

int cmd_check(Args args, std::ostream& out, std::ostream& err) {
  static constexpr OptionSpec kOptions[] = {
      {"--level", true}, {"--json", false}, {"--min-radius-ratio", true}};
  const ArgParseResult parsed = parse_args(args, kOptions);
  if (!parsed.ok()) return usage_error("check", parsed.error, err);
  if (parsed.args.positionals.size() != 1) {
    return usage_error(
        "check", parsed.args.positionals.empty() ? "missing MESH" : "too many arguments", err);
  }
  inv::CheckLevel level = inv::CheckLevel::kFull;
  if (const auto text = parsed.args.value("--level")) {
    const auto parsed_level = parse_level(*text);
    if (!parsed_level) {
      return usage_error("check", "--level must be local, full or exact, not '" + *text + "'",
                         err);
    }
    level = *parsed_level;
  }
  double floor = 0.0;
  if (const auto text = parsed.args.value("--min-radius-ratio")) {
    const auto value = parse_double(*text);
    if (!value || *value < 0.0 || *value > 1.0) {
      return usage_error("check",
                         "--min-radius-ratio must be a number from 0 to 1, not '" + *text + "'",
                         err);
    }
    floor = *value;
  }

  const std::string& path = parsed.args.positionals[0];
  const std::optional<RawMesh> mesh = load_mesh(path, err);
  if (!mesh) return kExitBadInput;

  const CheckOutcome outcome = run_check(*mesh, level, floor);
  if (parsed.args.has("--json")) {
    write_json(path, outcome, out);
  } else {
    write_text(path, outcome, out);
  }
  return outcome.valid() ? kExitOk : kExitViolated;
}

}  // namespace tetcut::cli
