// Driving an engine adapter through a plan with the independent checker after every operation
// (what `tetcut check-engine` runs). Each plan runs in a child process (child_process.hpp): an
// engine that crashes is reported with its signal, the adapter and the operation.
//
// After every operation the harness reads the engine's mesh back (engine.h's mesh()) and checks
// it: with a change log, the local check of what the operation says it removed and created
// (LocalChecker, O(operation)), the moved vertices held to their reported positions, the
// no-degradation rule (I7) only when the adapter promises it (by the lower angle floor an
// operation says it held, counted in the report) and the tissue rule (I10) only when
// it promises that; without a change log, the full check of the whole mesh (check_raw, O(n)),
// with quality reported and not judged. The first objection stops the plan: the checker assumes
// a valid mesh before each operation, and the first broken one is what a user triages.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "tetcut/harness/child_process.hpp"
#include "tetcut/harness/engine_library.hpp"
#include "tetcut/harness/engine_plan.hpp"
#include "tetcut/invariants/check.hpp"

namespace tetcut::harness {

// What an adapter says of itself, as the harness read it from the library (in a child).
struct AdapterInfo {
  std::string path, name, version;
  std::uint32_t abi_version = 0;
  std::uint32_t capabilities = 0;
};

struct PlanCheck {
  std::string adapter;                 // the adapter's name
  std::string plan;                    // EnginePlan::name
  std::string level;                   // "local" (change log) or "full"
  std::uint64_t operations = 0;        // in the plan
  std::uint64_t run = 0;               // carried out and checked (refused ones included)
  std::uint64_t refused = 0;           // TETCUT_ENGINE_REFUSED
  std::uint64_t missed = 0;            // removals whose point no live tet holds (not sent)
  std::uint64_t tets_before = 0, tets_after = 0;  // live tets
  double volume_before = 0.0, volume_after = 0.0;
  // The first operation the checker objected to (1-based; 0: the mesh as created), its name, the
  // violated invariants ("I5") and the checker's report.
  std::optional<std::uint64_t> failed_operation;
  std::string failed_operation_name;
  std::vector<std::string> invariants;
  std::string objection;
  // Singular vertices (I5) and edges (I6) and flat or inverted tets (I4) in the mesh at the end,
  // by a full check.
  std::uint64_t singular_vertices = 0, singular_edges = 0, inverted_tets = 0;
  // Quality of the tets the operations created (local) or of the final mesh (full).
  double min_radius_ratio = 1.0, min_dihedral_deg = 180.0;
  std::uint64_t quality_tets = 0;
  // Operations in which the engine said it held its created tets to a lower angle floor than the
  // rule's (engine.h: angle_floor_lowered), judged by that floor, and the lowest it went.
  std::uint64_t angle_floor_lowered = 0;
  double lowest_angle_floor_deg = 180.0;
  // The engine failed (TETCUT_ENGINE_ERROR, a bad answer) or its child died: why, for people.
  std::string engine_error;
  int signal = 0;
  std::vector<std::string> notes;

  [[nodiscard]] bool ok() const { return !failed_operation && engine_error.empty(); }
};

struct EngineCheckOptions {
  unsigned timeout_seconds = 600;  // per plan; 0: none
};

// Loads the adapter in a child and reads its table. Throws EngineError when it cannot be loaded
// or its table is invalid (the child's message), or when the child died doing it.
AdapterInfo probe_adapter(const std::string& adapter_path);

// Runs `plan` through a fresh engine of the adapter (as probe_adapter() found it) in a child
// process.
PlanCheck check_plan(const AdapterInfo& adapter, const EnginePlan& plan, const EngineCheckOptions& options = {});

// The same in this process (what the child runs; tests call it for an adapter they trust).
PlanCheck check_plan_here(const EngineLibrary& library, const EnginePlan& plan, const Announce* announce = nullptr);

}  // namespace tetcut::harness
