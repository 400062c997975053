// No parameter makes a cut hang. One test per kind of extreme parameter, on the bundled
// liver, one cut at 95,100,100: the cut finishes, or it is refused up front with a message that
// names the parameter and leaves the mesh bit-identical. How fast each row runs is the
// benchmark's business (bench/cut_limits_bench.cpp, gated by ci/bench), not a test's.
#include <gtest/gtest.h>

#include <cmath>

#include "checked.hpp"
#include "refine/refine.hpp"
#include "test_meshes.hpp"
#include "tetcut/canonical_hash.hpp"
#include "tetcut/cut.hpp"
#include "tetcut/detail/local_tables.hpp"
#include "tetcut/io.hpp"

namespace tetcut {
namespace {

TetMesh load_liver() {
  ReadResult read = read_mesh(std::string(TETCUT_CORPUS_DIR) + "/meshes/liver.msh");
  if (!read.mesh) {
    ADD_FAILURE() << "cannot read liver.msh";
    return {};
  }
  return testing::build_or_fail(*read.mesh);
}

// Raw arrays, not only the hash: a rollback must restore ids, free lists' effects and all.
::testing::AssertionResult bit_identical(const TetMesh& mesh, const TetMesh& before) {
  if (mesh.tet_capacity() != before.tet_capacity() || mesh.vertex_capacity() != before.vertex_capacity())
    return ::testing::AssertionFailure() << "capacities changed";
  for (std::uint32_t t = 0; t < mesh.tet_capacity(); ++t) {
    if (mesh.raw_tets()[t] != before.raw_tets()[t]) return ::testing::AssertionFailure() << "tet " << t << " changed";
    if (mesh.is_live(TetId{t}) != before.is_live(TetId{t})) return ::testing::AssertionFailure() << "tet " << t << " liveness";
    if (mesh.is_live(TetId{t}))
      for (int f = 0; f < 4; ++f)
        if (!(mesh.neighbour(TetId{t}, f) == before.neighbour(TetId{t}, f)))
          return ::testing::AssertionFailure() << "neighbour " << f << " of tet " << t << " changed";
  }
  for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v)
    if (!(mesh.position(VertId{v}) == before.position(VertId{v})) || !(mesh.vertex_tet(VertId{v}) == before.vertex_tet(VertId{v})))
      return ::testing::AssertionFailure() << "vertex " << v << " changed";
  if (canonical_hash(mesh) != canonical_hash(before)) return ::testing::AssertionFailure() << "canonical hash changed";
  return ::testing::AssertionSuccess();
}

const Vec3 kCentre{95, 100, 100};

// Rows 1-4: a tool from half the liver's size to ten thousand times it removes what it can.
class LargeTool : public ::testing::TestWithParam<double> {};

TEST_P(LargeTool, FinishesAndLeavesAValidMesh) {
  TetMesh mesh = load_liver();
  const std::uint32_t tets = mesh.num_tets();
  Cutter cutter(mesh, {.tool_diameter = GetParam()});
  const CutReport r = cutter.cut(kCentre);
  ASSERT_TRUE(r.ok) << r.failure;
  EXPECT_GT(r.tets_hit, 0u);
  EXPECT_GT(r.tets_removed, 0u);
  EXPECT_EQ(r.refine_iterations, 0u) << "D_ref = 1.5 x diameter is above every edge of the liver";
  EXPECT_LT(mesh.num_tets(), tets);
  EXPECT_TRUE(testing::mesh_is_valid(mesh));
}

INSTANTIATE_TEST_SUITE_P(IssueTable, LargeTool, ::testing::Values(100.0, 1000.0, 1e4, 1e6), [](const auto& info) {
  return "diameter_" + std::to_string(static_cast<long long>(info.param));
});

// Row 5: D_ref = 0.08 mm, far below the liver's shortest edge: refused before any work, naming
// d_ref_factor, the mesh untouched; the same Cutter then cuts with a factor the message allows.
TEST(CutLimits, ADrefFarBelowTheShortestEdgeIsRefusedUpFrontNamingTheParameter) {
  TetMesh mesh = load_liver();
  Cutter cutter(mesh, {.tool_diameter = 8.0, .d_ref_factor = 0.01});
  const TetMesh before = mesh;
  const CutReport r = cutter.cut(kCentre);
  ASSERT_FALSE(r.ok);
  EXPECT_NE(r.failure.find("d_ref_factor"), std::string::npos) << r.failure;
  EXPECT_NE(r.failure.find("max_tets_created"), std::string::npos) << r.failure;
  EXPECT_EQ(r.tets_hit, 0u) << "refused before locating: no work done";
  EXPECT_EQ(r.edges_split, 0u);
  EXPECT_TRUE(cutter.last_created().empty());
  EXPECT_TRUE(bit_identical(mesh, before));
  // The message's suggestion is honoured: "a d_ref_factor of X or more fits".
  const std::size_t at = r.failure.find("a d_ref_factor of ");
  ASSERT_NE(at, std::string::npos) << r.failure;
  const double suggested = std::stod(r.failure.substr(at + 18));
  CutParams fits = cutter.params();
  fits.d_ref_factor = suggested;
  ASSERT_FALSE(cutter.set_params(fits).has_value());
  const CutReport ok = cutter.cut(kCentre);
  EXPECT_EQ(ok.failure.find("d_ref_factor"), std::string::npos) << ok.failure;
  EXPECT_TRUE(testing::mesh_is_valid(mesh));
}

// A loop over budget stops inside the refinement, and the Cutter rolls it back bit-identically.
// D_ref at the shortest edge: the up-front check does not apply, only the budget does.
TEST(CutLimits, ARefinementOverBudgetIsRefusedInsideTheLoopAndRolledBack) {
  TetMesh mesh = load_liver();
  const MeshScale scale = measure_scale(mesh);
  Cutter cutter(mesh, {.tool_diameter = 8.0, .d_ref_factor = 1.0001 * scale.shortest_edge / 8.0, .max_tets_created = 500});
  const TetMesh before = mesh;
  const CutReport r = cutter.cut(kCentre);
  ASSERT_FALSE(r.ok);
  EXPECT_NE(r.failure.find("max_tets_created"), std::string::npos) << r.failure;
  EXPECT_GT(r.tets_hit, 0u);
  EXPECT_TRUE(cutter.last_created().empty());
  EXPECT_TRUE(bit_identical(mesh, before));
}

TEST(CutLimits, MeshScaleIsTheShortestEdgeAndTheVolume) {
  TetMesh mesh = testing::build_or_fail(make_box_mesh(2, 3, 4, {0, 0, 0}, {1, 3, 2}));
  const MeshScale scale = measure_scale(mesh);
  EXPECT_DOUBLE_EQ(scale.shortest_edge, 0.5) << "cells of 0.5 x 1 x 0.5";
  EXPECT_NEAR(scale.volume, 6.0, 1e-12);
  // Below the shortest edge the bound applies (and grows as D_ref^-3); at or above it, not.
  EXPECT_EQ(min_tets_to_refine(scale, 0.1, 0.5), 0.0);
  EXPECT_GT(min_tets_to_refine(scale, 0.1, 0.25), 0.0);
  EXPECT_NEAR(min_tets_to_refine(scale, 0.1, 0.05) / min_tets_to_refine(scale, 0.1, 0.1), 8.0, 1e-9);
  // A tool larger than the mesh: the mesh's volume bounds what must be refined.
  EXPECT_NEAR(min_tets_to_refine(scale, 1e6, 0.25), 6.0 / (0.25 * 0.25 * 0.25 / (6.0 * std::sqrt(2.0))), 1e-6);
}

}  // namespace
}  // namespace tetcut
