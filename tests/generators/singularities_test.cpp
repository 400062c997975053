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

// A 2x2x2 box whose centre is reached by two conical holes, from the top and from the bottom:
// the centre's shell stays face-connected but its link is an annulus (design I5).
RawMesh pinched_box() {
  RawMesh box = make_box_mesh(2, 2, 2, {0, 0, 0}, {2, 2, 2});
  const auto centre = vertex_at(box, {1, 1, 1});
  const auto top = vertex_at(box, {1, 1, 2});
  const auto bottom = vertex_at(box, {1, 1, 0});
  RawMesh out;
  out.positions = box.positions;
  for (const auto& t : box.tets) {
    const bool on_axis = test::contains(t, centre) && (test::contains(t, top) || test::contains(t, bottom));
    if (!on_axis) out.tets.push_back(t);
  }
  return out;
}

TEST(Singularities, APinchedTunnelIsFoundThoughTheShellIsConnected) {
  const RawMesh m = pinched_box();
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
