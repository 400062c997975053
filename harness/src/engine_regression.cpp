#include "tetcut/harness/engine_regression.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "tetcut/scenario/delta_debugging.hpp"
#include "tetcut/scenario/scenario.hpp"

namespace tetcut::harness {

namespace {

std::string exact(double v) {
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", v);
  return text;
}

std::string exact(const Vec3& p) { return exact(p.x) + "," + exact(p.y) + "," + exact(p.z); }

// FNV-1a, 64 bits: the same name for the same text on every platform.
std::uint64_t text_hash(const std::string& text) {
  std::uint64_t h = 0xcbf29ce484222325ull;
  for (unsigned char c : text) {
    h ^= c;
    h *= 0x100000001b3ull;
  }
  return h;
}

}  // namespace

std::string signature_of(const PlanCheck& check) {
  if (check.signal != 0) return "signal-" + std::to_string(check.signal);
  if (!check.engine_error.empty()) return "engine-error";
  if (check.failed_operation) return check.invariants.empty() ? "objection" : check.invariants.front();
  return "";
}

Minimized minimize_plan(const AdapterInfo& adapter, const EnginePlan& plan, const std::string& signature,
                        const EngineCheckOptions& options, std::uint64_t max_checks) {
  Minimized result{plan, 0};
  EnginePlan trial = plan;  // the mesh copied once; each candidate's operations put into it
  auto reproduces = [&](const std::vector<EngineOperation>& candidate) {
    ++result.checks;
    trial.operations = candidate;
    return signature_of(check_plan(adapter, trial, options)) == signature;
  };
  scenario::delta_debug(result.plan.operations, reproduces, [&] { return result.checks >= max_checks; });
  return result;
}

std::string scenario_text(const EnginePlan& plan, const std::string& dir, const std::string& header) {
  std::ostringstream text;
  std::istringstream lines(header);
  for (std::string line; std::getline(lines, line);) text << "# " << line << "\n";
  text << "mesh " << scenario::mesh_path_from(plan.mesh_path, dir) << "\n";
  double diameter = -1;
  for (const EngineOperation& op : plan.operations) {
    if (op.kind == EngineOperation::Kind::kRemoveAt) {
      text << "remove " << exact(op.a) << "\n";
      continue;
    }
    if (op.diameter != diameter) {
      diameter = op.diameter;
      text << "diameter " << exact(diameter) << "\n";
    }
    text << "cut " << exact(op.a);
    if (op.b) text << " " << exact(*op.b);
    text << "\n";
  }
  return text.str();
}

std::string regression_name(const std::string& signature, const EnginePlan& plan, const std::string& text) {
  const char* kind = plan.operations.empty() ? "none"
                     : plan.operations.front().kind == EngineOperation::Kind::kRemoveAt ? "remove"
                                                                                       : "cut";
  char hash[16];
  std::snprintf(hash, sizeof hash, "%010llx",
                static_cast<unsigned long long>(text_hash(text) & 0xFFFFFFFFFFull));
  return signature + "-" + kind + "-" + hash;
}

std::string write_regression(const std::string& dir, const std::string& name, const std::string& text) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::create_directories(dir, ec);
  const fs::path path = fs::path(dir) / (name + ".scn");
  const fs::path temporary = fs::path(dir) / ("." + name + ".scn.tmp");
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out << text;
    if (!out.flush()) throw std::runtime_error(temporary.string() + ": cannot write");
  }
  fs::rename(temporary, path, ec);
  if (ec) throw std::runtime_error(path.string() + ": cannot rename into place: " + ec.message());
  return path.string();
}

}  // namespace tetcut::harness
