#include "tetcut/harness/engine_check.hpp"

#include <algorithm>
#include <exception>
#include <utility>

#include <nlohmann/json.hpp>

#include "tetcut/predicates.hpp"

namespace tetcut::harness {

namespace inv = tetcut::invariants;
using Json = nlohmann::json;

namespace {

// The live tet holding `p` (on its boundary counts), by the exact orientation predicate; the
// lowest id when several do. A scan: the harness is not what is timed.
std::optional<std::uint32_t> tet_holding(const EngineMesh& mesh, const Vec3& p) {
  for (std::uint32_t t = 0; t < mesh.tets.size(); ++t) {
    const auto& v = mesh.tets[t];
    if (v[0] == kDeadTetMarker) continue;
    const Vec3& a = mesh.positions[v[0]];
    const Vec3& b = mesh.positions[v[1]];
    const Vec3& c = mesh.positions[v[2]];
    const Vec3& d = mesh.positions[v[3]];
    if (orientation(p, b, c, d) >= 0 && orientation(a, p, c, d) >= 0 && orientation(a, b, p, d) >= 0 &&
        orientation(a, b, c, p) >= 0) {
      return t;
    }
  }
  return std::nullopt;
}

void record_objection(PlanCheck& result, std::uint64_t index, const std::string& name, const inv::CheckReport& report) {
  result.failed_operation = index;
  result.failed_operation_name = name;
  for (const inv::Violation& v : report.violations) result.invariants.emplace_back(inv::id_string(v.id));
  result.objection = inv::to_string(report);
  while (!result.objection.empty() && result.objection.back() == '\n') result.objection.pop_back();
}

void pool_quality(PlanCheck& result, const inv::QualityStats& quality) {
  if (quality.tets == 0) return;
  result.min_radius_ratio = std::min(result.min_radius_ratio, quality.min_radius_ratio);
  result.min_dihedral_deg = std::min(result.min_dihedral_deg, quality.min_dihedral_deg);
  result.quality_tets += quality.tets;
}

// The full check of the mesh as it ends: what is left broken, and (without a change log, where
// no operation's created tets were measured) the quality of every tet.
void finish(PlanCheck& result, const EngineMesh& mesh, bool judge, bool whole_mesh_quality) {
  inv::CheckOptions options;
  options.level = inv::CheckLevel::kFull;
  options.operation = "the mesh at the end";
  const inv::CheckReport report = inv::check_raw(mesh.view(), options);
  if (const inv::Violation* v = report.find(inv::Invariant::kI5VertexShell)) result.singular_vertices = v->count;
  if (const inv::Violation* v = report.find(inv::Invariant::kI6EdgeShell)) result.singular_edges = v->count;
  if (const inv::Violation* v = report.find(inv::Invariant::kI4Orientation)) result.inverted_tets = v->count;
  result.tets_after = mesh.live_tets;
  result.volume_after = report.volume;
  if (whole_mesh_quality) pool_quality(result, report.quality);
  if (judge && !report.ok() && !result.failed_operation) record_objection(result, result.run, options.operation, report);
}

Json to_json(const PlanCheck& r) {
  Json j = {{"adapter", r.adapter}, {"plan", r.plan}, {"level", r.level}, {"operations", r.operations},
            {"run", r.run}, {"refused", r.refused}, {"missed", r.missed}, {"tets_before", r.tets_before},
            {"tets_after", r.tets_after}, {"volume_before", r.volume_before}, {"volume_after", r.volume_after},
            {"failed_operation_name", r.failed_operation_name}, {"invariants", r.invariants},
            {"objection", r.objection}, {"singular_vertices", r.singular_vertices},
            {"singular_edges", r.singular_edges}, {"inverted_tets", r.inverted_tets},
            {"min_radius_ratio", r.min_radius_ratio}, {"min_dihedral_deg", r.min_dihedral_deg},
            {"quality_tets", r.quality_tets}, {"angle_floor_lowered", r.angle_floor_lowered},
            {"lowest_angle_floor_deg", r.lowest_angle_floor_deg}, {"engine_error", r.engine_error}, {"signal", r.signal},
            {"notes", r.notes}};
  j["failed_operation"] = r.failed_operation ? Json(*r.failed_operation) : Json(nullptr);
  return j;
}

PlanCheck from_json(const Json& j) {
  PlanCheck r;
  r.adapter = j.at("adapter");
  r.plan = j.at("plan");
  r.level = j.at("level");
  r.operations = j.at("operations");
  r.run = j.at("run");
  r.refused = j.at("refused");
  r.missed = j.at("missed");
  r.tets_before = j.at("tets_before");
  r.tets_after = j.at("tets_after");
  r.volume_before = j.at("volume_before");
  r.volume_after = j.at("volume_after");
  if (!j.at("failed_operation").is_null()) r.failed_operation = j.at("failed_operation").get<std::uint64_t>();
  r.failed_operation_name = j.at("failed_operation_name");
  r.invariants = j.at("invariants").get<std::vector<std::string>>();
  r.objection = j.at("objection");
  r.singular_vertices = j.at("singular_vertices");
  r.singular_edges = j.at("singular_edges");
  r.inverted_tets = j.at("inverted_tets");
  r.min_radius_ratio = j.at("min_radius_ratio");
  r.min_dihedral_deg = j.at("min_dihedral_deg");
  r.quality_tets = j.at("quality_tets");
  r.angle_floor_lowered = j.at("angle_floor_lowered");
  r.lowest_angle_floor_deg = j.at("lowest_angle_floor_deg");
  r.engine_error = j.at("engine_error");
  r.signal = j.at("signal");
  r.notes = j.at("notes").get<std::vector<std::string>>();
  return r;
}

}  // namespace

AdapterInfo probe_adapter(const std::string& adapter_path) {
  const ChildOutcome outcome = run_in_child([&](const Announce& announce) {
    announce("loading " + adapter_path);
    const EngineLibrary library(adapter_path);
    const Json info = {{"name", library.name()},
                       {"version", library.version()},
                       {"abi_version", library.api().abi_version},
                       {"capabilities", library.api().capabilities}};
    return info.dump();
  });
  if (!outcome.completed) {
    // The child's own message is the EngineError's whole text already ("adapter ..., load: ...").
    if (outcome.signal == 0 && !outcome.error.empty()) throw std::runtime_error(outcome.error);
    throw EngineError("adapter (" + adapter_path + ")", "load", outcome.failure());
  }
  const Json info = Json::parse(outcome.payload);
  return {adapter_path, info.at("name"), info.at("version"), info.at("abi_version"), info.at("capabilities")};
}

PlanCheck check_plan_here(const EngineLibrary& library, const EnginePlan& plan, const Announce* announce) {
  PlanCheck result;
  result.adapter = library.name();
  result.plan = plan.name;
  result.operations = plan.operations.size();
  result.notes = plan.notes;
  const bool local = library.has(TETCUT_ENGINE_CHANGE_LOG);
  result.level = local ? "local" : "full";
  auto say = [&](const std::string& what) {
    if (announce != nullptr) (*announce)(what);
  };
  try {
    say("create on " + plan.name);
    EngineInstance engine(library, plan.mesh);
    const EngineMesh* mesh = &engine.read("create");
    {
      inv::CheckOptions options;
      options.operation = "create";
      const inv::CheckReport report = inv::check_raw(mesh->view(), options);
      result.tets_before = mesh->live_tets;
      result.volume_before = report.volume;
      if (!report.ok()) {
        record_objection(result, 0, "create", report);
        finish(result, *mesh, false, !local);
        return result;
      }
    }
    std::optional<inv::LocalChecker> checker;
    if (local) checker.emplace(mesh->view());
    if (!library.has(TETCUT_ENGINE_QUALITY_FLOOR)) {
      result.notes.emplace_back("quality reported, not judged: the adapter does not promise the no-degradation rule");
    }
    for (std::size_t i = 0; i < plan.operations.size(); ++i) {
      const EngineOperation& op = plan.operations[i];
      const std::size_t tets_before = mesh->tets.size();
      EngineStatus status = EngineStatus::kOk;
      say(op.name);
      if (op.kind == EngineOperation::Kind::kRemoveAt) {
        const std::optional<std::uint32_t> tet = tet_holding(*mesh, op.a);
        if (!tet) {
          ++result.missed;
          continue;
        }
        status = engine.remove_tet(*tet, op.name);
      } else {
        status = engine.cut(op.a, op.b, op.diameter, op.name);
      }
      ++result.run;
      if (status == EngineStatus::kRefused) ++result.refused;
      mesh = &engine.read(op.name);
      inv::CheckOptions options;
      options.operation = op.name;
      inv::CheckReport report;
      if (local) {
        const EngineChanges changes = engine.changes(tets_before, op.name);
        options.level = inv::CheckLevel::kLocal;
        options.moved = changes.moved;
        options.quality_rule = library.has(TETCUT_ENGINE_QUALITY_FLOOR) ? inv::QualityRule::kNoDegradation
                                                                         : inv::QualityRule::kReportOnly;
        if (library.has(TETCUT_ENGINE_TISSUE_RULE) && op.kind == EngineOperation::Kind::kCut) {
          options.tool = inv::ToolRule{.centre = op.a, .radius = op.diameter / 2, .d_ref = changes.d_ref,
                                       .left = changes.left_in_tool, .end = op.b};
        }
        if (changes.angle_floor_deg && options.quality_rule == inv::QualityRule::kNoDegradation) {
          ++result.angle_floor_lowered;
          result.lowest_angle_floor_deg = std::min(result.lowest_angle_floor_deg, *changes.angle_floor_deg);
          options.min_dihedral_deg = std::min(options.min_dihedral_deg, *changes.angle_floor_deg);
        }
        report = checker->after_operation(mesh->view(), changes.removed, changes.created, options);
        pool_quality(result, report.quality);
      } else {
        options.level = inv::CheckLevel::kFull;
        report = inv::check_raw(mesh->view(), options);
      }
      if (!report.ok()) {
        record_objection(result, i + 1, op.name, report);
        break;
      }
    }
    say("the full check at the end of " + plan.name);
    finish(result, *mesh, true, !local);
  } catch (const EngineError& e) {
    result.engine_error = e.what();
  }
  return result;
}

PlanCheck check_plan(const AdapterInfo& adapter, const EnginePlan& plan, const EngineCheckOptions& options) {
  const std::string& adapter_path = adapter.path;
  const ChildOutcome outcome = run_in_child(
      [&](const Announce& announce) {
        announce("loading " + adapter_path);
        const EngineLibrary library(adapter_path);
        return to_json(check_plan_here(library, plan, &announce)).dump();
      },
      options.timeout_seconds);
  if (outcome.completed) return from_json(Json::parse(outcome.payload));
  PlanCheck result;
  result.adapter = adapter.name;
  result.plan = plan.name;
  result.operations = plan.operations.size();
  result.signal = outcome.signal;
  // An exception's text names the adapter already (EngineError); a death does not.
  result.engine_error = outcome.signal == 0 && !outcome.error.empty()
                            ? outcome.error
                            : "adapter '" + adapter.name + "' (" + adapter.path + "): " + outcome.failure();
  result.notes = plan.notes;
  return result;
}

}  // namespace tetcut::harness
