// Random removal sequences, as a cautery meets the surface: the local checker after every single
// request, the full checker every few dozen; every request removed (combined, basic, wide);
// the statistics of the paper's Tables 1 and 2, deterministic. The wide strategy hollows a mesh
// down to nothing. Combined and basic refine (3.4, 3.7, the fallback), and a cautery that keeps
// meeting the small tets they make keeps the mesh alive: their runs are bounded by a number of
// requests instead.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "removal_test_support.hpp"
#include "tetcut/canonical_hash.hpp"
#include "tetcut/io.hpp"

namespace tetcut::testing {
namespace {

struct RunOutcome {
  RemovalReport report;
  std::uint64_t hash = 0;
  std::uint32_t tets_left = 0;
};

// Requests boundary tets at random until the mesh is empty (or `max_requests`), checking after
// each one. Stops early on a checker failure.
RunOutcome hollow_out(TetMesh& mesh, RemovalStrategy strategy, std::uint64_t seed, int full_every,
                      std::uint64_t max_requests = 0) {
  // Every request removes at least one tet unless it is left unresolved, and each unresolved
  // tet is met again at most a few times before the picker moves on: bound the loop anyway.
  if (max_requests == 0) max_requests = 20ull * mesh.num_tets() + 100;
  invariants::LocalChecker local(mesh.raw_view());
  Remover remover({.strategy = strategy});
  BoundaryTetPicker picker(mesh, seed);
  std::uint64_t n = 0;
  for (TetId t = picker.pick(mesh); t.valid() && n < max_requests; t = picker.pick(mesh), ++n) {
    const auto ok = remove_checked(remover, mesh, t, local);
    EXPECT_TRUE(ok) << "request " << n;
    if (!ok) break;
    picker.add(remover.last_exposed());
    if (full_every > 0 && n % full_every == 0) {
      const auto full = mesh_is_valid(mesh);
      EXPECT_TRUE(full) << "request " << n;
      if (!full) break;
    }
  }
  EXPECT_TRUE(mesh_is_valid(mesh));
  return {remover.report(), canonical_hash(mesh), mesh.num_tets()};
}

void print_table(const std::string& name, RemovalStrategy strategy, const RemovalReport& r) {
  const double req = r.requested ? double(r.requested) : 1.0;
  const double vs = r.vertex_singularities ? double(r.vertex_singularities) : 1.0;
  const double es = r.edge_singularities ? double(r.edge_singularities) : 1.0;
  std::printf(
      "[stats] %-14s %-10s requests %6llu  direct %5.1f%%  vertex %5.1f%%  edge %4.1f%%  "
      "neighbours solve %5.1f%% of vertex, %5.1f%% of edge (card %.2f / %.2f)  refined %llu "
      "(optimized %llu, undone %llu)  fallback %llu  unresolved %llu  mean cardinality %.3f  created %llu\n",
      name.c_str(), to_string(strategy), (unsigned long long)r.requested, 100.0 * r.direct / req,
      100.0 * r.vertex_singularities / req, 100.0 * r.edge_singularities / req,
      100.0 * r.vertex_resolved_by_neighbours / vs, 100.0 * r.edge_resolved_by_neighbours / es,
      r.vertex_resolved_by_neighbours ? double(r.vertex_neighbour_set_tets) / r.vertex_resolved_by_neighbours : 0.0,
      r.edge_resolved_by_neighbours ? double(r.edge_neighbour_set_tets) / r.edge_resolved_by_neighbours : 0.0,
      (unsigned long long)r.resolved_by_refinement, (unsigned long long)r.resolved_by_optimized_refinement,
      (unsigned long long)r.attempts_undone, (unsigned long long)r.resolved_by_fallback, (unsigned long long)r.unresolved, r.mean_cardinality(),
      (unsigned long long)r.tets_created);
}

void expect_everything_removed(const RunOutcome& run) {
  EXPECT_EQ(run.tets_left, 0u);
  EXPECT_EQ(run.report.unresolved, 0u);
  EXPECT_EQ(run.report.removed, run.report.requested);
  EXPECT_EQ(run.report.direct + run.report.resolved_by_neighbours + run.report.resolved_by_refinement +
                run.report.resolved_by_fallback,
            run.report.removed);
  EXPECT_EQ(run.report.direct + run.report.vertex_singularities + run.report.edge_singularities,
            run.report.requested);
}

void expect_every_request_resolved(const RunOutcome& run) {
  EXPECT_EQ(run.report.unresolved, 0u);
  EXPECT_EQ(run.report.removed, run.report.requested);
  EXPECT_EQ(run.report.direct + run.report.resolved_by_neighbours + run.report.resolved_by_refinement +
                run.report.resolved_by_fallback,
            run.report.removed);
}

TEST(RandomRemoval, CombinedResolvesEveryRequest) {
  for (std::uint64_t seed : {1ull, 2ull, 3ull}) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    TetMesh mesh = box(4, 4, 3);
    const RunOutcome run = hollow_out(mesh, RemovalStrategy::kCombined, seed, 25, 400);
    ASSERT_NO_FATAL_FAILURE(expect_every_request_resolved(run));
    EXPECT_GT(run.report.resolved_by_neighbours, 0u);
    print_table("box 4x4x3", RemovalStrategy::kCombined, run.report);
  }
}

TEST(RandomRemoval, WideHollowsBoxesOutCompletely) {
  for (std::uint64_t seed : {1ull, 2ull}) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    TetMesh mesh = box(4, 4, 3);
    const RunOutcome run = hollow_out(mesh, RemovalStrategy::kWide, seed, 25);
    ASSERT_NO_FATAL_FAILURE(expect_everything_removed(run));
    print_table("box 4x4x3", RemovalStrategy::kWide, run.report);
  }
}

