#include "operations/checked_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <utility>

#include "support/fuzz_failure.hpp"

namespace tetcut::fuzz {

namespace inv = tetcut::invariants;

CheckedMesh::CheckedMesh(TetMesh mesh) : mesh_(std::move(mesh)), expected_volume_(mesh_.total_volume()) {
  local_.emplace(mesh_.raw_view());
  const char* env = std::getenv("TETCUT_FUZZ_TRACE");
  tracing_ = env != nullptr && *env != '\0' && *env != '0';
  if (tracing_) trace(0, 0);
}

void CheckedMesh::reset(const TetMesh& mesh) {
  mesh_ = mesh;  // a copy-assignment: the vectors keep their capacity
  expected_volume_ = mesh_.total_volume();
  local_->reset(mesh_.raw_view());
  index_ = 0;
  name_ = "build";
  arguments_.clear();
  if (tracing_) trace(0, 0);
}

void CheckedMesh::begin(std::string name) {
  ++index_;
  name_ = std::move(name);
  arguments_.clear();
}

void CheckedMesh::end(const ChangeLog& log, std::optional<double> volume_change, inv::QualityRule rule,
                      const inv::ToolRule* tool, std::optional<double> min_dihedral_deg) {
  created_.clear();
  for (const CreatedTet& c : log.created) created_.push_back(c.tet);
  moved_.clear();
  for (const MovedVertex& m : log.moved) moved_.push_back(raw_moved(m));
  end(log.removed, created_, volume_change, rule, tool, min_dihedral_deg, moved_);
}

void CheckedMesh::end(std::span<const TetId> removed, std::span<const TetId> created,
                      std::optional<double> volume_change, inv::QualityRule rule, const inv::ToolRule* tool,
                      std::optional<double> min_dihedral_deg, std::span<const RawMovedVertex> moved) {
  if (volume_change) expected_volume_ += *volume_change;
  inv::CheckOptions options;
  if (tool) options.tool = *tool;
  options.moved = moved;
  if (min_dihedral_deg) options.min_dihedral_deg = *min_dihedral_deg;
  options.level = inv::CheckLevel::kLocal;
  options.quality_rule = rule;
  options.operation = name_;
  if (tracing_) trace(removed.size(), created.size());
  report(local_->after_operation(mesh_.raw_view(), removed, created, options, volume_change), "local");
}

void CheckedMesh::describe(const std::string& arguments) {
  if (!arguments_.empty()) arguments_ += ' ';
  arguments_ += arguments;
}

void CheckedMesh::trace(std::size_t removed, std::size_t created) const {
  std::fprintf(stderr, "tetcut-fuzz: operation %zu (%s%s%s): -%zu +%zu tets -> %u tets, %u vertices\n", index_,
               name_.c_str(), arguments_.empty() ? "" : " ", arguments_.c_str(), removed, created, mesh_.num_tets(),
               mesh_.num_vertices());
}

void CheckedMesh::end_renumbered() {
  if (tracing_) trace(0, 0);
  local_.emplace(mesh_.raw_view());
  full_check();
}

void CheckedMesh::full_check() {
  inv::CheckOptions options;
  options.level = inv::CheckLevel::kFull;
  options.operation = name_;
  // An empty mesh has nothing to compare a relative tolerance with.
  if (mesh_.num_tets() > 0) options.expected_volume = expected_volume_;
  report(inv::check_mesh(mesh_.raw_view(), options), "full");
}

void CheckedMesh::require(bool condition, std::string_view property, const std::string& detail) const {
  if (!condition) fail(property, index_, name_, detail);
}

void CheckedMesh::report(const inv::CheckReport& report, std::string_view level) const {
  if (report.ok()) return;
  const inv::Violation& first = report.violations.front();
  std::string detail(level);
  detail += " check: ";
  detail += inv::to_string(report);
  while (!detail.empty() && detail.back() == '\n') detail.pop_back();
  fail(inv::id_string(first.id), index_, name_, detail);
}

}  // namespace tetcut::fuzz
