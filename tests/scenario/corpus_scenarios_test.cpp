// Every scenario in corpus/scenarios/ runs to the end with all its checks and expectations
// (hashes included: the same bits in every build type and compiler).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "tetcut/scenario/scenario.hpp"

namespace tetcut::scenario {
namespace {

std::vector<std::string> scenario_files() {
  std::vector<std::string> out;
  for (const auto& e : std::filesystem::directory_iterator(TETCUT_CORPUS_DIR "/scenarios"))
    if (e.path().extension() == ".scn") out.push_back(e.path().filename().string());
  std::sort(out.begin(), out.end());
  return out;
}

class CorpusScenario : public ::testing::TestWithParam<std::string> {};

TEST_P(CorpusScenario, RunsWithEveryCheckAndExpectation) {
  const ParseResult p = parse_file(TETCUT_CORPUS_DIR "/scenarios/" + GetParam());
  ASSERT_TRUE(p.scenario) << p.error;
  const RunResult r = run(*p.scenario);
  EXPECT_TRUE(r.ok) << r.error;
  EXPECT_FALSE(r.cuts.empty());
}

INSTANTIATE_TEST_SUITE_P(Corpus, CorpusScenario, ::testing::ValuesIn(scenario_files()), [](const auto& info) {
  std::string n = info.param.substr(0, info.param.find('.'));
  for (char& c : n)
    if (c == '-') c = '_';
  return n;
});

}  // namespace
}  // namespace tetcut::scenario
