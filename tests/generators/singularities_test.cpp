// The complete singularity finder: every singular vertex and edge, with its shell's components.
#include <gtest/gtest.h>

#include "test_meshes.hpp"
#include "tetcut/generators/singularities.hpp"

namespace tetcut::generators {
namespace {

using test::glue;
using test::vertex_at;

TEST(Singularities, AStructuredBoxHasNone) {
  EXPECT_TRUE(find_singularities(make_box_mesh(3, 2, 2)).empty());
}

TEST(Singularities, TwoBoxesTouchingAtACornerMakeOneSingularVertexWithTwoComponents) {
  const RawMesh m = glue(make_box_mesh(1, 1, 1), make_box_mesh(1, 1, 1, {1, 1, 1}));
  const Singularities s = find_singularities(m);
  EXPECT_TRUE(s.edges.empty());
  ASSERT_EQ(s.vertices.size(), 1u);
  EXPECT_EQ(s.vertices[0].vertex, vertex_at(m, {1, 1, 1}));
  EXPECT_EQ(s.vertices[0].components.size(), 2u);
  EXPECT_TRUE(s.vertices[0].on_boundary);
  EXPECT_EQ(s.vertices[0].link_euler, 2);  // two disks
}

TEST(Singularities, TwoBoxesSharingAnEdgeMakeASingularEdgeAndItsEnds) {
  const RawMesh m = glue(make_box_mesh(1, 1, 1), make_box_mesh(1, 1, 1, {1, 1, 0}));
  const Singularities s = find_singularities(m);
  ASSERT_EQ(s.edges.size(), 1u);
  const auto a = vertex_at(m, {1, 1, 0}), b = vertex_at(m, {1, 1, 1});
  EXPECT_EQ(s.edges[0].a, std::min(a, b));
  EXPECT_EQ(s.edges[0].b, std::max(a, b));
  EXPECT_EQ(s.edges[0].components.size(), 2u);
  ASSERT_EQ(s.vertices.size(), 2u);
}

TEST(Singularities, APinchedTunnelIsFoundThoughTheShellIsConnected) {
  const RawMesh m = test::pinched_box();
  const Singularities s = find_singularities(m);
  const auto centre = vertex_at(m, {1, 1, 1});
  const SingularVertex* found = nullptr;
  for (const auto& v : s.vertices)
    if (v.vertex == centre) found = &v;
  ASSERT_NE(found, nullptr);
  EXPECT_EQ(found->components.size(), 1u);
  EXPECT_TRUE(found->on_boundary);
  EXPECT_EQ(found->link_euler, 0);  // an annulus
}

}  // namespace
}  // namespace tetcut::generators
