// The threading contract's run-time check (tetcut/thread_contract.hpp): a cut while another
// thread declares a read of the same mesh, and a change while another thread changes it, stop
// the process with both names; what the contract allows (readers together, nesting on one
// thread, threads taking turns, two meshes at once) runs. The overlaps are made certain, not
// hoped for: the other thread holds its scope until the death test's process has died.
#include <gtest/gtest.h>

#include <atomic>
#include <thread>
#include <vector>

#include "tetcut/box_mesh.hpp"
#include "tetcut/cut.hpp"
#include "../test_meshes.hpp"  // build_or_fail
#include "tetcut/thread_contract.hpp"

namespace tetcut {
namespace {

TetMesh box() { return testing::build_or_fail(make_box_mesh(4, 4, 4)); }

// Starts a thread that takes `Scope` on `mesh` and holds it until the process ends, and returns
// once it holds it.
template <class Scope>
void hold_on_another_thread(const TetMesh& mesh, const char* what) {
  std::atomic<bool> holding{false};
  std::thread([&mesh, &holding, what] {
    const Scope scope(mesh, what);
    holding = true;
    for (;;) std::this_thread::sleep_for(std::chrono::seconds(1));
  }).detach();
  while (!holding) std::this_thread::yield();
}

class ThreadContractDeath : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!TETCUT_THREAD_CHECKS_ON) GTEST_SKIP() << "built with TETCUT_THREAD_CHECKS=OFF: the check is compiled out";
    GTEST_FLAG_SET(death_test_style, "threadsafe");
  }
};

TEST_F(ThreadContractDeath, ACutWhileAnotherThreadReadsStopsTheProcessNamingBoth) {
  EXPECT_DEATH(
      {
        TetMesh mesh = box();
        Cutter cutter(mesh, {.tool_diameter = 0.4});
        hold_on_another_thread<MeshReadScope>(mesh, "the haptic loop's read");
        cutter.cut({0.5, 0.5, 0.5});
      },
      "threading contract violated: Cutter::cut\\(\\) while the read the haptic loop's read on another thread");
}

TEST_F(ThreadContractDeath, AReadWhileAnotherThreadCutsStopsTheProcess) {
  EXPECT_DEATH(
      {
        TetMesh mesh = box();
        hold_on_another_thread<MeshWriteScope>(mesh, "a cut elsewhere");
        const MeshReadScope reading(mesh, "the renderer's read");
      },
      "threading contract violated: the renderer's read while the change a cut elsewhere on another thread");
}

TEST_F(ThreadContractDeath, TwoChangesOfOneMeshAtOnceStopTheProcess) {
  EXPECT_DEATH(
      {
        TetMesh mesh = box();
        hold_on_another_thread<MeshWriteScope>(mesh, "another Cutter's cut");
        mesh.compact();
      },
      "threading contract violated: TetMesh::compact\\(\\) while the change another Cutter's cut");
}

TEST(ThreadContract, WhatTheContractAllowsRuns) {
  TetMesh mesh = box();
  Cutter cutter(mesh, {.tool_diameter = 0.4});
  // Readers together: eight threads, each declaring its reads a thousand times.
  std::vector<std::thread> readers;
  std::atomic<std::uint64_t> seen{0};
  for (int r = 0; r < 8; ++r)
    readers.emplace_back([&] {
      for (int k = 0; k < 1000; ++k) {
        const MeshReadScope reading(mesh, "a reader");
        seen += mesh.num_tets();
      }
    });
  for (std::thread& t : readers) t.join();
  EXPECT_EQ(seen.load(), std::uint64_t{8000} * mesh.num_tets());
  // Nesting on one thread: a read and a change inside a change, a Cutter's compact() calling the
  // mesh's.
  {
    const MeshWriteScope writing(mesh, "the caller's change");
    const MeshReadScope reading(mesh, "its own read");
    EXPECT_TRUE(cutter.cut({0.5, 0.5, 0.5}).ok);
  }
  cutter.compact();
  // Threads taking turns (a join orders them), and each thread its own mesh at the same time.
  for (int k = 0; k < 4; ++k)
    std::thread([&cutter, k] { EXPECT_TRUE(cutter.cut({0.2 + 0.2 * k, 0.3, 0.7}).ok); }).join();
  TetMesh other = box();
  Cutter other_cutter(other, {.tool_diameter = 0.4});
  const std::uint32_t mesh_before = mesh.num_tets(), other_before = other.num_tets();
  std::thread a([&] { for (int k = 0; k < 20; ++k) cutter.cut({0.05 * k, 0.5, 0.2}); });
  std::thread b([&] { for (int k = 0; k < 20; ++k) other_cutter.cut({0.05 * k, 0.5, 0.2}); });
  a.join();
  b.join();
  EXPECT_LT(mesh.num_tets(), mesh_before);
  EXPECT_LT(other.num_tets(), other_before);
}

}  // namespace
}  // namespace tetcut
