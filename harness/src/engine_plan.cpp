#include "tetcut/harness/engine_plan.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <utility>

#include "core/random.hpp"
#include "tetcut/io.hpp"
#include "tetcut/scenario/scenario.hpp"
#include "tetcut/scenario/sweep.hpp"
#include "tetcut/scenario/values.hpp"

namespace tetcut::harness {

namespace {

using scenario::OpKind;

std::string where(const scenario::Scenario& s, const scenario::Op& op) {
  return s.name + ":" + std::to_string(op.line);
}

RawMesh read_plan_mesh(const std::string& path, const std::string& where_from) {
  ReadResult read = read_mesh(path);
  if (!read.mesh) {
    const ParseError& e = *read.error;
    std::string message = where_from;
    message.append(": ").append(e.file);
    if (e.line > 0) message.append(":").append(std::to_string(e.line));
    message.append(": ").append(e.reason);
    throw std::runtime_error(message);
  }
  return std::move(*read.mesh);
}

std::string mesh_path(const scenario::Scenario& s, const std::string& path) {
  if (!path.empty() && path.front() == '/') return path;
  return s.base_dir.empty() ? path : s.base_dir + "/" + path;
}

}  // namespace

double median_edge_length(const RawMesh& mesh) {
  std::vector<double> lengths;
  lengths.reserve(6 * mesh.tets.size());
  for (const auto& t : mesh.tets) {
    for (int i = 0; i < 4; ++i) {
      for (int j = i + 1; j < 4; ++j) lengths.push_back(norm(mesh.positions[t[i]] - mesh.positions[t[j]]));
    }
  }
  if (lengths.empty()) return 1.0;
  auto middle = lengths.begin() + static_cast<std::ptrdiff_t>(lengths.size() / 2);
  std::nth_element(lengths.begin(), middle, lengths.end());
  return *middle;
}

MeshBox bounding_box(const RawMesh& mesh) {
  MeshBox box;
  if (mesh.positions.empty()) return box;
  box.low = box.high = mesh.positions.front();
  for (const Vec3& p : mesh.positions) {
    box.low = {std::min(box.low.x, p.x), std::min(box.low.y, p.y), std::min(box.low.z, p.z)};
    box.high = {std::max(box.high.x, p.x), std::max(box.high.y, p.y), std::max(box.high.z, p.z)};
  }
  return box;
}

std::string point_text(const Vec3& p) {
  char text[96];
  std::snprintf(text, sizeof text, "(%.6g, %.6g, %.6g)", p.x, p.y, p.z);
  return text;
}

EnginePlan plan_from_scenario(const std::string& path) {
  scenario::ParseResult parsed = scenario::parse_file(path);
  if (!parsed.scenario) throw std::runtime_error(parsed.error);
  const scenario::Scenario& s = *parsed.scenario;
  EnginePlan plan;
  plan.name = s.name;
  bool have_mesh = false;
  double diameter = 1.0;  // CutParams' default, which a scenario without a diameter line cuts with
  auto add_cut = [&](const scenario::Op& op, const Vec3& a, const std::optional<Vec3>& b) {
    EngineOperation cut{EngineOperation::Kind::kCut, a, b, diameter, ""};
    cut.name = where(s, op) + ": cut " + std::to_string(plan.operations.size() + 1) + " at " + point_text(a);
    if (b) cut.name += " to " + point_text(*b);
    plan.operations.push_back(std::move(cut));
  };
  for (const scenario::Op& op : s.ops) {
    if (op.kind != OpKind::kMesh && op.kind != OpKind::kParam && !have_mesh) {
      throw std::runtime_error(where(s, op) + ": an operation before the scenario's mesh line");
    }
    switch (op.kind) {
      case OpKind::kMesh:
        if (have_mesh) throw std::runtime_error(where(s, op) + ": a second mesh; the harness runs scenarios of one mesh");
        plan.mesh_path = mesh_path(s, op.text);
        plan.mesh = read_plan_mesh(plan.mesh_path, where(s, op));
        have_mesh = true;
        break;
      case OpKind::kParam:
        if (op.text == "diameter") {
          diameter = *scenario::parse_double(op.value);  // the parser has read it already
        } else {
          plan.notes.push_back(where(s, op) + ": skipped: '" + op.text + "' tunes tetcut, not the engine interface");
        }
        break;
      case OpKind::kCut:
        add_cut(op, op.a, op.swept ? std::optional<Vec3>(op.b) : std::nullopt);
        break;
      case OpKind::kSweep:
        for (const scenario::CutTool& tool : scenario::sweep_cuts(op.a, op.b, op.step, op.swept)) {
          add_cut(op, tool.centre, tool.end);
        }
        break;
      case OpKind::kRemove: {
        EngineOperation remove{EngineOperation::Kind::kRemoveAt, op.a, std::nullopt, 0.0, ""};
        remove.name = where(s, op) + ": remove the tet at " + point_text(op.a);
        plan.operations.push_back(std::move(remove));
        break;
      }
      case OpKind::kUndo:
      case OpKind::kCompact:
      case OpKind::kUncuttable:
        throw std::runtime_error(where(s, op) +
                                 ": undo, compact and uncuttable are not in the engine interface, and the lines "
                                 "after them mean something else without them");
      case OpKind::kCheck:
        break;  // the harness checks after every operation anyway
      case OpKind::kExpectHash:
      case OpKind::kExpectTets:
      case OpKind::kExpectUnresolved:
      case OpKind::kExpectComponents:
      case OpKind::kExpectMinQuality:
        plan.notes.push_back(where(s, op) + ": skipped: an expectation of tetcut's own result");
        break;
    }
  }
  if (!have_mesh) throw std::runtime_error(s.name + ": no mesh line");
  return plan;
}

EnginePlan random_sweep_plan(const std::string& mesh_name, RawMesh mesh, std::uint64_t seed, std::uint32_t cuts,
                             double diameter_in_edges) {
  EnginePlan plan;
  char name[160];
  std::snprintf(name, sizeof name, "sweep %s seed %llu", mesh_name.c_str(), static_cast<unsigned long long>(seed));
  plan.name = name;
  const auto [low, high] = bounding_box(mesh);
  const double diameter = diameter_in_edges * median_edge_length(mesh);
  SplitMix64 random(seed);
  auto in_middle_third = [&](double a, double b) { return a + (b - a) * (1.0 + random.unit()) / 3.0; };
  const Vec3 through{in_middle_third(low.x, high.x), in_middle_third(low.y, high.y), in_middle_third(low.z, high.z)};
  // A uniform direction: a point drawn in the unit ball by rejection from the cube, normalised.
  Vec3 direction;
  double length = 0;
  do {
    direction = {2 * random.unit() - 1, 2 * random.unit() - 1, 2 * random.unit() - 1};
    length = norm(direction);
  } while (length < 1e-3 || length > 1.0);
  direction = (1.0 / length) * direction;
  const double step = diameter / 2;
  const Vec3 start = through - (step * cuts / 2.0) * direction;
  for (std::uint32_t k = 0; k < cuts; ++k) {
    const Vec3 centre = start + (step * k) * direction;
    plan.operations.push_back({EngineOperation::Kind::kCut, centre, std::nullopt, diameter,
                               "cut " + std::to_string(k + 1) + " at " + point_text(centre)});
  }
  plan.mesh = std::move(mesh);
  return plan;
}

}  // namespace tetcut::harness