TEST(RandomRemoval, BasicResolvesEveryRequest) {
  // Basic refines at every singularity, and the cautery then meets the small tets it made:
  // the mesh grows (paper 3.4), so the run is bounded by a number of requests, not emptiness.
  for (std::uint64_t seed : {1ull, 2ull, 3ull}) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    TetMesh mesh = box(4, 4, 3);
    const RunOutcome run = hollow_out(mesh, RemovalStrategy::kBasic, seed, 25, 400);
    EXPECT_EQ(run.report.unresolved, 0u);
    EXPECT_EQ(run.report.removed, run.report.requested);
    EXPECT_EQ(run.report.resolved_by_neighbours, 0u);
    print_table("box 4x4x3", RemovalStrategy::kBasic, run.report);
  }
}

TEST(RandomRemoval, NeighboursAloneNeverBreaksTheMesh) {
  // It may leave tets it cannot resolve; the picker then meets them again (counted once).
  TetMesh mesh = box(5, 5, 3);
  const RunOutcome run = hollow_out(mesh, RemovalStrategy::kNeighbours, 5, 25, 600);
  EXPECT_GT(run.report.resolved_by_neighbours, 0u);
  EXPECT_EQ(run.report.resolved_by_refinement, 0u);
  EXPECT_EQ(run.report.tets_created, 0u);
}

class CorpusRemoval : public ::testing::TestWithParam<const char*> {};

TEST_P(CorpusRemoval, WideHollowsTheMeshOutCompletely) {
  const std::string path = std::string(TETCUT_CORPUS_DIR) + "/meshes/" + GetParam();
  ReadResult read = read_mesh(path);
  if (!read.mesh) GTEST_SKIP() << "no " << path;
  TetMesh mesh = build_or_fail(*read.mesh);
  ASSERT_GT(mesh.num_tets(), 0u);
  const int full_every = mesh.num_tets() > 10000 ? 200 : 60;
  const RunOutcome run = hollow_out(mesh, RemovalStrategy::kWide, 2002, full_every);
  expect_everything_removed(run);
  print_table(GetParam(), RemovalStrategy::kWide, run.report);
}

TEST_P(CorpusRemoval, CombinedResolvesEveryRequest) {
  const std::string path = std::string(TETCUT_CORPUS_DIR) + "/meshes/" + GetParam();
  ReadResult read = read_mesh(path);
  if (!read.mesh) GTEST_SKIP() << "no " << path;
  TetMesh mesh = build_or_fail(*read.mesh);
  const RunOutcome run = hollow_out(mesh, RemovalStrategy::kCombined, 2002, 200, 1500);
  expect_every_request_resolved(run);
  print_table(GetParam(), RemovalStrategy::kCombined, run.report);
}

INSTANTIATE_TEST_SUITE_P(Bundled, CorpusRemoval,
                         ::testing::Values("cylinder.msh", "sheet.msh", "liver-coarse.msh",
                                           "liver-refined.msh", "liver.msh"),
                         [](const auto& info) { return test_name_of_mesh(info.param); });

TEST(RandomRemoval, StatisticsAndResultAreDeterministic) {
  const std::string path = std::string(TETCUT_CORPUS_DIR) + "/meshes/cylinder.msh";
  ReadResult read = read_mesh(path);
  const RawMesh raw = read.mesh ? *read.mesh : make_box_mesh(4, 4, 4);
  TetMesh a = build_or_fail(raw), b = build_or_fail(raw);
  const RunOutcome ra = hollow_out(a, RemovalStrategy::kCombined, 99, 0, 1500);
  const RunOutcome rb = hollow_out(b, RemovalStrategy::kCombined, 99, 0, 1500);
  EXPECT_EQ(ra.report, rb.report);
  EXPECT_EQ(ra.hash, rb.hash);
  EXPECT_EQ(ra.tets_left, rb.tets_left);
  EXPECT_GT(ra.report.vertex_singularities, 0u);
}

}  // namespace
}  // namespace tetcut::testing
