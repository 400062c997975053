#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "test_meshes.hpp"
#include "tetcut/mesh_builder.hpp"

namespace tetcut {
namespace {

bool has_problem(const BuildResult& r, BuildProblemKind kind, std::uint32_t vertex_or_tet, bool is_vertex) {
  return std::any_of(r.problems.begin(), r.problems.end(), [&](const BuildProblem& p) {
    if (p.kind != kind) return false;
    const auto& ids = is_vertex ? p.vertices : p.tets;
    return std::find(ids.begin(), ids.end(), vertex_or_tet) != ids.end();
  });
}

// Two unit-corner tets glued at one vertex (vertex 0 shared): a vertex singularity (paper Fig. 1).
RawMesh two_tets_sharing_a_vertex() {
  return {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-1, 0, 0}, {0, -1, 0}, {0, 0, -1}},
          {{0, 1, 2, 3}, {0, 4, 6, 5}}};
}

// Two tets glued along edge (0, 1) only: an edge singularity (paper Fig. 1).
RawMesh two_tets_sharing_an_edge() {
  return {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, -1, 0}, {0, 0, -1}}, {{0, 1, 2, 3}, {0, 1, 4, 5}}};
}

TEST(MeshBuilder, AcceptsAValidMesh) {
  const BuildResult r = build_mesh(make_box_mesh(2, 2, 2));
  ASSERT_TRUE(r.ok());
  EXPECT_TRUE(r.problems.empty());
  EXPECT_EQ(r.mesh->num_tets(), 48u);
  EXPECT_EQ(r.mesh->num_vertices(), 27u);
}

TEST(MeshBuilder, ReportsADanglingReferenceWithTheTet) {
  RawMesh raw = testing::single_tet();
  raw.tets.push_back({0, 1, 2, 9});
  const BuildResult r = build_mesh(raw);
  EXPECT_FALSE(r.ok());
  EXPECT_TRUE(has_problem(r, BuildProblemKind::kDanglingReference, 1, false));
  EXPECT_TRUE(has_problem(r, BuildProblemKind::kDanglingReference, 9, true));
}

TEST(MeshBuilder, ReportsARepeatedVertex) {
  RawMesh raw = testing::single_tet();
  raw.tets.push_back({0, 1, 1, 3});
  const BuildResult r = build_mesh(raw);
  EXPECT_TRUE(has_problem(r, BuildProblemKind::kRepeatedVertex, 1, false));
}

TEST(MeshBuilder, ReportsADuplicateTetEvenWithPermutedVertices) {
  RawMesh raw = testing::single_tet();
  raw.tets.push_back({1, 0, 3, 2});  // same set, even permutation
  const BuildResult r = build_mesh(raw);
  EXPECT_TRUE(has_problem(r, BuildProblemKind::kDuplicateTet, 1, false));
}

TEST(MeshBuilder, ReportsAFaceSharedByThreeTets) {
  // Three tets on face (0, 1, 2): apexes above, below and far above (overlapping, but
  // combinatorially the point is the face count).
  RawMesh raw{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, -1}, {0.1, 0.1, 2}}, {{0, 1, 2, 3}, {0, 2, 1, 4}, {0, 1, 2, 5}}};
  const BuildResult r = build_mesh(raw);
  ASSERT_TRUE(std::any_of(r.problems.begin(), r.problems.end(),
                          [](const BuildProblem& p) { return p.kind == BuildProblemKind::kOverSharedFace && p.tets.size() == 3; }));
}

TEST(MeshBuilder, RefusesInvertedTetsUnlessAskedToReorient) {
  RawMesh raw = make_box_mesh(1, 1, 1);
  std::swap(raw.tets[2][0], raw.tets[2][1]);
  const BuildResult refused = build_mesh(raw);
  EXPECT_TRUE(has_problem(refused, BuildProblemKind::kInvertedTet, 2, false));
  EXPECT_FALSE(refused.ok());

  const BuildResult fixed = build_mesh(raw, {.reorient_inverted = true});
  ASSERT_TRUE(fixed.ok());
  EXPECT_EQ(fixed.reoriented, 1u);
  EXPECT_NEAR(fixed.mesh->total_volume(), 1.0, 1e-12);
}

