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

#include "command.hpp"
#include "command_parser.hpp"
#include "json_output.hpp"
#include "mesh_input.hpp"
#include "tetcut/invariants/check.hpp"
#include "tetcut/mesh_builder.hpp"

namespace tetcut::cli {

namespace {

namespace inv = tetcut::invariants;

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
  out << " at level " << scenario::to_string(o.level_run) << " (" << o.tets << " tets, " << o.vertices
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

Json violation_json(const inv::Violation& v) {
  return Json{{"id", inv::id_string(v.id)},
              {"description", inv::description(v.id)},
              {"count", v.count},
              {"tets", v.tets},
              {"vertices", v.vertices},
              {"detail", v.detail}};
}

Json outcome_json(const std::string& path, const CheckOutcome& o) {
  Json violations = Json::array();
  for (const inv::Violation& v : o.report.violations) violations.push_back(violation_json(v));
  const Json first_problem = o.engine_first_problem.empty() ? Json(nullptr) : Json(o.engine_first_problem);
  return Json{{"file", path},
              {"level", scenario::to_string(o.level_requested)},
              {"level_run", scenario::to_string(o.level_run)},
              {"valid", o.valid()},
              {"vertices", o.vertices},
              {"tets", o.tets},
              {"tets_checked", o.report.tets_checked},
              {"volume", o.volume},
              {"violations", std::move(violations)},
              {"engine", {{"built", o.engine_built}, {"problems", o.engine_problems}, {"first_problem", first_problem}}},
              {"quality",
               {{"min_radius_ratio", o.report.quality.min_radius_ratio},
                {"mean_radius_ratio", o.report.quality.mean_radius_ratio},
                {"min_dihedral_deg", o.report.quality.min_dihedral_deg}}},
              {"notes", o.notes}};
}

}  // namespace

int cmd_check(Args args, std::ostream& out, std::ostream& err) {
  std::optional<std::string> path;
  std::optional<inv::CheckLevel> level;
  std::optional<double> floor;
  bool json = false;
  CommandParser parser(
      "check", "tetcut check MESH [--level local|full|exact] [--min-radius-ratio R] [--json]",
      "Runs the independent invariant checker (I1-I9) on a mesh file and names every violated\n"
      "invariant with its count, its first offending tets and vertices, and a detail line.\n"
      "\n"
      "The file is checked from its raw arrays, so a non-manifold or inverted mesh is diagnosed\n"
      "rather than refused. If the engine can also build its mesh from the file, that mesh is\n"
      "checked too (adjacency I2 and bookkeeping I8), and a refusal by the engine is reported.\n"
      "\n"
      "Levels: full (default) every invariant, O(n); exact: full, plus the geometric tests\n"
      "(boundary self-intersection, exact); local: builds the engine mesh and runs the local\n"
      "checker as if one operation had just replaced every tet by itself, so that the code path\n"
      "run after each cut is exercised on the whole file (if the engine cannot build the mesh,\n"
      "falls back to the full check of the raw arrays, with a note).\n",
      "exit: 0 valid, 1 an invariant is violated, 2 unreadable input or bad usage");
  CLI::App& app = parser.app();
  opt::text(app, "MESH", path, "the mesh file", "")->required();
  opt::check_level(app, level, "how deep the check goes (default full; see above)");
  opt::number(app, "--min-radius-ratio", floor, "I7: a tet with radius ratio below R (0..1) is a violation", "R");
  opt::flag(app, "--json", json, "the report as JSON on stdout");
  if (const auto code = parser.parse(args, out, err)) return *code;
  if (floor && (*floor < 0.0 || *floor > 1.0))
    return parser.usage_error("--min-radius-ratio: must be from 0 to 1", err);

  const std::optional<RawMesh> mesh = load_mesh(*path, err);
  if (!mesh) return kExitBadInput;

  const CheckOutcome outcome = run_check(*mesh, level.value_or(inv::CheckLevel::kFull), floor.value_or(0.0));
  if (json) {
    out << json_text(outcome_json(*path, outcome));
  } else {
    write_text(*path, outcome, out);
  }
  return outcome.valid() ? kExitOk : kExitViolated;
}

}  // namespace tetcut::cli
