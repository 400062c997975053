// The Smoother (engine/src/improve/smoothing.hpp) on its own: a vertex of a unit cube coned to it
// is moved to lift the worst tet of its star; an interior vertex moves in every direction, one on
// a flat face of the surface only within that face's plane, one at a corner not at all, and a
// vertex already where its star is best is refused. Each plan is read before it is applied: the
// mesh does not change until apply(), and then the star is what the plan said it would be.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <vector>

#include "checked.hpp"
#include "core/quality.hpp"
#include "improve/operation.hpp"
#include "improve/smoothing.hpp"
#include "test_meshes.hpp"
#include "tetcut/predicates.hpp"

namespace tetcut::testing {
namespace {

// The unit cube as tets coned from one point to the cube's faces, the cone point made in an open
// transaction (only such a vertex moves): built coned at `built_at`, then re-coned at `apex`.
// `faces`: the cube's faces the cone covers (0..5: -x, +x, -y, +y, -z, +z); an apex on a face of
// the cube cones to the other five, and that face's part of the surface is made of the cone's
// faces through the apex.
struct ConedCube {
  TetMesh mesh;
  VertId apex;
};

ConedCube coned_cube(const Vec3& built_at, const Vec3& apex, const std::vector<int>& faces) {
  RawMesh raw;
  for (int i = 0; i < 8; ++i) raw.positions.push_back({double(i & 1), double((i >> 1) & 1), double((i >> 2) & 1)});
  raw.positions.push_back(built_at);
  // Each face's corners in cyclic order (corner i at (i & 1, (i >> 1) & 1, (i >> 2) & 1)).
  constexpr int kFaceCorners[6][4] = {{0, 2, 6, 4}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 5, 7, 6}};
  std::vector<std::array<std::uint32_t, 3>> triangles;
  for (int f : faces) {
    const int* c = kFaceCorners[f];
    triangles.push_back({std::uint32_t(c[0]), std::uint32_t(c[1]), std::uint32_t(c[2])});
    triangles.push_back({std::uint32_t(c[0]), std::uint32_t(c[2]), std::uint32_t(c[3])});
  }
  auto positive = [&](std::array<std::uint32_t, 3> tri, std::uint32_t apex_id, const Vec3& at) {
    if (orientation(raw.positions[tri[0]], raw.positions[tri[1]], raw.positions[tri[2]], at) < 0) std::swap(tri[0], tri[1]);
    return std::array<std::uint32_t, 4>{tri[0], tri[1], tri[2], apex_id};
  };
  for (const auto& tri : triangles) raw.tets.push_back(positive(tri, 8, built_at));
  ConedCube cube{build_or_fail(raw), kNoVert};
  TetMesh& mesh = cube.mesh;
  mesh.begin_transaction();
  cube.apex = mesh.add_vertex(apex);
  std::vector<TetId> old;
  std::vector<TetMesh::TetVerts> coned;
  for (std::uint32_t t = 0; t < mesh.tet_capacity(); ++t) old.push_back(TetId{t});
  for (const auto& tri : triangles) {
    const auto q = positive(tri, 9, apex);
    coned.push_back({VertId{q[0]}, VertId{q[1]}, VertId{q[2]}, cube.apex});
  }
  mesh.replace_tets(old, coned);
  return cube;
}

const std::vector<int> kAllFaces = {0, 1, 2, 3, 4, 5};
const std::vector<int> kAllButBottom = {0, 1, 2, 3, 5};

// The worst quality of an added tet of the plan, its corners where the plan puts them: what a
// caller evaluates without applying.
double planned_worst(const TetMesh& mesh, const detail::Plan& plan) {
  double worst = 1.0;
  for (const TetMesh::TetVerts& t : plan.added_tets()) {
    const std::array<Vec3, 4> x = plan.corners(mesh, t);
    worst = std::min(worst, quality(x[0], x[1], x[2], x[3]));
  }
  return worst;
}

double star_worst(const TetMesh& mesh, VertId v) {
  std::vector<TetId> star;
  mesh.vertex_shell(v, star);
  return worst_quality(mesh, star);
}

TEST(Smoother, AnInteriorVertexMovesFreelyToLiftTheWorstTetOfItsStarAndTheMeshIsWhatThePlanSaid) {
  const Vec3 centre{0.5, 0.5, 0.5}, off{0.8, 0.62, 0.33};
  ConedCube cube = coned_cube(centre, off, kAllFaces);
  TetMesh& mesh = cube.mesh;
  const double before = star_worst(mesh, cube.apex);
  detail::Smoother smoother;
  detail::Plan plan;
  ASSERT_EQ(smoother.plan(mesh, cube.apex, 1e-6, nullptr, plan), detail::Refusal::kNone);
  EXPECT_EQ(plan.op, detail::Operator::kSmoothing);
  EXPECT_EQ(plan.placed, cube.apex);
  EXPECT_EQ(plan.worst_before, before);
  EXPECT_GT(plan.worst_after, before * 1.1) << "an apex this far off the centre has much to gain";
  // Freely: off every coordinate plane through where it was, and towards the cube's centre.
  const Vec3 step = plan.placed_at - off;
  EXPECT_NE(step.x, 0.0);
  EXPECT_NE(step.y, 0.0);
  EXPECT_NE(step.z, 0.0);
  EXPECT_LT(norm(plan.placed_at - centre), norm(off - centre));
  // Planned, not applied; and what a caller measures from the plan is its worst_after.
  EXPECT_EQ(mesh.position(cube.apex), off);
  EXPECT_EQ(plan.removed_tets().size(), 12u);
  EXPECT_EQ(plan.added_tets().size(), 12u);
  EXPECT_EQ(planned_worst(mesh, plan), plan.worst_after);

  std::vector<TetId> created;
  plan.apply(mesh, created);
  EXPECT_EQ(mesh.position(cube.apex), plan.placed_at);
  EXPECT_EQ(created.size(), 12u);
  EXPECT_EQ(star_worst(mesh, cube.apex), plan.worst_after);
  mesh.commit();
  EXPECT_TRUE(mesh_is_valid(mesh, invariants::CheckLevel::kExact, 1.0));
}

TEST(Smoother, AVertexOnAFlatFaceOfTheSurfaceMovesOnlyWithinItsPlane) {
  // On the bottom face z = 0, off its centre: every boundary face at the apex lies in z = 0.
  const Vec3 off{0.78, 0.35, 0.0};
  ConedCube cube = coned_cube({0.5, 0.5, 0.0}, off, kAllButBottom);
  TetMesh& mesh = cube.mesh;
  ASSERT_TRUE(mesh.is_boundary_vertex(cube.apex));
  const double before = star_worst(mesh, cube.apex);
  detail::Smoother smoother;
  detail::Plan plan;
  ASSERT_EQ(smoother.plan(mesh, cube.apex, 1e-6, nullptr, plan), detail::Refusal::kNone);
  EXPECT_GT(plan.worst_after, before);
  EXPECT_EQ(plan.placed_at.z, 0.0) << "the surface keeps its plane exactly";
  EXPECT_NE(plan.placed_at.x, off.x);
  EXPECT_NE(plan.placed_at.y, off.y);
  EXPECT_EQ(planned_worst(mesh, plan), plan.worst_after);
  std::vector<TetId> created;
  plan.apply(mesh, created);
  mesh.commit();
  EXPECT_TRUE(mesh_is_valid(mesh, invariants::CheckLevel::kExact, 1.0));
}

TEST(Smoother, AVertexAtACornerOfTheSurfaceDoesNotMove) {
  // The cube's corner (0, 0, 0) has boundary faces in three planes: moving it would bend the
  // surface (planned on the const mesh: the corner was there before the transaction, and a
  // plan that cannot move it is never applied).
  ConedCube cube = coned_cube({0.5, 0.5, 0.5}, {0.7, 0.6, 0.4}, kAllFaces);
  detail::Smoother smoother;
  detail::Plan plan;
  EXPECT_EQ(smoother.plan(cube.mesh, VertId{0}, 1e-6, nullptr, plan), detail::Refusal::kSurfaceConstraint);
}

TEST(Smoother, AVertexWhereItsStarIsAlreadyBestIsRefusedAsNotBetter) {
  // At the centre of the cube the twelve tets of the star are congruent: any move worsens one.
  ConedCube cube = coned_cube({0.5, 0.5, 0.5}, {0.5, 0.5, 0.5}, kAllFaces);
  TetMesh& mesh = cube.mesh;
  const TetMesh before = mesh;
  detail::Smoother smoother;
  detail::Plan plan;
  EXPECT_EQ(smoother.plan(mesh, cube.apex, 1e-6, nullptr, plan), detail::Refusal::kNotBetter);
  EXPECT_LE(plan.worst_after, plan.worst_before * (1.0 + 1e-6));
  EXPECT_TRUE(std::equal(mesh.positions().begin(), mesh.positions().end(), before.positions().begin(), before.positions().end()));
}

}  // namespace
}  // namespace tetcut::testing
