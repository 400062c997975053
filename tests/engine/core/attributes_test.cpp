#include <gtest/gtest.h>

#include "test_meshes.hpp"
#include "tetcut/attributes.hpp"

namespace tetcut {
namespace {

TEST(VertexAttributes, ChannelsAreZeroInitialisedAndNamed) {
  VertexAttributes attrs;
  attrs.resize(3);
  const auto uv = attrs.add_channel(kTexCoordChannel, 2);
  ASSERT_TRUE(uv);
  EXPECT_EQ(attrs.find(kTexCoordChannel), uv);
  EXPECT_FALSE(attrs.add_channel(kTexCoordChannel, 3)) << "same name, other width";
  EXPECT_EQ(attrs.add_channel(kTexCoordChannel, 2), uv);
  EXPECT_EQ(attrs.value(*uv, VertId{2}).size(), 2u);
  EXPECT_EQ(attrs.value(*uv, VertId{2})[1], 0.0);
  EXPECT_FALSE(attrs.find("missing"));
}

TEST(VertexAttributes, EdgeVertexInterpolatesEveryChannel) {
  TetMesh mesh = testing::build_or_fail(testing::single_tet());
  const auto rest = *mesh.attributes().add_channel(kRestPositionChannel, 3);
  const auto user = *mesh.attributes().add_channel("stiffness", 1);
  for (std::uint32_t v = 0; v < 4; ++v) {
    const Vec3 p = mesh.position(VertId{v});
    auto r = mesh.attributes().value(rest, VertId{v});
    r[0] = p.x; r[1] = p.y; r[2] = p.z;
    mesh.attributes().value(user, VertId{v})[0] = 10.0 * v;
  }
  const VertId m = mesh.add_vertex_on_edge(VertId{1}, VertId{3}, 0.25);
  EXPECT_EQ(mesh.position(m), (Vec3{0.75, 0, 0.25}));
  EXPECT_DOUBLE_EQ(mesh.attributes().value(rest, m)[0], 0.75);
  EXPECT_DOUBLE_EQ(mesh.attributes().value(rest, m)[2], 0.25);
  EXPECT_DOUBLE_EQ(mesh.attributes().value(user, m)[0], 15.0);
}

TEST(VertexAttributes, FollowTheirVertexThroughCompaction) {
  TetMesh mesh = testing::build_or_fail(make_box_mesh(2, 1, 1));
  const auto tag = *mesh.attributes().add_channel("tag", 1);
  for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v) mesh.attributes().value(tag, VertId{v})[0] = v;
  // Remove the tets of the first cube: vertex 0 (corner) loses all its tets.
  std::vector<TetId> first_cube;
  for (std::uint32_t t = 0; t < 6; ++t) first_cube.push_back(TetId{t});
  mesh.remove_tets(first_cube);
  ASSERT_FALSE(mesh.is_live(VertId{0}));
  const Renumbering map = mesh.compact();
  for (std::uint32_t old = 0; old < map.vert_old_to_new.size(); ++old) {
    const VertId now = map.vert_old_to_new[old];
    if (now.valid()) {
      EXPECT_EQ(mesh.attributes().value(tag, now)[0], old);
    }
  }
  EXPECT_EQ(mesh.attributes().size(), mesh.num_vertices());
}

}  // namespace
}  // namespace tetcut
