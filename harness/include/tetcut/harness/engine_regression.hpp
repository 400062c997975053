// A failure of an engine, made small and kept: its signature (what broke), the plan cut down to
// the operations that still break it the same way (delta debugging), and the scenario file under
// corpus/regressions/engines/<engine>/<target>/ that replays it, as tetcut's own regressions are
// kept under corpus/regressions/<target>/.
#pragma once

#include <cstdint>
#include <string>

#include "tetcut/harness/engine_check.hpp"

namespace tetcut::harness {

// What broke, as one word a file name can hold: the first violated invariant ("I5"), the
// signal that killed the engine ("signal-6"), or "engine-error"; "" when the plan passed.
std::string signature_of(const PlanCheck& check);

struct Minimized {
  EnginePlan plan;
  std::uint64_t checks = 0;  // plans run to minimize
};

// The smallest plan found (delta debugging over the operations, ddmin) whose check still has
// `signature`, each candidate run in a child process as check_plan() runs it. `plan` must have it.
// At most `max_checks` candidates are run.
Minimized minimize_plan(const AdapterInfo& adapter, const EnginePlan& plan, const std::string& signature,
                        const EngineCheckOptions& options = {}, std::uint64_t max_checks = 4000);

// The plan as a scenario file (tools/scenario's language): its mesh relative to `dir` when both
// lie in one tree, a `diameter` line whenever the diameter changes, every point to the last bit
// (%.17g), and `header` as # comments. plan_from_scenario() reads it back to the same plan.
std::string scenario_text(const EnginePlan& plan, const std::string& dir, const std::string& header);

// Writes `text` to `dir`/`name`.scn through a temporary file and a rename, creating `dir`.
// Returns the path. Throws std::runtime_error naming the path when it cannot.
std::string write_regression(const std::string& dir, const std::string& name, const std::string& text);

// "<signature>-<first operation kind>-<10 hex digits of the text's hash>": the file's name.
std::string regression_name(const std::string& signature, const EnginePlan& plan, const std::string& text);

}  // namespace tetcut::harness
