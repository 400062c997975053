// The stored failures of other engines (corpus/regressions/engines/<engine>/<target>/*.scn),
// replayed: each must still fail on its engine with the signature its header records (when that
// engine's adapter is built here), and tetcut must pass every one of them. A peer's fix shows up
// here as a failure to reproduce: then the file goes, with the reason in the commit.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include "tetcut/harness/engine_regression.hpp"

namespace tetcut::harness {
namespace {

namespace fs = std::filesystem;

// The header line "# NAME: value" of a regression file.
std::string header_value(const fs::path& file, const std::string& name) {
  std::ifstream in(file);
  const std::string prefix = "# " + name + ": ";
  for (std::string line; std::getline(in, line);) {
    if (line.rfind(prefix, 0) == 0) return line.substr(prefix.size());
  }
  return "";
}

TEST(EngineRegressions, FailOnTheirEngineAndPassOnTetcut) {
  const std::map<std::string, std::string> built = {{"blind", TETCUT_ADAPTER_BLIND}, {"tetcut", TETCUT_ADAPTER_TETCUT}};
  const AdapterInfo tetcut = probe_adapter(TETCUT_ADAPTER_TETCUT);
  std::size_t replayed = 0;
  for (const auto& entry : fs::recursive_directory_iterator(fs::path(TETCUT_CORPUS_DIR) / "regressions" / "engines")) {
    if (!entry.is_regular_file() || entry.path().extension() != ".scn") continue;
    const fs::path& file = entry.path();
    const std::string engine = file.parent_path().parent_path().filename().string();
    const std::string signature = header_value(file, "signature");
    EXPECT_EQ(header_value(file, "engine"), engine) << file;
    EXPECT_FALSE(signature.empty()) << file << ": no '# signature:' line";
    const EnginePlan plan = plan_from_scenario(file.string());
    if (const auto adapter = built.find(engine); adapter != built.end() && engine != "tetcut") {
      EXPECT_EQ(signature_of(check_plan(probe_adapter(adapter->second), plan)), signature)
          << file << " no longer fails on " << engine << " as recorded";
    }
    const PlanCheck by_tetcut = check_plan(tetcut, plan);
    EXPECT_TRUE(by_tetcut.ok()) << file << ": " << by_tetcut.objection << by_tetcut.engine_error;
    ++replayed;
  }
  EXPECT_GE(replayed, 2u);  // blind removal's cut and removal findings, at least
}

}  // namespace
}  // namespace tetcut::harness
