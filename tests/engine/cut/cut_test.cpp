#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <tuple>

#include "change_log_check.hpp"
#include "checked.hpp"
#include "test_meshes.hpp"
#include "tetcut/bounding_box.hpp"
#include "tetcut/canonical_hash.hpp"
#include "tetcut/cut.hpp"
#include "tetcut/io.hpp"

namespace tetcut {
namespace {

TetMesh load_corpus(const std::string& name) {
  ReadResult read = read_mesh(std::string(TETCUT_CORPUS_DIR) + "/meshes/" + name);
  if (!read.mesh) {
    ADD_FAILURE() << "cannot read " << name;
    return {};
  }
  return testing::build_or_fail(*read.mesh);
}

// The removal requests a fresh Cutter makes on `base` along `centres`.
std::uint64_t removal_requests_of_fresh_sweep(const TetMesh& base, const std::vector<Vec3>& centres, double diameter) {
  TetMesh mesh = base;
  Cutter cutter(mesh, {.tool_diameter = diameter});
  for (const Vec3& c : centres) cutter.cut(c);
  return cutter.removal_report().requested;
}

class CorpusSweep : public ::testing::TestWithParam<std::string> {};

TEST_P(CorpusSweep, EveryCutKeepsTheMeshValidAndRemovesEverythingRequested) {
  TetMesh mesh = load_corpus(GetParam());
  // A channel to follow: the change log's vertex origins must reproduce it (paper 3.2).
  const auto tag = *mesh.attributes().add_channel("tag", 1);
  for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v) mesh.attributes().value(tag, VertId{v})[0] = std::sin(v);
  const BoundingBox box = bounding_box(mesh);
  Cutter cutter(mesh, {.tool_diameter = box.diagonal() / 25});
  invariants::LocalChecker local(mesh.raw_view());
  std::uint32_t removed = 0;
  for (const Vec3& centre : testing::lancet_sweep(box, 12)) {
    const TetMesh before = mesh;
    ChangeLog log;
    const CutReport r = cutter.cut(centre, &log);
    ASSERT_TRUE(r.ok) << r.failure;
    // The log a consumer gets is the net change the checker is told about, and it replays.
    EXPECT_EQ(log.removed, cutter.last_removed());
    ASSERT_EQ(log.created.size(), cutter.last_created().size());
    for (std::size_t i = 0; i < log.created.size(); ++i) EXPECT_EQ(log.created[i].tet, cutter.last_created()[i]);
    testing::expect_log_describes(before, mesh, log);
    EXPECT_EQ(r.unresolved, 0u) << "combined must resolve every singularity";
    removed += r.tets_removed;
    const invariants::CheckReport l =
        local.after_operation(mesh.raw_view(), cutter.last_removed(), cutter.last_created(), testing::cut_check(cutter, centre));
    ASSERT_TRUE(l.ok()) << invariants::id_string(l.violations.front().id) << ": " << l.violations.front().detail;
    ASSERT_TRUE(testing::mesh_is_valid(mesh)) << "after the cut at " << centre.x << "," << centre.y << "," << centre.z;
  }
  EXPECT_GT(removed, 0u);
}

INSTANTIATE_TEST_SUITE_P(Bundled, CorpusSweep,
                         ::testing::Values("cylinder.msh", "sheet.msh", "liver-coarse.msh", "liver-refined.msh", "liver.msh"),
                         [](const auto& info) { return testing::test_name_of_mesh(info.param); });

// Every strategy, tools of 0.6 and 1.5 mean edges in turn (the small one refines and its new
// vertices are then smoothed, the large one removes whole tets): each created vertex's origin in
// the log reproduces its position and its attributes, as a consumer interpolating its own arrays
// needs (a vertex moved after the origin was recorded was found this way).
class StrategySweep : public ::testing::TestWithParam<std::tuple<std::string, RemovalStrategy>> {};

TEST_P(StrategySweep, TheLogsVertexOriginsReproduceTheirPositions) {
  const auto& [file, strategy] = GetParam();
  TetMesh mesh = load_corpus(file);
  const auto tag = *mesh.attributes().add_channel("tag", 1);
  for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v) mesh.attributes().value(tag, VertId{v})[0] = std::sin(v);
  const BoundingBox box = bounding_box(mesh);
  const double edge = mesh.mean_edge_length();
  Cutter cutter(mesh, {.tool_diameter = edge, .strategy = strategy});
  int index = 0;
  for (const Vec3& centre : testing::lancet_sweep(box, 6)) {
    CutParams params = cutter.params();
    params.tool_diameter = (index++ % 2 == 0 ? 0.6 : 1.5) * edge;
    ASSERT_FALSE(cutter.set_params(params));
    const TetMesh before = mesh;
    ChangeLog log;
    cutter.cut(centre, &log);
    testing::expect_log_describes(before, mesh, log);
    ASSERT_FALSE(::testing::Test::HasFailure()) << "the cut at " << centre.x << "," << centre.y << "," << centre.z;
  }
}

