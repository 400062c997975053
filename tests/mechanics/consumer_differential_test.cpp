// The consumers against a rebuild after every cut (differential.hpp): every bundled
// mesh and every removal strategy, a lancet sweep, the invariant checker after each cut too;
// then the planted bugs a consumer could be fed (a corrupted copy of a cut's log) and the proof
// that the differential check catches each.
#include <gtest/gtest.h>

#include <algorithm>

#include <optional>
#include <string>
#include <tuple>

#include "../engine/checked.hpp"  // cut_check
#include "mechanics_test_support.hpp"
#include "tetcut/cut.hpp"
#include "tetcut/invariants/check.hpp"
#include "tetcut/mechanics/differential.hpp"
#include "tetcut/mechanics/tet_labels.hpp"

namespace tetcut {
namespace {

using mechanics::DifferentialCheck;

// Release: 6 cuts per sweep; under the sanitizers 3 (each cut's check is O(#T) and the brute
// location of its new tets O(#created x #T): the ASan build runs the same code ten times slower).
int sweep_cuts() { return testing::sanitized_build() ? 3 : 6; }

class ConsumerSweep : public ::testing::TestWithParam<std::tuple<std::string, RemovalStrategy>> {};

TEST_P(ConsumerSweep, IncrementalConsumersEqualARebuildAfterEveryCut) {
  const auto& [file, strategy] = GetParam();
  TetMesh mesh = testing::load_bundled(file);
  const BoundingBox box = bounding_box(mesh);
  // Tools of 0.6 and 1.5 mean edges in turn: the small one refines (D_ref = 0.9 mean edges),
  // the large one removes whole tets.
  const double edge = mesh.mean_edge_length();
  Cutter cutter(mesh, {.tool_diameter = edge, .strategy = strategy});
  int index = 0;
  DifferentialCheck check(mesh, testing::four_materials(), testing::hashed_labels(mesh));
  // The labels the command line carries (TetLabels) against the model's, which the check holds
  // to the rule's recomputation from geometry after every cut.
  mechanics::TetLabels labels(mesh, testing::hashed_labels(mesh));
  invariants::LocalChecker local(mesh.raw_view());
  std::uint32_t removed = 0, created = 0;
  for (const Vec3& centre : testing::lancet_sweep(box, sweep_cuts())) {
    check.before(mesh);
    CutParams params = cutter.params();
    params.tool_diameter = (index++ % 2 == 0 ? 0.6 : 1.5) * edge;
    ASSERT_FALSE(cutter.set_params(params));
    ChangeLog log;
    const CutReport r = cutter.cut(centre, &log);
    removed += static_cast<std::uint32_t>(log.removed.size());
    created += static_cast<std::uint32_t>(log.created.size());
    invariants::CheckOptions o;  // a refused cut changed nothing, and is held to no tool
    o.min_dihedral_deg = std::min(params.min_dihedral_deg, cutter.last_min_dihedral_held());  // the theta it held
    if (r.ok)
      o.tool = invariants::ToolRule{.centre = centre, .radius = params.tool_diameter / 2, .d_ref = params.d_ref(),
                                    .left = cutter.last_left_in_tool()};
    o.moved = cutter.last_moved();
    const invariants::CheckReport l = local.after_operation(mesh.raw_view(), cutter.last_removed(), cutter.last_created(), o);
    ASSERT_TRUE(l.ok()) << invariants::id_string(l.violations.front().id) << ": " << l.violations.front().detail;
    const auto problem = check.after(mesh, log);
    ASSERT_FALSE(problem) << *problem << " (cut at " << centre.x << "," << centre.y << "," << centre.z
                          << (r.ok ? "" : ", rolled back") << ")";
    ASSERT_EQ(labels.apply(mesh, log), 0u);
    for (std::uint32_t t = 0; t < mesh.tet_capacity(); ++t) {
      if (!mesh.is_live(TetId{t})) continue;
      ASSERT_EQ(labels.label(TetId{t}), check.model().label(TetId{t})) << "tet " << t;
    }
  }
  EXPECT_GT(removed, 0u);
  EXPECT_GT(created, 0u) << "no cut refined anything: the sweep tests only removal";
  std::printf("worst relative difference from the rebuild: %.3g (tolerance %.0e)\n", check.worst_relative_error(),
              mechanics::kDifferentialTolerance);
}

INSTANTIATE_TEST_SUITE_P(
    Bundled, ConsumerSweep,
    ::testing::Combine(::testing::Values("cylinder.msh", "sheet.msh", "liver-coarse.msh", "liver-local.msh",
                                         "liver-refined.msh", "liver.msh"),
                       ::testing::Values(RemovalStrategy::kBasic, RemovalStrategy::kNeighbours,
                                         RemovalStrategy::kCombined, RemovalStrategy::kWide)),
    [](const auto& info) { return testing::test_name_of_mesh(std::get<0>(info.param)) + "_" + to_string(std::get<1>(info.param)); });

// ---- planted bugs: a corrupted copy of the log, applied to one check; the honest log to a twin.

struct PlantedRun {
  std::optional<std::string> honest, planted;
  bool planted_something = false;
};

// Cuts along a sweep of liver-coarse; at the first cut where `corrupt` finds something to
// corrupt, the twin checks diverge: returns what each said.
template <class Corrupt>
PlantedRun run_planted(Corrupt corrupt) {
  TetMesh mesh = testing::load_bundled("liver-coarse.msh");
  const BoundingBox box = bounding_box(mesh);
  Cutter cutter(mesh, {.tool_diameter = box.diagonal() / 25});
  DifferentialCheck honest(mesh, testing::four_materials(), testing::hashed_labels(mesh));
  DifferentialCheck planted(mesh, testing::four_materials(), testing::hashed_labels(mesh));
  PlantedRun run;
  for (const Vec3& centre : testing::lancet_sweep(box, 8)) {
    honest.before(mesh);
    planted.before(mesh);
    const std::uint32_t capacity_before = mesh.tet_capacity();
    ChangeLog log;
    cutter.cut(centre, &log);
    ChangeLog bad = log;
    run.planted_something = corrupt(mesh, capacity_before, bad);
    run.honest = honest.after(mesh, log);
    run.planted = planted.after(mesh, bad);
    if (run.planted_something || run.honest) break;
  }
  return run;
}

TEST(PlantedLogBug, ADroppedRemovedTetFailsTheDifferentialCheck) {
  const PlantedRun run = run_planted([](const TetMesh&, std::uint32_t, ChangeLog& log) {
    if (log.removed.empty()) return false;
    log.removed.erase(log.removed.begin() + static_cast<std::ptrdiff_t>(log.removed.size() / 2));
    return true;
  });
  ASSERT_TRUE(run.planted_something);
  EXPECT_FALSE(run.honest) << *run.honest;
  ASSERT_TRUE(run.planted) << "the check passed a log that forgot a removed tet";
  // Caught by the comparison with the rebuild (the tet is still in the model), not only by the
  // log's own consistency.
  EXPECT_NE(run.planted->find("in the incremental model only"), std::string::npos) << *run.planted;
}

TEST(PlantedLogBug, AnIntermediateParentFailsTheDifferentialCheck) {
  const PlantedRun run = run_planted([](const TetMesh& mesh, std::uint32_t capacity_before, ChangeLog& log) {
    // Ids the cut appended and that are dead at its end: tets it made and removed or split again
    // (a transaction reuses no id, change_log.hpp), i.e. the intermediate tets.
    std::vector<TetId> intermediate;
    for (std::uint32_t t = capacity_before; t < mesh.tet_capacity(); ++t)
      if (!mesh.is_live(TetId{t})) intermediate.push_back(TetId{t});
    if (intermediate.empty()) return false;
    std::size_t k = 0, named = 0;
    for (CreatedTet& c : log.created) {
      if (c.parents_count != 1) continue;
      c.parent = log.parents[c.parents_begin] = intermediate[k++ % intermediate.size()];
      ++named;
    }
    return named > 0;
  });
  ASSERT_TRUE(run.planted_something) << "no cut of the sweep made an intermediate tet";
  EXPECT_FALSE(run.honest) << *run.honest;
  ASSERT_TRUE(run.planted) << "the check passed a log that names intermediate parents";
  // Caught by the model's own account of the log: a parent it never had, not among the removed
  // tets. (The children's labels come out right all the same: label_rule.hpp's step 2 finds the
  // removed pre-cut tet that contains each centroid.)
  EXPECT_NE(run.planted->find("parents not removed"), std::string::npos) << *run.planted;
}

TEST(PlantedLogBug, AWrongVertexOriginFailsTheDifferentialCheck) {
  const PlantedRun run = run_planted([](const TetMesh&, std::uint32_t, ChangeLog& log) {
    for (CreatedVertex& v : log.vertices) {
      if (!v.on_edge()) continue;
      v.weight[0] += 0.25;  // a point of the same edge, but not where the vertex is
      v.weight[1] -= 0.25;
      return true;
    }
    return false;
  });
  ASSERT_TRUE(run.planted_something);
  EXPECT_FALSE(run.honest) << *run.honest;
  ASSERT_TRUE(run.planted) << "the check passed a vertex interpolated from the wrong weights";
  EXPECT_NE(run.planted->find("interpolation"), std::string::npos) << *run.planted;
}

// ---- vertices there before that a cut moves (the pass smooths within the cut's reach:
// ChangeLog::moved): the consumers interpolate them too, from the values before the cut.

// A sweep of small tools (0.2 on the bundled cylinder, radius 1: about 0.4 of its median edge),
// a cut every third of the tool: its pass moves some vertices that were there before. Each cut's
// log, as given or as `corrupt` changes it, is applied to the consumers and checked against a
// rebuild, the checker's I8 holding the moves to the reach; returns the moves seen and the first
// problem.
struct MovedRun {
  std::uint32_t vertices_moved = 0, cuts_moving = 0;
  std::optional<std::string> problem;
};
template <class Corrupt>
MovedRun sweep_moving_vertices(Corrupt corrupt) {
  TetMesh mesh = testing::load_bundled("cylinder.msh");
  const double diameter = 0.2;
  Cutter cutter(mesh, {.tool_diameter = diameter});
  DifferentialCheck check(mesh, testing::four_materials(), testing::hashed_labels(mesh));
  mechanics::TetLabels labels(mesh, testing::hashed_labels(mesh));
  invariants::LocalChecker local(mesh.raw_view());
  MovedRun run;
  const Vec3 from{0, -0.8, 0.5}, to{0, 0.8, 3.5};
  const int steps = static_cast<int>(norm(to - from) / (diameter / 3));
  for (int k = 0; k <= steps && !run.problem; ++k) {
    const Vec3 centre = from + (static_cast<double>(k) / steps) * (to - from);
    check.before(mesh);
    ChangeLog log;
    const CutReport r = cutter.cut(centre, &log);
    EXPECT_TRUE(r.ok) << r.failure;
    EXPECT_EQ(r.vertices_moved, log.moved.size());
    run.vertices_moved += r.vertices_moved;
    run.cuts_moving += r.vertices_moved > 0;
    invariants::CheckOptions o = testing::cut_check(cutter, centre);
    const invariants::CheckReport l = local.after_operation(mesh.raw_view(), cutter.last_removed(), cutter.last_created(), o);
    EXPECT_TRUE(l.ok()) << invariants::to_string(l);
    corrupt(log);
    run.problem = check.after(mesh, log);
    if (!run.problem && labels.apply(mesh, log) != 0) run.problem = "labels: orphans";
    for (std::uint32_t t = 0; t < mesh.tet_capacity() && !run.problem; ++t)
      if (mesh.is_live(TetId{t}) && labels.label(TetId{t}) != check.model().label(TetId{t}))
        run.problem = "labels: tet " + std::to_string(t) + " differs from the model's";
  }
  return run;
}

TEST(MovedVertices, TheConsumersInterpolateVerticesACutMovedAndEqualARebuild) {
  const MovedRun run = sweep_moving_vertices([](ChangeLog&) {});
  EXPECT_FALSE(run.problem) << *run.problem;
  EXPECT_GT(run.vertices_moved, 0u) << "no cut moved a vertex there before: the sweep tests nothing new";
  std::printf("%u vertices there before moved by %u cuts\n", run.vertices_moved, run.cuts_moving);
}

TEST(PlantedLogBug, AMovedVertexLeftOutOfTheLogFailsTheDifferentialCheck) {
  // The moved vertex's tets are still removed and created, but its values are not interpolated:
  // the model keeps its displacement where the mesh's attributes moved on.
  const MovedRun run = sweep_moving_vertices([](ChangeLog& log) { log.moved.clear(); });
  ASSERT_TRUE(run.problem) << "the check passed a log that forgot the vertices it moved";
  EXPECT_NE(run.problem->find("interpolation"), std::string::npos) << *run.problem;
}

}  // namespace
}  // namespace tetcut
