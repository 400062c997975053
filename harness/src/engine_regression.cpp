#include "tetcut/harness/engine_regression.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

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
  std::vector<EngineOperation>& ops = result.plan.operations;
  auto reproduces = [&](const std::vector<EngineOperation>& candidate) {
    if (result.checks >= max_checks) return false;
    ++result.checks;
    EnginePlan trial = result.plan;
    trial.operations = candidate;
    return signature_of(check_plan(adapter, trial, options)) == signature;
  };
  // ddmin (Zeller and Hildebrandt): drop ever smaller chunks while the failure stays the same.
  std::size_t parts = 2;
  while (ops.size() >= 2) {
    const std::size_t chunk = (ops.size() + parts - 1) / parts;
    bool reduced = false;
    for (std::size_t start = 0; start < ops.size(); start += chunk) {
      std::vector<EngineOperation> candidate(ops.begin(), ops.begin() + static_cast<std::ptrdiff_t>(start));
      candidate.insert(candidate.end(), ops.begin() + static_cast<std::ptrdiff_t>(std::min(start + chunk, ops.size())),
                       ops.end());
      if (reproduces(candidate)) {
        ops = std::move(candidate);
        parts = std::max<std::size_t>(parts - 1, 2);
        reduced = true;
        break;
      }
    }
    if (!reduced) {
      if (parts >= ops.size() || result.checks >= max_checks) break;
      parts = std::min(ops.size(), 2 * parts);
    }
  }
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