INSTANTIATE_TEST_SUITE_P(Bundled, StrategySweep,
                         ::testing::Combine(::testing::Values("cylinder.msh", "liver-coarse.msh", "liver-refined.msh"),
                                            ::testing::Values(RemovalStrategy::kBasic, RemovalStrategy::kNeighbours,
                                                              RemovalStrategy::kCombined, RemovalStrategy::kWide)),
                         [](const auto& info) {
                           return testing::test_name_of_mesh(std::get<0>(info.param)) + "_" +
                                  to_string(std::get<1>(info.param));
                         });

TEST(Cut, AToolOutsideTheMeshChangesNothing) {
  TetMesh mesh = testing::build_or_fail(make_box_mesh(4, 4, 4));
  const std::uint64_t hash = canonical_hash(mesh);
  Cutter cutter(mesh, {.tool_diameter = 0.2});
  const CutReport r = cutter.cut({3, 3, 3});
  EXPECT_TRUE(r.ok);
  EXPECT_EQ(r.tets_hit, 0u);
  EXPECT_EQ(canonical_hash(mesh), hash);
}

TEST(Cut, AToolSwallowingTheMeshLeavesAValidMesh) {
  TetMesh mesh = testing::build_or_fail(make_box_mesh(3, 3, 3));
  Cutter cutter(mesh, {.tool_diameter = 10.0});
  const CutReport r = cutter.cut({0.5, 0.5, 0.5});
  ASSERT_TRUE(r.ok) << r.failure;
  EXPECT_EQ(r.unresolved, 0u);
  EXPECT_EQ(mesh.num_tets(), 0u) << "every tet's centroid is inside the tool";
  EXPECT_EQ(r.tets_removed, 162u);
  EXPECT_EQ(r.requested, 162u);
  EXPECT_EQ(cutter.last_removed().size(), 162u);
  EXPECT_TRUE(testing::mesh_is_valid(mesh));
}

TEST(Cut, AToolHoldingAllButOneTetRemovesThemOneByOne) {
  // The whole-mesh shortcut applies only when every tet is selected.
  TetMesh mesh = testing::build_or_fail(make_box_mesh(3, 3, 3));
  Cutter cutter(mesh, {.tool_diameter = 2.6});  // radius 1.3 from a corner of the unit box: the far corner stays
  const CutReport r = cutter.cut({0.0, 0.0, 0.0});
  ASSERT_TRUE(r.ok) << r.failure;
  EXPECT_GT(mesh.num_tets(), 0u);
  EXPECT_GT(r.requests, 0u);
  EXPECT_TRUE(testing::mesh_is_valid(mesh));
}

TEST(Cut, InvalidParametersAreRefusedWithAMessage) {
  TetMesh mesh = testing::build_or_fail(make_box_mesh(2, 2, 2));
  Cutter cutter(mesh, {});
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const CutParams& bad : {CutParams{.tool_diameter = 0}, CutParams{.tool_diameter = -1}, CutParams{.tool_diameter = nan},
                               CutParams{.d_ref_factor = 0}, CutParams{.p = 1.0}, CutParams{.p = nan},
                               CutParams{.search_depth = 0}, CutParams{.max_refine_iterations = 0}}) {
    const auto message = cutter.set_params(bad);
    ASSERT_TRUE(message.has_value());
    EXPECT_FALSE(message->empty());
  }
  EXPECT_EQ(cutter.params().tool_diameter, 1.0) << "a refused change keeps the old parameters";
}

