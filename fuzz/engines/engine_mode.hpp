// The sequence targets' engine mode: `cut_sequence -engine=LIB ...` (or TETCUT_FUZZ_ENGINE=LIB)
// fuzzes another engine through its adapter (tetcut/harness/engine.h) instead of tetcut. Its inputs
// are the engine inputs of harness/include/tetcut/harness/engine_input.hpp (seeds:
// corpus/fuzz/engines/<target>/), each run in this process with the independent checker after
// every operation (harness::check_plan_here): an engine that crashes is a crash libFuzzer keeps,
// and a checker objection is one line and an abort, as tetcut's own findings are
// (support/fuzz_failure.hpp), so that ci/fuzz-nightly's triage reads it the same way.
//
// `tetcut check-engine --fuzz` is the same search without coverage feedback, each input in a
// child process, with minimization into a scenario; this mode gives an adapter libFuzzer's
// coverage-guided search (the coverage of whatever of the engine was compiled with it).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>

namespace tetcut::fuzz {

// Looks for -engine=LIB (or --engine=LIB) among the arguments, taking it out of them so that
// libFuzzer does not warn, else for TETCUT_FUZZ_ENGINE. Loads the adapter and the fuzz meshes;
// exits with a message (status 2) when either fails, or when this build has no harness
// (TETCUT_BUILD_TOOLS off). `target`: "cut_sequence" or "removal_sequence".
void engine_mode_init(int* argc, char*** argv, std::string_view target);

// True after engine_mode_init() found an adapter.
bool engine_mode_on();

// Decodes the input as an engine input and checks the engine on it; fail()s on an objection or
// an engine error.
void run_engine_input(const std::uint8_t* data, std::size_t size);

}  // namespace tetcut::fuzz
