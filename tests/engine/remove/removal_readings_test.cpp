// The paper's removal readings side by side (cut_strategies.hpp): the orders of T_removal
// (direct-first, surface-first-by-id, revisit) and the two readings of 3.5 (the smallest
// removable set, or the first). Each must remove every selected tet and keep the mesh valid; the
// revisit order must count a tet it meets again once; 3.5's first set is never smaller than the
// smallest and is the search's first removable candidate.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "remove/neighbour_search.hpp"
#include "removal_test_support.hpp"
#include "tetcut/canonical_hash.hpp"
#include "tetcut/cut.hpp"
#include "tetcut/io.hpp"

namespace tetcut::testing {
namespace {

TEST(RemovalReadings, OrderNamesSayWhatTheyDoAndTheOldNameStillParses) {
  EXPECT_STREQ(to_string(RemovalOrder::kDirectFirst), "direct-first");
  EXPECT_STREQ(to_string(RemovalOrder::kSurfaceFirstById), "surface-first-by-id");
  EXPECT_STREQ(to_string(RemovalOrder::kRevisit), "revisit");
  EXPECT_EQ(parse_removal_order("paper"), RemovalOrder::kSurfaceFirstById);
  EXPECT_EQ(parse_removal_order("surface-first-by-id"), RemovalOrder::kSurfaceFirstById);
  EXPECT_EQ(parse_removal_order("revisit"), RemovalOrder::kRevisit);
  EXPECT_EQ(parse_removal_order("direct-first"), RemovalOrder::kDirectFirst);
  EXPECT_FALSE(parse_removal_order("random").has_value());
  EXPECT_EQ(parse_neighbour_set_choice("smallest"), NeighbourSetChoice::kSmallest);
  EXPECT_EQ(parse_neighbour_set_choice("first"), NeighbourSetChoice::kFirst);
  EXPECT_STREQ(to_string(NeighbourSetChoice::kFirst), "first");
  EXPECT_FALSE(parse_neighbour_set_choice("largest").has_value());
  EXPECT_EQ(CutParams{}.order, RemovalOrder::kDirectFirst);
  EXPECT_EQ(CutParams{}.neighbour_set, NeighbourSetChoice::kSmallest);
}

struct SweepOutcome {
  std::uint64_t hash = 0;
  RemovalReport report;
};

// The coarse liver's paper scenario (an 8 mm tool every 4 mm, 1,833 cuts; about 0.2 s in
// Release), the improvement pass off (the paper's algorithm alone), with the given reading. Every cut must succeed, leave nothing unresolved
// and keep the mesh valid.
SweepOutcome liver_sweep(RemovalOrder order, NeighbourSetChoice set) {
  ReadResult read = read_mesh(std::string(TETCUT_CORPUS_DIR) + "/meshes/liver-coarse.msh");
  EXPECT_TRUE(read.mesh.has_value());
  if (!read.mesh) return {};
  TetMesh mesh = build_or_fail(*read.mesh);
  CutParams params{.tool_diameter = 8.0};
  params.improve = false;
  params.order = order;
  params.neighbour_set = set;
  Cutter cutter(mesh, params);
  for (double z = 10; z <= 200; z += 5)  // corpus/scenarios/paper/liver-coarse.scn
    for (double y = 15; y <= 200; y += 4) {
      const CutReport r = cutter.cut({95, y, z});
      EXPECT_TRUE(r.ok) << to_string(order) << "/" << to_string(set) << " cut at " << y << "," << z << ": " << r.failure;
      EXPECT_EQ(r.unresolved, 0u) << to_string(order) << "/" << to_string(set) << " cut at " << y << "," << z;
    }
  EXPECT_TRUE(mesh_is_valid(mesh)) << to_string(order) << "/" << to_string(set);
  const RemovalReport& r = cutter.removal_report();
  std::printf("[%s, %s] %llu requested, %llu vertex / %llu edge singularities, %llu by neighbours, %llu met again\n",
              to_string(order), to_string(set), (unsigned long long)r.requested, (unsigned long long)r.vertex_singularities,
              (unsigned long long)r.edge_singularities, (unsigned long long)r.resolved_by_neighbours,
              (unsigned long long)r.repeated_requests);
  return {canonical_hash(mesh), cutter.removal_report()};
}

TEST(RemovalReadings, EveryReadingRemovesTheToolsTissueAndEachIsItsOwn) {
  const SweepOutcome base = liver_sweep(RemovalOrder::kDirectFirst, NeighbourSetChoice::kSmallest);
  ASSERT_GT(base.report.removed, 0u);
  ASSERT_GT(base.report.vertex_singularities, 0u);
  for (RemovalOrder order : {RemovalOrder::kSurfaceFirstById, RemovalOrder::kRevisit}) {
    const SweepOutcome o = liver_sweep(order, NeighbourSetChoice::kSmallest);
    EXPECT_NE(o.hash, base.hash) << to_string(order) << " removes as direct-first does: not wired?";
  }
  const SweepOutcome first = liver_sweep(RemovalOrder::kDirectFirst, NeighbourSetChoice::kFirst);
  EXPECT_NE(first.hash, base.hash) << "3.5's first set removes as its smallest does: not wired?";
  // The same reading twice: the same mesh (determinism).
  EXPECT_EQ(liver_sweep(RemovalOrder::kRevisit, NeighbourSetChoice::kFirst).hash,
            liver_sweep(RemovalOrder::kRevisit, NeighbourSetChoice::kFirst).hash);
}

TEST(RemovalReadings, TheRevisitOrderMeetsTetsAgainAndCountsEachOnceByItsFirstVerdict) {
  const RemovalReport r = liver_sweep(RemovalOrder::kRevisit, NeighbourSetChoice::kSmallest).report;
  EXPECT_GT(r.repeated_requests, 0u) << "no tet was put off and met again";
  // Each distinct tet has one first verdict: removable, vertex or edge singular.
  EXPECT_EQ(r.requested, r.direct + r.vertex_singularities + r.edge_singularities);
  EXPECT_EQ(r.surface_requested, r.surface_direct + r.surface_vertex_singularities + r.surface_edge_singularities);
  EXPECT_EQ(r.unresolved, 0u);
  // surface-first-by-id meets no tet twice: every request is the tet's first.
  const RemovalReport s = liver_sweep(RemovalOrder::kSurfaceFirstById, NeighbourSetChoice::kSmallest).report;
  EXPECT_EQ(s.repeated_requests, 0u);
}

// On every vertex-singular tet of hand-made cones (removal_test_support.hpp): 3.5's first set is found exactly when its smallest is, is
// removable, holds T, is no smaller; and is the shortest path itself whenever that is removable.
TEST(RemovalReadings, ThePapersFirstSetIsFoundWhenTheSmallestIsAndIsNoSmaller) {
  int tested = 0, larger = 0;
  for (std::uint32_t n : {4u, 6u, 8u}) {
    {
      const TetMesh mesh = build_or_fail(cone_over_grid(n));
      SetRemovalWorkspace ws;
      detail::NeighbourSearch search;
      std::vector<TetId> smallest, first, path;
      for (std::uint32_t i = 0; i < mesh.tet_capacity(); ++i) {
        const TetId t{i};
        const Removability verdict = removability(mesh, t);
        if (verdict.kind != SingularityKind::kVertex) continue;
        ++tested;
        const bool found_smallest = search.find(mesh, ws, t, verdict, 10, 64, smallest, false);
        const bool found_first = search.find(mesh, ws, t, verdict, 10, 64, first, true);
        ASSERT_EQ(found_first, found_smallest) << "tet " << i;
        if (!found_first) continue;
        EXPECT_TRUE(std::find(first.begin(), first.end(), t) != first.end());
        EXPECT_TRUE(ws.check(mesh, first).removable());
        EXPECT_TRUE(still_valid_without(mesh, first)) << "tet " << i;
        EXPECT_GE(first.size(), smallest.size()) << "tet " << i;
        larger += first.size() > smallest.size() ? 1 : 0;
        path.clear();
        ASSERT_TRUE(detail::shortest_path_to_border(mesh, ws, t, verdict.vertex, 10, path));
        path.insert(path.begin(), t);
        if (ws.check(mesh, path).removable()) {
          EXPECT_EQ(first, path) << "tet " << i;
        }
      }
    }
  }
  EXPECT_GT(tested, 20);
  std::printf("[3.5] %d vertex singularities, %d where the first removable set is larger than the smallest\n",
              tested, larger);
}

}  // namespace
}  // namespace tetcut::testing
