// `tetcut check-engine` run as a user runs it: the exit code says whether the engine passed, the
// text and the JSON say which operation broke what, and a bad adapter or scenario is bad input.
#include <gtest/gtest.h>

#include <stdlib.h>

#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "run_process.hpp"

namespace tetcut::test {
namespace {

const std::string kCorpus = TETCUT_CORPUS_DIR;

class CheckEngineCli : public ::testing::Test {
 protected:
  void SetUp() override {
    scratch_ = std::filesystem::temp_directory_path() /
               ("tetcut_check_engine_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    std::filesystem::create_directories(scratch_);
  }
  void TearDown() override {
    unsetenv("TETCUT_FAULTY_ADAPTER");
    std::filesystem::remove_all(scratch_);
  }
  ProcessResult run(std::vector<std::string> args) {
    args.insert(args.begin(), "check-engine");
    return run_process(TETCUT_EXE, args, scratch_.string());
  }
  std::filesystem::path scratch_;
};

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST_F(CheckEngineCli, TetcutPassesTheCylinderScenarioAndASweep) {
  const ProcessResult r = run({"--engine", TETCUT_ADAPTER_TETCUT, "--scenario", kCorpus + "/scenarios/cylinder-cut.scn",
                               "--mesh", kCorpus + "/meshes/cylinder.msh", "--cuts", "12"});
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_TRUE(contains(r.out, "adapter 'tetcut'")) << r.out;
  EXPECT_TRUE(contains(r.out, "2 of 2 plans passed")) << r.out;
}

TEST_F(CheckEngineCli, BlindRemovalFailsNamingTheOperationAndTheInvariant) {
  const ProcessResult r = run({"--engine", TETCUT_ADAPTER_BLIND, "--mesh", kCorpus + "/meshes/cylinder.msh", "--json"});
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  const nlohmann::json doc = nlohmann::json::parse(r.out);
  EXPECT_FALSE(doc["ok"].get<bool>());
  EXPECT_EQ(doc["adapter"]["name"], "blind");
  const nlohmann::json& plan = doc["plans"][0];
  EXPECT_FALSE(plan["ok"].get<bool>());
  EXPECT_TRUE(plan["failed_operation"].is_number());
  EXPECT_TRUE(contains(plan["failed_operation_name"].get<std::string>(), "cut ")) << plan.dump();
  EXPECT_TRUE(contains(plan["objection"].get<std::string>(), "manifold")) << plan.dump();
}

TEST_F(CheckEngineCli, ACrashingEngineIsReportedAndTheOtherPlansStillRun) {
  setenv("TETCUT_FAULTY_ADAPTER", "abort-on-cut-2", 1);
  const ProcessResult r = run({"--engine", TETCUT_ADAPTER_FAULTY, "--mesh", kCorpus + "/meshes/cylinder.msh", "--mesh",
                               kCorpus + "/meshes/sheet.msh", "--cuts", "3"});
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_TRUE(contains(r.out, "killed by signal 6")) << r.out;
  EXPECT_TRUE(contains(r.out, "during cut 2 at")) << r.out;
  EXPECT_TRUE(contains(r.out, "0 of 2 plans passed")) << r.out;  // both ran, both crashed
}

TEST_F(CheckEngineCli, AnUnloadableAdapterOrAnUnplannableScenarioIsBadInput) {
  ProcessResult r = run({"--engine", "/nonexistent/libnothing.so"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(contains(r.err, "/nonexistent/libnothing.so")) << r.err;
  r = run({"--engine", TETCUT_ADAPTER_TETCUT, "--scenario", kCorpus + "/scenarios/cylinder-retry.scn"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(contains(r.err, "cylinder-retry.scn:")) << r.err;
  r = run({"--engine", TETCUT_ADAPTER_TETCUT, "--diameter-edges", "0"});
  EXPECT_EQ(r.exit_code, 2);
}

}  // namespace
}  // namespace tetcut::test