TEST(MeshBuilder, ReportsAFlatTet) {
  RawMesh raw{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}}, {{0, 1, 2, 3}}};
  const BuildResult r = build_mesh(raw);
  EXPECT_TRUE(has_problem(r, BuildProblemKind::kFlatTet, 0, false));
}

TEST(MeshBuilder, ReportsNonFinitePositions) {
  RawMesh raw = testing::single_tet();
  raw.positions[2].y = std::numeric_limits<double>::quiet_NaN();
  const BuildResult r = build_mesh(raw);
  EXPECT_TRUE(has_problem(r, BuildProblemKind::kNonFinitePosition, 2, true));
}

TEST(MeshBuilder, ReportsAVertexSingularity) {
  const BuildResult r = build_mesh(two_tets_sharing_a_vertex());
  EXPECT_TRUE(has_problem(r, BuildProblemKind::kSingularVertex, 0, true));
  EXPECT_FALSE(r.ok());
  EXPECT_TRUE(build_mesh(two_tets_sharing_a_vertex(), {.require_manifold = false}).ok());
}

TEST(MeshBuilder, ReportsAnEdgeSingularity) {
  const BuildResult r = build_mesh(two_tets_sharing_an_edge());
  EXPECT_TRUE(std::any_of(r.problems.begin(), r.problems.end(), [](const BuildProblem& p) {
    return p.kind == BuildProblemKind::kSingularEdge && p.vertices == std::vector<std::uint32_t>{0, 1};
  }));
}

TEST(MeshBuilder, ReportsAPinchedLinkWhoseShellIsConnected) {
  // In a 2x2x2 box the centre vertex (13) has a sphere as link. Removing the tets around its two
  // vertical edges cuts two polar caps off that sphere: the shell stays connected but the link
  // is an annulus (a tunnel pinched at the vertex).
  RawMesh raw = make_box_mesh(2, 2, 2);
  const std::uint32_t centre = 13, above = 22, below = 4;
  std::vector<std::array<std::uint32_t, 4>> kept;
  for (const auto& t : raw.tets) {
    const bool has_centre = std::find(t.begin(), t.end(), centre) != t.end();
    const bool on_axis = std::find(t.begin(), t.end(), above) != t.end() || std::find(t.begin(), t.end(), below) != t.end();
    if (!(has_centre && on_axis)) kept.push_back(t);
  }
  raw.tets = kept;
  const BuildResult r = build_mesh(raw);
  ASSERT_TRUE(std::any_of(r.problems.begin(), r.problems.end(), [&](const BuildProblem& p) {
    return p.kind == BuildProblemKind::kSingularVertex && p.vertices == std::vector<std::uint32_t>{centre} &&
           p.message.find("Euler characteristic 0") != std::string::npos;
  }));
}

TEST(MeshBuilder, ReportsEveryProblemNotOnlyTheFirst) {
  RawMesh raw = make_box_mesh(2, 1, 1);
  std::swap(raw.tets[0][0], raw.tets[0][1]);
  std::swap(raw.tets[7][0], raw.tets[7][1]);
  raw.tets.push_back({0, 1, 2, 99});
  const BuildResult r = build_mesh(raw);
  EXPECT_TRUE(has_problem(r, BuildProblemKind::kInvertedTet, 0, false));
  EXPECT_TRUE(has_problem(r, BuildProblemKind::kInvertedTet, 7, false));
  EXPECT_TRUE(has_problem(r, BuildProblemKind::kDanglingReference, 12, false));
}

TEST(MeshBuilder, KeepsUnreferencedVerticesAsDeadIds) {
  RawMesh raw = testing::single_tet();
  raw.positions.push_back({5, 5, 5});
  const TetMesh mesh = testing::build_or_fail(raw);
  EXPECT_EQ(mesh.num_vertices(), 4u);
  EXPECT_FALSE(mesh.is_live(VertId{4}));
  EXPECT_EQ(mesh.vertex_capacity(), 5u);
}

}  // namespace
}  // namespace tetcut
