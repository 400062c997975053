// The harness for any engine (harness/): adapters loaded and validated, plans made from
// scenarios and seeds, each plan checked in a child process, and every kind of bad adapter
// reported by name, operation and reason, never a crash of the harness.
#include <gtest/gtest.h>

#include <signal.h>
#include <stdlib.h>

#include <algorithm>
#include <string>

#include "tetcut/harness/engine_check.hpp"
#include "tetcut/io.hpp"
#include "tetcut/scenario/sweep.hpp"

namespace tetcut::harness {
namespace {

const std::string kCorpus = TETCUT_CORPUS_DIR;

RawMesh corpus_mesh(const std::string& name) {
  ReadResult read = read_mesh(kCorpus + "/meshes/" + name);
  EXPECT_TRUE(read.mesh.has_value());
  return std::move(*read.mesh);
}

AdapterInfo adapter(const std::string& path) { return probe_adapter(path); }

// Sets TETCUT_FAULTY_ADAPTER for one test; the children the harness forks inherit it.
class FaultyAdapter : public ::testing::Test {
 protected:
  void TearDown() override { unsetenv("TETCUT_FAULTY_ADAPTER"); }
  static void fault(const char* mode) { setenv("TETCUT_FAULTY_ADAPTER", mode, 1); }
  static EnginePlan three_cuts() { return random_sweep_plan("cylinder.msh", corpus_mesh("cylinder.msh"), 1, 3); }
};

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(EngineLibrary, LoadsTheShippedAdaptersWithTheirCapabilities) {
  const EngineLibrary tetcut(TETCUT_ADAPTER_TETCUT);
  EXPECT_EQ(tetcut.name(), "tetcut");
  EXPECT_TRUE(tetcut.has(TETCUT_ENGINE_CHANGE_LOG));
  EXPECT_TRUE(tetcut.has(TETCUT_ENGINE_TISSUE_RULE));
  const EngineLibrary blind(TETCUT_ADAPTER_BLIND);
  EXPECT_EQ(blind.name(), "blind");
  EXPECT_TRUE(blind.has(TETCUT_ENGINE_CAPSULE));
  EXPECT_FALSE(blind.has(TETCUT_ENGINE_QUALITY_FLOOR));
  EXPECT_EQ(capability_names(blind.api().capabilities), "capsule, change log");
}

TEST(EngineLibrary, AMissingFileOrEntryPointIsALoadError) {
  try {
    EngineLibrary missing("/nonexistent/libnothing.so");
    FAIL() << "loaded a missing file";
  } catch (const EngineError& e) {
    EXPECT_EQ(e.operation(), "load");
    EXPECT_TRUE(contains(e.what(), "/nonexistent/libnothing.so")) << e.what();
  }
  // A shared library that is no adapter: the harness's own process has libc loaded.
  try {
    EngineLibrary libc("libc.so.6");
    FAIL() << "libc passed for an adapter";
  } catch (const EngineError& e) {
    EXPECT_TRUE(contains(e.what(), "no symbol tetcut_engine_adapter")) << e.what();
  }
}

TEST_F(FaultyAdapter, AnUnknownVersionOrAMissingFunctionIsRefusedAtLoad) {
  fault("abi-99");
  try {
    probe_adapter(TETCUT_ADAPTER_FAULTY);
    FAIL() << "abi 99 accepted";
  } catch (const std::exception& e) {
    EXPECT_TRUE(contains(e.what(), "abi_version 99")) << e.what();
    EXPECT_TRUE(contains(e.what(), "adapter 'faulty'")) << e.what();
  }
  fault("no-mesh");
  try {
    probe_adapter(TETCUT_ADAPTER_FAULTY);
    FAIL() << "a NULL mesh function accepted";
  } catch (const std::exception& e) {
    EXPECT_TRUE(contains(e.what(), "required function mesh is NULL")) << e.what();
  }
}

TEST(ChildProcess, ReturnsThePayloadOrTheSignalAndTheLastAnnouncement) {
  const ChildOutcome fine = run_in_child([](const Announce& announce) {
    announce("step one");
    return std::string("{\"answer\": 42}");
  });
  EXPECT_TRUE(fine.completed);
  EXPECT_EQ(fine.payload, "{\"answer\": 42}");
  EXPECT_EQ(fine.last_announced, "step one");

  const ChildOutcome crashed = run_in_child([](const Announce& announce) -> std::string {
    announce("step one");
    announce("step\ntwo");  // one line on the pipe
    std::abort();
  });
  EXPECT_FALSE(crashed.completed);
  EXPECT_EQ(crashed.signal, SIGABRT);
  EXPECT_EQ(crashed.last_announced, "step two");
  EXPECT_TRUE(contains(crashed.failure(), "signal 6")) << crashed.failure();
  EXPECT_TRUE(contains(crashed.failure(), "during step two")) << crashed.failure();

  const ChildOutcome thrown = run_in_child([](const Announce&) -> std::string { throw std::runtime_error("no mesh"); });
  EXPECT_FALSE(thrown.completed);
  EXPECT_EQ(thrown.error, "no mesh");
}

TEST_F(FaultyAdapter, ACrashIsReportedWithItsSignalTheAdapterAndTheOperation) {
  fault("abort-on-cut-2");
  const AdapterInfo info = adapter(TETCUT_ADAPTER_FAULTY);
  const PlanCheck check = check_plan(info, three_cuts());
  EXPECT_FALSE(check.ok());
  EXPECT_EQ(check.signal, SIGABRT);
  EXPECT_TRUE(contains(check.engine_error, "adapter 'faulty'")) << check.engine_error;
  EXPECT_TRUE(contains(check.engine_error, "during cut 2 at")) << check.engine_error;
}

TEST_F(FaultyAdapter, AHungEngineIsKilledAtTheTimeout) {
  fault("hang");
  const PlanCheck check = check_plan(adapter(TETCUT_ADAPTER_FAULTY), three_cuts(), {.timeout_seconds = 1});
  EXPECT_EQ(check.signal, SIGALRM);
  EXPECT_TRUE(contains(check.engine_error, "during cut 1 at")) << check.engine_error;
}

TEST_F(FaultyAdapter, BadAnswersAreNamedNotRead) {
  struct Case {
    const char* mode;
    const char* says;
  };
  const Case cases[] = {
      {"error", "cut_ball() failed: the tool left the workspace"},
      {"status-7", "cut_ball() returned an unknown status 7"},
      {"bad-vertex", "mesh() returned tet 0 with vertex"},
      {"null-points", "mesh() returned"},
      {"bad-removed", "changes() lists removed tet"},
      {"create-fails", "create: the faulty engine refuses every mesh"},
  };
  for (const Case& c : cases) {
    fault(c.mode);
    const PlanCheck check = check_plan(adapter(TETCUT_ADAPTER_FAULTY), three_cuts());
    EXPECT_FALSE(check.ok()) << c.mode;
    EXPECT_EQ(check.signal, 0) << c.mode;
    EXPECT_TRUE(contains(check.engine_error, c.says)) << c.mode << ": " << check.engine_error;
    EXPECT_TRUE(contains(check.engine_error, "adapter 'faulty'")) << c.mode << ": " << check.engine_error;
  }
}

TEST(EngineCheck, TetcutPassesWhatBlindRemovalBreaks) {
  const EnginePlan plan = random_sweep_plan("cylinder.msh", corpus_mesh("cylinder.msh"), 1, 24);
  const PlanCheck tetcut = check_plan(adapter(TETCUT_ADAPTER_TETCUT), plan);
  EXPECT_TRUE(tetcut.ok()) << tetcut.objection << tetcut.engine_error;
  EXPECT_EQ(tetcut.run, 24u);
  EXPECT_EQ(tetcut.level, "local");
  EXPECT_GT(tetcut.quality_tets, 0u);
  EXPECT_GE(tetcut.min_dihedral_deg, 15.0);  // the floor it promises, judged by the checker
  EXPECT_EQ(tetcut.singular_vertices + tetcut.singular_edges, 0u);

  const PlanCheck blind = check_plan(adapter(TETCUT_ADAPTER_BLIND), plan);
  ASSERT_TRUE(blind.failed_operation.has_value());
  EXPECT_TRUE(std::count(blind.invariants.begin(), blind.invariants.end(), "I5") +
                  std::count(blind.invariants.begin(), blind.invariants.end(), "I6") >
              0)
      << blind.objection;
  EXPECT_GT(blind.singular_vertices + blind.singular_edges, 0u);
  EXPECT_TRUE(blind.engine_error.empty()) << blind.engine_error;
}

TEST(EngineCheck, ThePeersAreCheckedAsTheyAre) {
  const EnginePlan plan = random_sweep_plan("cylinder.msh", corpus_mesh("cylinder.msh"), 1, 24);
  // Blind removal as iMSTK and SOFA do it: singular vertices or edges; SOFA renumbers (no
  // change log), so it is checked whole after every cut.
  for (const char* path : {TETCUT_ADAPTER_IMSTK_STYLE, TETCUT_ADAPTER_SOFA_STYLE}) {
    const PlanCheck check = check_plan(adapter(path), plan);
    ASSERT_TRUE(check.failed_operation.has_value()) << path;
    EXPECT_TRUE(check.invariants.front() == "I5" || check.invariants.front() == "I6") << check.objection;
    EXPECT_TRUE(check.engine_error.empty()) << check.engine_error;
  }
  EXPECT_EQ(check_plan(adapter(TETCUT_ADAPTER_SOFA_STYLE), plan).level, "full");
  // The same cuts remove the same tets in both: the first objection comes at the same cut.
  EXPECT_EQ(check_plan(adapter(TETCUT_ADAPTER_IMSTK_STYLE), plan).failed_operation,
            check_plan(adapter(TETCUT_ADAPTER_BLIND), plan).failed_operation);
#ifdef TETCUT_ADAPTER_CGAL
  // CGAL's classification keeps the mesh manifold by refusing removals.
  const PlanCheck cgal = check_plan(adapter(TETCUT_ADAPTER_CGAL), plan);
  EXPECT_TRUE(cgal.ok()) << cgal.objection << cgal.engine_error;
  EXPECT_GT(cgal.refused, 0u);
  // Remeshing the tool's neighbourhood first, then the same classification: manifold too, and
  // with no change log, checked whole after every cut.
  const PlanCheck remesh = check_plan(adapter(TETCUT_ADAPTER_CGAL_REMESH), plan);
  EXPECT_TRUE(remesh.ok()) << remesh.objection << remesh.engine_error;
  EXPECT_EQ(remesh.level, "full");
  EXPECT_EQ(remesh.run, 24u);
  // TetGen refining the neighbourhood, then the blind removal: its boundary splices back (no
  // engine error), and the removal leaves what blind removal leaves.
  const PlanCheck tetgen = check_plan(adapter(TETCUT_ADAPTER_TETGEN_LOCAL), plan);
  EXPECT_TRUE(tetgen.engine_error.empty()) << tetgen.engine_error;
  ASSERT_TRUE(tetgen.failed_operation.has_value());
  EXPECT_TRUE(tetgen.invariants.front() == "I5" || tetgen.invariants.front() == "I6") << tetgen.objection;
#endif
}

TEST(EngineCheck, TheSameOutcomeInTheChildAndInThisProcess) {
  const EnginePlan plan = random_sweep_plan("sheet.msh", corpus_mesh("sheet.msh"), 3, 12);
  const EngineLibrary library(TETCUT_ADAPTER_TETCUT);
  const PlanCheck here = check_plan_here(library, plan);
  const PlanCheck there = check_plan(adapter(TETCUT_ADAPTER_TETCUT), plan);
  EXPECT_EQ(here.run, there.run);
  EXPECT_EQ(here.tets_after, there.tets_after);
  EXPECT_EQ(here.volume_after, there.volume_after);
  EXPECT_EQ(here.min_radius_ratio, there.min_radius_ratio);
  EXPECT_EQ(here.ok(), there.ok());
}

TEST(EnginePlan, AScenarioKeepsItsCutsAndNotesWhatNoEngineInterfaceCarries) {
  const std::string path = kCorpus + "/scenarios/cylinder-cut.scn";
  const EnginePlan plan = plan_from_scenario(path);
  std::size_t expected = 0;
  for (double y : {-1.1, -0.85, -0.6, -0.35, -0.1, 0.15, 0.4, 0.65, 0.9, 1.15}) {
    expected += scenario::sweep_cuts({-1.2, y, 2}, {1.2, y, 2}, 0.15, false).size();
  }
  EXPECT_EQ(plan.operations.size(), expected);
  EXPECT_DOUBLE_EQ(plan.operations.front().diameter, 0.4);
  EXPECT_EQ(plan.mesh.tets.size(), corpus_mesh("cylinder.msh").tets.size());
  // expect unresolved, components, min_quality and hash: tetcut's own answers.
  EXPECT_EQ(plan.notes.size(), 4u);
  EXPECT_TRUE(contains(plan.notes.front(), "cylinder-cut.scn:")) << plan.notes.front();
}

TEST(EnginePlan, UndoIsRefusedWithItsLine) {
  try {
    plan_from_scenario(kCorpus + "/scenarios/cylinder-retry.scn");
    FAIL() << "a scenario with undo planned";
  } catch (const std::runtime_error& e) {
    EXPECT_TRUE(contains(e.what(), "cylinder-retry.scn:")) << e.what();
    EXPECT_TRUE(contains(e.what(), "undo")) << e.what();
  }
}

TEST(EnginePlan, ARandomSweepIsItsSeed) {
  const RawMesh mesh = corpus_mesh("sheet.msh");
  const EnginePlan a = random_sweep_plan("sheet.msh", mesh, 7, 10);
  const EnginePlan b = random_sweep_plan("sheet.msh", mesh, 7, 10);
  const EnginePlan c = random_sweep_plan("sheet.msh", mesh, 8, 10);
  ASSERT_EQ(a.operations.size(), 10u);
  for (std::size_t i = 0; i < a.operations.size(); ++i) {
    EXPECT_EQ(a.operations[i].a, b.operations[i].a);
    EXPECT_EQ(a.operations[i].name, b.operations[i].name);
  }
  EXPECT_NE(a.operations[0].a, c.operations[0].a);
}

}  // namespace
}  // namespace tetcut::harness