TEST(Cut, AFailedCutLeavesTheMeshBitIdentical) {
  TetMesh mesh = load_corpus("liver-coarse.msh");
  const BoundingBox box = bounding_box(mesh);
  Cutter cutter(mesh, {.tool_diameter = box.diagonal() / 30});
  // A first cut so that the free lists are in use.
  ASSERT_TRUE(cutter.cut(0.5 * (box.lo + box.hi)).ok);
  const TetMesh before = mesh;
  CutParams tight = cutter.params();
  tight.max_tets_created = 1;  // any refinement now exceeds the budget
  ASSERT_FALSE(cutter.set_params(tight).has_value());
  const Vec3 elsewhere = box.lo + 0.3 * (box.hi - box.lo);
  const CutReport r = cutter.cut(elsewhere);
  ASSERT_FALSE(r.ok);
  EXPECT_FALSE(r.failure.empty());
  ASSERT_EQ(mesh.tet_capacity(), before.tet_capacity());
  ASSERT_EQ(mesh.vertex_capacity(), before.vertex_capacity());
  for (std::uint32_t t = 0; t < mesh.tet_capacity(); ++t) {
    ASSERT_EQ(mesh.raw_tets()[t], before.raw_tets()[t]);
    if (mesh.is_live(TetId{t})) {
      for (int f = 0; f < 4; ++f) ASSERT_EQ(mesh.neighbour(TetId{t}, f), before.neighbour(TetId{t}, f));
    }
  }
  for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v) {
    ASSERT_EQ(mesh.position(VertId{v}), before.position(VertId{v}));
    ASSERT_EQ(mesh.vertex_tet(VertId{v}), before.vertex_tet(VertId{v}));
  }
  // And the cutter still works afterwards.
  tight.max_tets_created = 200000;
  ASSERT_FALSE(cutter.set_params(tight).has_value());
  EXPECT_TRUE(cutter.cut(elsewhere).ok);
  EXPECT_TRUE(testing::mesh_is_valid(mesh));
}

TEST(Cut, TheSameSweepGivesTheSameHash) {
  auto run = [] {
    TetMesh mesh = load_corpus("liver-coarse.msh");
    const BoundingBox box = bounding_box(mesh);
    Cutter cutter(mesh, {.tool_diameter = box.diagonal() / 25});
    for (const Vec3& c : testing::lancet_sweep(box, 8)) cutter.cut(c);
    return canonical_hash(mesh);
  };
  EXPECT_EQ(run(), run());
}

// A Cutter reset onto another mesh (assigned into the one it holds: a fuzzer's next input)
// cuts exactly as a Cutter built on that mesh does, and so does one whose mesh was compacted
// through it: the index never keeps ids of the old mesh.
TEST(Cut, AResetCutterCutsAsAFreshOne) {
  const TetMesh liver = load_corpus("liver-coarse.msh");
  const TetMesh cylinder = load_corpus("cylinder.msh");
  auto sweep_of = [](const TetMesh& m) {
    const BoundingBox box = bounding_box(m);
    return std::make_pair(testing::lancet_sweep(box, 6), box.diagonal() / 20);
  };
  auto fresh = [&](const TetMesh& base) {
    TetMesh mesh = base;
    const auto [centres, diameter] = sweep_of(base);
    Cutter cutter(mesh, {.tool_diameter = diameter});
    std::uint32_t removed = 0;
    for (const Vec3& c : centres) removed += cutter.cut(c).tets_removed;
    return std::make_pair(canonical_hash(mesh), removed);
  };

  TetMesh mesh = liver;
  auto [liver_centres, liver_diameter] = sweep_of(liver);
  Cutter cutter(mesh, {.tool_diameter = liver_diameter});
  for (const Vec3& c : liver_centres) cutter.cut(c);
  EXPECT_EQ(canonical_hash(mesh), fresh(liver).first);

  mesh = cylinder;  // the next case, into the same object
  cutter.reset();
  const auto [cylinder_centres, cylinder_diameter] = sweep_of(cylinder);
  ASSERT_FALSE(cutter.set_params({.tool_diameter = cylinder_diameter}).has_value());
  std::uint32_t removed = 0;
  for (const Vec3& c : cylinder_centres) removed += cutter.cut(c).tets_removed;
  EXPECT_GT(removed, 0u);
  EXPECT_EQ(std::make_pair(canonical_hash(mesh), removed), fresh(cylinder));
  EXPECT_EQ(cutter.removal_report().requested, removal_requests_of_fresh_sweep(cylinder, cylinder_centres, cylinder_diameter));
  EXPECT_TRUE(testing::mesh_is_valid(mesh));

  // Compacted through the Cutter, then cut again: valid, and as a fresh Cutter on the compacted mesh.
  const std::uint32_t capacity_before = mesh.tet_capacity(), live = mesh.num_tets();
  ASSERT_GT(capacity_before, live) << "the sweep left tombstones to compact";
  const Renumbering map = cutter.compact();
  EXPECT_EQ(map.tet_old_to_new.size(), capacity_before);
  EXPECT_EQ(mesh.tet_capacity(), live);
  const TetMesh compacted = mesh;
  const Vec3 again = cylinder_centres.front();
  const CutReport r = cutter.cut(again);
  ASSERT_TRUE(r.ok) << r.failure;
  TetMesh reference = compacted;
  Cutter reference_cutter(reference, {.tool_diameter = cylinder_diameter});
  reference_cutter.cut(again);
  EXPECT_EQ(canonical_hash(mesh), canonical_hash(reference));
  EXPECT_TRUE(testing::mesh_is_valid(mesh));
}

}  // namespace
}  // namespace tetcut
