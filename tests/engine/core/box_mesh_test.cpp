#include <gtest/gtest.h>

#include "test_meshes.hpp"
#include "tetcut/box_mesh.hpp"
#include "tetcut/predicates.hpp"

namespace tetcut {
namespace {

TEST(BoxMesh, HasSixTetsPerCellAllPositive) {
  const RawMesh raw = make_box_mesh(3, 2, 4);
  EXPECT_EQ(raw.tets.size(), 6u * 3 * 2 * 4);
  EXPECT_EQ(raw.positions.size(), 4u * 3 * 5);
  for (const auto& t : raw.tets)
    EXPECT_EQ(orientation(raw.positions[t[0]], raw.positions[t[1]], raw.positions[t[2]], raw.positions[t[3]]), 1);
}

TEST(BoxMesh, BuildsAsAManifoldWithTheExpectedSurface) {
  const TetMesh mesh = testing::build_or_fail(make_box_mesh(3, 2, 4, {0, 0, 0}, {3, 2, 4}));
  std::vector<FaceRef> faces;
  mesh.boundary_faces(faces);
  EXPECT_EQ(faces.size(), 2u * 2 * (3 * 2 + 2 * 4 + 3 * 4));
  EXPECT_NEAR(mesh.total_volume(), 24.0, 1e-12);
}

}  // namespace
}  // namespace tetcut
