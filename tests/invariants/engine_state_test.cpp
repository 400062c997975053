// I2 and I8: the engine's adjacency and bookkeeping are compared with the checker's own
// recomputation. To break exactly them we corrupt a TetMesh's private state through the
// engine's internal seam (detail::MeshInternals, aliased TetMeshTestAccess).
#include <gtest/gtest.h>

#include "test_support.hpp"
#include "tet_mesh_test_access.hpp"

namespace tetcut::invariants::testing {
namespace {

using Access = TetMeshTestAccess;

TetMesh box() { return build_or_fail(make_box_mesh(2, 2, 2)); }

// An interior face (t, f) of the box.
FaceRef interior_face(const TetMesh& mesh) {
  for (std::uint32_t t = 0; t < mesh.tet_capacity(); ++t)
    for (std::uint8_t f = 0; f < 4; ++f)
      if (mesh.neighbour(TetId{t}, f).valid()) return {TetId{t}, f};
  return {};
}

TEST(EngineState, I2ANeighbourDroppedOnOneSideIsNamedAndOnlyThat) {
  TetMesh mesh = box();
  ASSERT_TRUE(check_mesh(mesh.raw_view()).ok());
  const FaceRef face = interior_face(mesh);
  ASSERT_TRUE(face.valid());
  Access::adjacency(mesh)[face.tet.value][face.face] = TetMesh::kNoNeighbour;
  const CheckReport report = check_mesh(mesh.raw_view());
  EXPECT_EQ(names(report), "I2") << to_string(report);
  EXPECT_EQ(report.find(Invariant::kI2Adjacency)->count, 1u);
}

TEST(EngineState, I2ANeighbourWithTheWrongMirrorFaceIsNamed) {
  TetMesh mesh = box();
  const FaceRef face = interior_face(mesh);
  const FaceRef other = mesh.neighbour(face.tet, face.face);
  auto& adj = Access::adjacency(mesh)[face.tet.value][face.face];
  adj = (other.tet.value << 2) | ((other.face + 1u) & 3u);
  const CheckReport report = check_mesh(mesh.raw_view());
  EXPECT_EQ(names(report), "I2") << to_string(report);
}

TEST(EngineState, I2ABoundaryFaceGivenANeighbourIsNamed) {
  TetMesh mesh = box();
  for (std::uint32_t t = 0; t < mesh.tet_capacity(); ++t)
    for (int f = 0; f < 4; ++f)
      if (mesh.is_boundary_face(TetId{t}, f)) {
        Access::adjacency(mesh)[t][f] = ((t + 1) << 2) | 0u;
        const CheckReport report = check_mesh(mesh.raw_view());
        EXPECT_EQ(names(report), "I2") << to_string(report);
        return;
      }
  FAIL() << "no boundary face";
}

TEST(EngineState, I8ABoundaryFlagOffByOneIsNamedAndOnlyThat) {
  TetMesh mesh = box();
  ++Access::boundary_faces(mesh)[4];
  const CheckReport report = check_mesh(mesh.raw_view());
  EXPECT_EQ(names(report), "I8") << to_string(report);
  EXPECT_EQ(report.find(Invariant::kI8Bookkeeping)->vertices, std::vector<std::uint32_t>{4});
}

TEST(EngineState, I8AVertexToTetReferenceToAForeignTetIsNamed) {
  TetMesh mesh = box();
  const VertId v{0};
  for (std::uint32_t t = 0; t < mesh.tet_capacity(); ++t) {
    if (mesh.local_index(TetId{t}, v) < 0) {
      Access::vertex_tet(mesh)[v.value] = TetId{t};
      break;
    }
  }
  const CheckReport report = check_mesh(mesh.raw_view());
  EXPECT_EQ(names(report), "I8") << to_string(report);
}

TEST(EngineState, I8CountsAndAttributeSizesAreCompared) {
  TetMesh mesh = box();
  ++Access::live_tets(mesh);
  EXPECT_EQ(names(check_mesh(mesh.raw_view())), "I8");
  --Access::live_tets(mesh);
  EXPECT_TRUE(check_mesh(mesh.raw_view()).ok());
  mesh.attributes().resize(mesh.vertex_capacity() + 1);
  EXPECT_EQ(names(check_mesh(mesh.raw_view())), "I8");
}

TEST(EngineState, LocalCheckerSeesCorruptionInTheRegionOfAnOperation) {
  // A boundary tet whose removal leaves a valid mesh.
  TetId t = kNoTet;
  for (std::uint32_t c = 0; c < 48 && !t.valid(); ++c) {
    TetMesh trial = box();
    const TetId one[] = {TetId{c}};
    trial.remove_tets(one);
    if (check_mesh(trial.raw_view()).ok()) t = TetId{c};
  }
  ASSERT_TRUE(t.valid());
  TetMesh mesh = box();
  LocalChecker local(mesh.raw_view());
  const auto verts = mesh.tet(t);
  const TetId removed[] = {t};
  mesh.remove_tets(removed);
  ++Access::boundary_faces(mesh)[verts[0].value];
  const CheckReport report = local.after_operation(mesh.raw_view(), removed, {});
  EXPECT_EQ(names(report), "I8") << to_string(report);
  EXPECT_EQ(names(check_mesh(mesh.raw_view())), "I8");
}

TEST(EngineState, LocalCheckerSeesATetChangedBehindItsBack) {
  TetMesh mesh = box();
  LocalChecker local(mesh.raw_view());
  // Tet 0 and tet 1 share vertices; change tet 1 silently, then report an operation on tet 0.
  std::swap(Access::tet_verts(mesh)[1][1], Access::tet_verts(mesh)[1][2]);
  const TetId removed[] = {TetId{0}};
  mesh.remove_tets(removed);
  const CheckReport report = local.after_operation(mesh.raw_view(), removed, {});
  EXPECT_TRUE(has(report, Invariant::kI8Bookkeeping)) << to_string(report);
}

}  // namespace
}  // namespace tetcut::invariants::testing
