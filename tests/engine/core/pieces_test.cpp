// Face-connected pieces: a box is one; removing a slab of tets across it makes two.
#include <gtest/gtest.h>

#include "core/pieces.hpp"
#include "tetcut/box_mesh.hpp"
#include "tetcut/mesh_builder.hpp"

namespace tetcut {
namespace {

TEST(Pieces, ABoxIsOnePieceAndDeadIdsBelongToNone) {
  BuildResult built = build_mesh(make_box_mesh(3, 1, 1));
  ASSERT_TRUE(built.ok());
  const Pieces p = face_connected_pieces(*built.mesh);
  EXPECT_EQ(p.count, 1u);
  ASSERT_EQ(p.of_tet.size(), built.mesh->tet_capacity());
  for (std::uint32_t piece : p.of_tet) EXPECT_EQ(piece, 0u);
}

TEST(Pieces, RemovingTheMiddleSlabOfABoxLeavesTwoNumberedByTheirLowestTet) {
  BuildResult built = build_mesh(make_box_mesh(3, 1, 1, {0, 0, 0}, {3, 1, 1}));
  ASSERT_TRUE(built.ok());
  TetMesh& mesh = *built.mesh;
  // The tets of the middle cell, 1 < x < 2 (their centroids), removed together.
  std::vector<TetId> slab;
  for (std::uint32_t t = 0; t < mesh.tet_capacity(); ++t) {
    const auto v = mesh.tet(TetId{t});
    const double x = (mesh.position(v[0]).x + mesh.position(v[1]).x + mesh.position(v[2]).x + mesh.position(v[3]).x) / 4;
    if (x > 1 && x < 2) slab.push_back(TetId{t});
  }
  ASSERT_EQ(slab.size(), 6u);
  mesh.remove_tets(slab);
  const Pieces p = face_connected_pieces(mesh);
  EXPECT_EQ(p.count, 2u);
  std::uint32_t first_live = 0;
  while (!mesh.is_live(TetId{first_live})) ++first_live;
  EXPECT_EQ(p.of_tet[first_live], 0u);
  for (TetId t : slab) EXPECT_EQ(p.of_tet[t.value], kNoPiece);
  for (std::uint32_t t = 0; t < mesh.tet_capacity(); ++t) {
    if (!mesh.is_live(TetId{t})) continue;
    const auto v = mesh.tet(TetId{t});
    const bool left = mesh.position(v[0]).x + mesh.position(v[1]).x + mesh.position(v[2]).x + mesh.position(v[3]).x < 4;
    EXPECT_EQ(p.of_tet[t], left ? p.of_tet[first_live] : 1u - p.of_tet[first_live]);
  }
}

}  // namespace
}  // namespace tetcut
