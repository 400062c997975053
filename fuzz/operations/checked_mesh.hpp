// A mesh under fuzzing: every operation is bracketed by begin()/end(), and end() runs the local
// checker over what the operation touched (invariants I1-I9, and I10 after a cut), aborting with the
// invariant's id and the operation's index on the first violation (fuzz_failure.hpp). The full
// check runs on request (every few operations: it is O(#T)).
//
// Operations that report through a ChangeLog (splits, refinement, removal requests, cuts) hand
// end(log) their net change, which the mesh's journal derives at commit: the tets live before
// and removed, and the tets live afterwards that the operation created.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "tetcut/change_log.hpp"
#include "tetcut/ids.hpp"
#include "tetcut/invariants/check.hpp"
#include "tetcut/mesh.hpp"

namespace tetcut::fuzz {

class CheckedMesh {
 public:
  explicit CheckedMesh(TetMesh mesh);
  // Starts over on a copy of `mesh`, as a new CheckedMesh would, in the memory this one holds.
  void reset(const TetMesh& mesh);

  TetMesh& mesh() { return mesh_; }
  [[nodiscard]] const TetMesh& mesh() const { return mesh_; }
  [[nodiscard]] std::size_t operation_index() const { return index_; }
  [[nodiscard]] const std::string& operation_name() const { return name_; }
  // The total volume the mesh must have: the initial volume minus every removed tet's.
  [[nodiscard]] double expected_volume() const { return expected_volume_; }

  // Starts operation number operation_index() + 1 (the first is 1), named for messages.
  void begin(std::string name);
  // With TETCUT_FUZZ_TRACE=1 in the environment every operation is printed to stderr as it ends,
  // with what describe() added (its decoded arguments): the input read as a scenario, for
  // triage. Build the description only when tracing() says so: it costs executions.
  [[nodiscard]] bool tracing() const { return tracing_; }
  void describe(const std::string& arguments);
  // Ends it: the local check of the net change recorded in `log` (TetMesh::commit's). `volume_change` is the
  // operation's expected change of the total volume (0 for splits; nullopt: not checked).
  // `rule`: a Cutter transaction is judged by I7's no-degradation rule; a raw operation (a split,
  // a refinement loop) only reports quality (invariants/check.hpp, QualityRule).
  // `tool`: the operation was a cut with this tool, held to the tissue rule (I10);
  // `min_dihedral_deg`: the theta a Cutter transaction held (Cutter::last_min_dihedral_held()).
  void end(const ChangeLog& log, std::optional<double> volume_change,
           invariants::QualityRule rule = invariants::QualityRule::kNoDegradation,
           const invariants::ToolRule* tool = nullptr, std::optional<double> min_dihedral_deg = std::nullopt);
  // `moved`: the vertices there before that the operation moved (Cutter::last_moved()).
  void end(std::span<const TetId> removed, std::span<const TetId> created, std::optional<double> volume_change,
           invariants::QualityRule rule = invariants::QualityRule::kNoDegradation,
           const invariants::ToolRule* tool = nullptr, std::optional<double> min_dihedral_deg = std::nullopt,
           std::span<const RawMovedVertex> moved = {});
  // Ends an operation that renumbered everything (compact()): the local checker starts over and
  // the full check runs.
  void end_renumbered();

  // The O(#T) check of the whole mesh, including I9 against expected_volume().
  void full_check();

  // Aborts with `property` unless `condition` holds, naming the current operation.
  void require(bool condition, std::string_view property, const std::string& detail) const;

 private:
  void report(const invariants::CheckReport& report, std::string_view level) const;
  void trace(std::size_t removed, std::size_t created) const;

  TetMesh mesh_;
  std::optional<invariants::LocalChecker> local_;
  double expected_volume_ = 0.0;
  std::size_t index_ = 0;
  std::string name_ = "build";
  std::string arguments_;
  bool tracing_ = false;
  std::vector<TetId> created_;
  std::vector<RawMovedVertex> moved_;
};

}  // namespace tetcut::fuzz
