// The running half of a sequence target: a copy of a bundled mesh in a CheckedMesh, a Cutter on
// it, the scenario being recorded, and the checks every operation gets:
//   - the local checker on the Cutter's net change, with the volume change it implies (from a
//     per-tet volume cache, so that a tet killed but not reported breaks I9 in the full check);
//   - under the combined strategy every request is resolved ("unresolved-combined");
//   - a rolled back operation leaves the canonical hash as it was ("rollback-changed-mesh"),
//     compared with a copy of the mesh taken before the operation (a copy-assignment into the
//     same buffers: O(#T) memcpy, less than the operation itself; re-running the input up to
//     the operation instead made every rollback cost the whole prefix again);
//   - the full check when asked (check lines) and at the end.
// TETCUT_FUZZ_FAIL_AT=N in the environment makes operation N fail ("injected"): a test of what
// reports failures, independent of any bug. TETCUT_FUZZ_SLOW_AT=N makes operation N take 30 s:
// the same for what reports slowness (ci/fuzz-nightly's timeouts).
//
// One session per bundled mesh lives as long as the process (fuzzer throughput):
// start() copies the mesh back into the same buffers and resets the checker and the Cutter
// (Cutter::reset) instead of building them again, which was a third of an input's cost. An
// input's outcome does not depend on the inputs before it: tests/fuzz replays the corpus in two
// orders and compares every input's scenario and final mesh.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include <fuzzer/FuzzedDataProvider.h>

#include "operations/checked_mesh.hpp"
#include "operations/scenario_recorder.hpp"
#include "operations/sequence_meshes.hpp"
#include "operations/sequence_target.hpp"
#include "tetcut/cut.hpp"

namespace tetcut::fuzz {

struct OperationOutcome {
  std::size_t index = 0;      // CheckedMesh's operation index
  bool rolled_back = false;
  std::string reason;         // why, when rolled back
};

class SequenceSession {
 public:
  // The session of `bundled`, started on a fresh copy of its mesh, recording into `recorder`.
  // The Cutter starts with the default parameters but a per-operation tet budget of the
  // initial mesh's tets (params_with_budget), which the scenario sets on its second line
  // (max_tets_created): an operation over it is rolled back, and written into the scenario as a
  // comment, and what the budget stops without a rollback (a kept piece's request) the scenario
  // meets too. The reference is valid until the next start() on the same mesh.
  static SequenceSession& start(const BundledMesh& bundled, ScenarioRecorder& recorder);
  static CutParams params_with_budget(const BundledMesh& bundled);
  SequenceSession(const SequenceSession&) = delete;
  SequenceSession& operator=(const SequenceSession&) = delete;

  CheckedMesh& checked() { return checked_; }
  TetMesh& mesh() { return checked_.mesh(); }
  Cutter& cutter() { return cutter_; }
  ScenarioRecorder& recorder() { return *recorder_; }
  // The scenario runner's count of unresolved tets so far (of the operations that went through).
  [[nodiscard]] std::uint64_t unresolved() const { return unresolved_; }

  // A parameter line ("diameter 0.3"): recorded, then applied as the scenario runner does.
  void set_param(const std::string& name, const std::string& value, const CutParams& params);
  // The removal request for the tet containing p (a no-op when there is none), from line `line`.
  OperationOutcome remove_at(const Vec3& p, const std::string& name, std::uint32_t line);
  // One cut centred at c, from line `line`.
  OperationOutcome cut_at(const Vec3& c, const std::string& name, std::uint32_t line);
  // The capsule from a to b (Cutter::cut_segment), held to I10 as a capsule.
  OperationOutcome cut_segment_at(const Vec3& a, const Vec3& b, const std::string& name, std::uint32_t line);
  // "check full" as its own operation (recorded).
  void full_check();
  // The full check (recorded as "check full") unless nothing changed since the last one: the
  // periodic one and the final one. It dominates the cost of an input.
  void full_check_if_changed() {
    if (changed_since_full_check_) full_check();
  }
  // The end of an input: the full check if anything changed, and the final mesh's canonical
  // hash for the recorder.
  void finish();

 private:
  explicit SequenceSession(const BundledMesh& bundled);
  void restart(const BundledMesh& bundled, ScenarioRecorder& recorder);
  void begin(const std::string& name, std::uint32_t line);
  // The checks after a cut (with its centre: the tissue rule) or a removal request.
  OperationOutcome after(const CutReport& report, const Vec3* cut_centre = nullptr, const Vec3* cut_end = nullptr);
  void grow_volumes();

  ScenarioRecorder* recorder_ = nullptr;
  CheckedMesh checked_;
  TetMesh before_;  // the mesh before the current Cutter operation, for the rollback check
  Cutter cutter_;
  std::vector<double> volume_;  // per tet id, of the live tets
  std::uint64_t unresolved_ = 0;
  std::size_t fail_at_ = 0;  // TETCUT_FUZZ_FAIL_AT; 0: never
  std::size_t slow_at_ = 0;  // TETCUT_FUZZ_SLOW_AT; 0: never
  bool changed_since_full_check_ = false;
  bool pieces_bounded_ = false;  // a search for pieces stopped at its bound: Cutter::pieces() may be short since
};

// Runs `body` as a sequence target does: the version byte (is_sequence_version), failures
// captured or not, the recording. `body(version, input, recorder)` decodes and runs the
// operations.
SequenceResult run_sequence(const std::uint8_t* data, std::size_t size, const SequenceOptions& options,
                            const std::function<void(std::uint8_t, FuzzedDataProvider&, ScenarioRecorder&)>& body);

// The start of every sequence input: the mesh it chooses (its first value, sequence_meshes.hpp),
// the scenario's first lines ("# tetcut replay --target NAME ...", "mesh PATH"), and the session
// on a fresh copy of that mesh.
struct SequenceStart {
  const BundledMesh& bundled;
  SequenceSession& session;
};
SequenceStart start_sequence(std::string_view target, std::uint8_t version, FuzzedDataProvider& input,
                             ScenarioRecorder& recorder);

// The removal strategy an input chooses: versions 1-3 among basic, neighbours and combined (as
// they were found), kSequenceVersionAllStrategies and later among all four, `wide` included.
RemovalStrategy consume_strategy(std::uint8_t version, FuzzedDataProvider& input);

// The operation loop of every sequence target: `operation()` decodes and runs one operation,
// while `limits` allow, input remains and the mesh has tets but not kMaxTetsFactor times its
// initial ones; the periodic full checks; then finish().
template <class Operation>
void run_operations(const SequenceStart& start, FuzzedDataProvider& input, const SequenceLimits& limits,
                    Operation&& operation) {
  SequenceSession& session = start.session;
  const std::uint32_t max_tets = kMaxTetsFactor * start.bundled.mesh.num_tets();
  std::size_t since_check = 0;
  for (std::size_t i = 0; i < limits.max_operations && input.remaining_bytes() > 0 && session.mesh().num_tets() > 0 &&
                          session.mesh().num_tets() <= max_tets;
       ++i) {
    operation();
    if (++since_check == limits.full_check_every) {
      session.full_check_if_changed();
      since_check = 0;
    }
  }
  session.finish();
}

}  // namespace tetcut::fuzz
