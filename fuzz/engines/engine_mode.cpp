#include "engines/engine_mode.hpp"

#include <cstdio>
#include <cstdlib>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "support/fuzz_failure.hpp"

#ifdef TETCUT_FUZZ_HAVE_ENGINES
#include "tetcut/harness/engine_check.hpp"
#include "tetcut/harness/engine_input.hpp"
#include "tetcut/harness/engine_regression.hpp"
#endif

namespace tetcut::fuzz {

namespace {

std::optional<std::string> take_engine_argument(int* argc, char*** argv) {
  std::optional<std::string> found;
  int kept = 0;
  for (int i = 0; i < *argc; ++i) {
    const std::string_view arg = (*argv)[i];
    bool engine = false;
    for (std::string_view prefix : {"-engine=", "--engine="}) {
      if (i > 0 && arg.starts_with(prefix)) {
        found = std::string(arg.substr(prefix.size()));
        engine = true;
        break;
      }
    }
    if (!engine) (*argv)[kept++] = (*argv)[i];
  }
  *argc = kept;
  if (!found) {
    if (const char* env = std::getenv("TETCUT_FUZZ_ENGINE"); env != nullptr && *env != '\0') found = env;
  }
  return found;
}

#ifdef TETCUT_FUZZ_HAVE_ENGINES
struct EngineMode {
  std::unique_ptr<harness::EngineLibrary> library;
  harness::EngineTarget target{};
  std::vector<harness::FuzzMesh> meshes;
};
EngineMode* mode = nullptr;
#endif

}  // namespace

void engine_mode_init(int* argc, char*** argv, std::string_view target) {
  const std::optional<std::string> adapter = take_engine_argument(argc, argv);
  if (!adapter) return;
#ifdef TETCUT_FUZZ_HAVE_ENGINES
  try {
    auto m = std::make_unique<EngineMode>();
    m->library = std::make_unique<harness::EngineLibrary>(*adapter);
    m->target = *harness::engine_target(target);
    const char* corpus = std::getenv("TETCUT_CORPUS_DIR");
    m->meshes = harness::load_fuzz_meshes(corpus != nullptr && *corpus != '\0' ? corpus : TETCUT_FUZZ_CORPUS_ROOT);
    std::fprintf(stderr, "tetcut-fuzz: engine mode: %s, %s inputs (corpus/fuzz/engines/%s)\n",
                 m->library->label().c_str(), std::string(target).c_str(), std::string(target).c_str());
    mode = m.release();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tetcut-fuzz: %s\n", e.what());
    std::exit(2);
  }
#else
  std::fprintf(stderr, "tetcut-fuzz: -engine=%s: this build has no engine harness (TETCUT_BUILD_TOOLS is off)\n",
               adapter->c_str());
  std::exit(2);
#endif
}

bool engine_mode_on() {
#ifdef TETCUT_FUZZ_HAVE_ENGINES
  return mode != nullptr;
#else
  return false;
#endif
}

void run_engine_input(const std::uint8_t* data, std::size_t size) {
#ifdef TETCUT_FUZZ_HAVE_ENGINES
  const harness::EnginePlan plan =
      harness::decode_engine_input(std::span<const std::uint8_t>(data, size), mode->target, mode->meshes);
  if (plan.operations.empty()) return;
  const harness::PlanCheck check = harness::check_plan_here(*mode->library, plan);
  if (check.ok()) return;
  const std::size_t index = check.failed_operation.value_or(check.run);
  const std::string& name = check.failed_operation_name.empty() ? plan.name : check.failed_operation_name;
  // The finding is one line (ci/fuzz-nightly reads it): the report's lines joined.
  std::string detail = check.engine_error.empty() ? check.objection : check.engine_error;
  for (std::size_t at = detail.find('\n'); at != std::string::npos; at = detail.find('\n', at)) detail.replace(at, 1, "; ");
  fail(harness::signature_of(check), index, name, detail);
#else
  (void)data;
  (void)size;
#endif
}

}  // namespace tetcut::fuzz
