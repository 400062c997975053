// Fuzzing any engine (engine_input, engine_fuzz, engine_regression): inputs decoded the same
// whatever the engine, mutations that keep the version, minimization that keeps the failure, and
// the demonstration the harness exists for: from the shipped seeds, a fixed seed and run count
// find blind removal's non-manifold result, minimize it to a few operations, and the scenario
// written fails for blind removal and passes for tetcut.
#include <gtest/gtest.h>

#include <stdlib.h>

#include <filesystem>

#include "tetcut/harness/engine_fuzz.hpp"
#include "tetcut/harness/engine_regression.hpp"

namespace tetcut::harness {
namespace {

namespace fs = std::filesystem;
const std::string kCorpus = TETCUT_CORPUS_DIR;

const std::vector<FuzzMesh>& meshes() {
  static const std::vector<FuzzMesh> loaded = load_fuzz_meshes(kCorpus);
  return loaded;
}

class EngineFuzz : public ::testing::Test {
 protected:
  void SetUp() override {
    scratch_ = fs::temp_directory_path() /
               ("tetcut_engine_fuzz_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(scratch_);
    fs::create_directories(scratch_);
  }
  void TearDown() override {
    unsetenv("TETCUT_FAULTY_ADAPTER");
    fs::remove_all(scratch_);
  }
  fs::path scratch_;
};

TEST(EngineInput, TheBytesAloneFixThePlan) {
  for (EngineTarget target : {EngineTarget::kCutSequence, EngineTarget::kRemovalSequence}) {
    for (const auto& seed : load_engine_seeds(kCorpus, target)) {
      const EnginePlan a = decode_engine_input(seed, target, meshes());
      const EnginePlan b = decode_engine_input(seed, target, meshes());
      ASSERT_FALSE(a.operations.empty()) << target_name(target);
      EXPECT_LE(a.operations.size(), kMaxEngineOperations);
      ASSERT_EQ(a.operations.size(), b.operations.size());
      for (std::size_t i = 0; i < a.operations.size(); ++i) {
        EXPECT_EQ(a.operations[i].a, b.operations[i].a);
        EXPECT_EQ(a.operations[i].diameter, b.operations[i].diameter);
      }
    }
  }
  const std::vector<std::uint8_t> other_version = {2, 0, 0, 1, 2, 3};
  EXPECT_TRUE(decode_engine_input(other_version, EngineTarget::kCutSequence, meshes()).operations.empty());
  EXPECT_TRUE(decode_engine_input({}, EngineTarget::kCutSequence, meshes()).operations.empty());
}

TEST(EngineInput, ARemovalAimsAtATetOfTheMesh) {
  const std::vector<std::uint8_t> input = {kEngineInputVersion, 0, 0, 5, 1, 0};
  const EnginePlan plan = decode_engine_input(input, EngineTarget::kRemovalSequence, meshes());
  ASSERT_EQ(plan.operations.size(), 2u);
  const auto& tet = plan.mesh.tets[5];
  Vec3 centroid{};
  for (std::uint32_t v : tet) centroid = centroid + 0.25 * plan.mesh.positions[v];
  EXPECT_EQ(plan.operations[0].a, centroid);
  EXPECT_EQ(plan.operations[0].kind, EngineOperation::Kind::kRemoveAt);
}

TEST(EngineInput, MutationsKeepTheVersionAndTheSizeBound) {
  const auto seeds = load_engine_seeds(kCorpus, EngineTarget::kCutSequence);
  std::uint64_t state_a = 7, state_b = 7;
  std::vector<std::uint8_t> a = seeds[0], b = seeds[0];
  for (int i = 0; i < 200; ++i) {
    a = mutate(a, seeds, state_a);
    b = mutate(b, seeds, state_b);
    ASSERT_EQ(a, b);  // the seed alone decides
    ASSERT_GE(a.size(), 2u);
    ASSERT_LE(a.size(), kMaxEngineInputSize);
    ASSERT_EQ(a[0], kEngineInputVersion);
  }
}

TEST_F(EngineFuzz, AScenarioTextReadsBackToTheSamePlan) {
  const auto seeds = load_engine_seeds(kCorpus, EngineTarget::kCutSequence);
  for (const auto& seed : seeds) {
    const EnginePlan plan = decode_engine_input(seed, EngineTarget::kCutSequence, meshes());
    const std::string path = write_regression(scratch_.string(), "round-trip", scenario_text(plan, scratch_.string(), "a test"));
    const EnginePlan back = plan_from_scenario(path);
    ASSERT_EQ(back.operations.size(), plan.operations.size());
    for (std::size_t i = 0; i < plan.operations.size(); ++i) {
      EXPECT_EQ(back.operations[i].a, plan.operations[i].a);  // to the last bit
      EXPECT_EQ(back.operations[i].b.has_value(), plan.operations[i].b.has_value());
      if (plan.operations[i].b) {
        EXPECT_EQ(*back.operations[i].b, *plan.operations[i].b);
      }
      EXPECT_EQ(back.operations[i].diameter, plan.operations[i].diameter);
    }
    EXPECT_EQ(back.mesh.tets, plan.mesh.tets);
  }
}

TEST_F(EngineFuzz, MinimizationKeepsTheFailureAndDropsTheRest) {
  // The faulty engine aborts in its third cut, whatever the cuts are: three are the minimum.
  setenv("TETCUT_FAULTY_ADAPTER", "abort-on-cut-3", 1);
  const AdapterInfo faulty = probe_adapter(TETCUT_ADAPTER_FAULTY);
  const EnginePlan plan = random_sweep_plan("cylinder.msh", meshes().front().mesh, 1, 9);
  ASSERT_EQ(signature_of(check_plan(faulty, plan)), "signal-6");
  const Minimized minimized = minimize_plan(faulty, plan, "signal-6");
  EXPECT_EQ(minimized.plan.operations.size(), 3u);
  EXPECT_GT(minimized.checks, 0u);
  EXPECT_EQ(signature_of(check_plan(faulty, minimized.plan)), "signal-6");
}

TEST_F(EngineFuzz, BlindRemovalsSingularityFoundMinimizedAndReplayed) {
  const AdapterInfo blind = probe_adapter(TETCUT_ADAPTER_BLIND);
  const AdapterInfo tetcut = probe_adapter(TETCUT_ADAPTER_TETCUT);
  EngineFuzzOptions options;
  options.target = EngineTarget::kCutSequence;
  options.seed = 1;
  options.runs = 40;
  options.corpus_dir = kCorpus;
  options.regressions_dir = scratch_.string();
  const EngineFuzzResult result = fuzz_engine(blind, options);
  EXPECT_EQ(result.runs, 40u);
  ASSERT_FALSE(result.findings.empty());
  const EngineFinding& finding = result.findings.front();
  EXPECT_TRUE(finding.signature == "I5" || finding.signature == "I6") << finding.signature;
  EXPECT_LE(finding.minimized_operations, 10u);
  ASSERT_FALSE(finding.path.empty());
  EXPECT_EQ(fs::path(finding.path).parent_path(), scratch_ / "blind" / "cut_sequence");

  const EnginePlan replay = plan_from_scenario(finding.path);
  EXPECT_EQ(replay.operations.size(), finding.minimized_operations);
  EXPECT_EQ(signature_of(check_plan(blind, replay)), finding.signature);
  const PlanCheck by_tetcut = check_plan(tetcut, replay);
  EXPECT_TRUE(by_tetcut.ok()) << by_tetcut.objection << by_tetcut.engine_error;

  // The same seed and runs find the same thing: the file is the same to the byte.
  fs::remove_all(scratch_ / "blind");
  const EngineFuzzResult again = fuzz_engine(blind, options);
  ASSERT_FALSE(again.findings.empty());
  EXPECT_EQ(again.findings.front().scenario, finding.scenario);
  EXPECT_EQ(again.findings.front().path, finding.path);
}

TEST_F(EngineFuzz, TetcutSurvivesTheSameFuzzing) {
  const AdapterInfo tetcut = probe_adapter(TETCUT_ADAPTER_TETCUT);
  for (EngineTarget target : {EngineTarget::kCutSequence, EngineTarget::kRemovalSequence}) {
    EngineFuzzOptions options;
    options.target = target;
    options.runs = 30;
    options.corpus_dir = kCorpus;
    const EngineFuzzResult result = fuzz_engine(tetcut, options);
    EXPECT_EQ(result.failing, 0u) << target_name(target) << ": "
                                  << (result.findings.empty() ? "" : result.findings.front().scenario);
  }
}

}  // namespace
}  // namespace tetcut::harness
