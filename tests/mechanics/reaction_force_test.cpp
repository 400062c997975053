// mechanics::reaction_force (reaction_force.hpp): the force the tissue exerts on the tool. A tool
// pressed into the tissue feels it push back against the press; a tool that holds all of the
// tissue feels nothing, the elastic forces of a body summing to zero; and a capsule feels what
// the balls along its segment feel together.
#include <gtest/gtest.h>

#include <vector>

#include "mechanics_test_support.hpp"
#include "tetcut/mechanics/reaction_force.hpp"
#include "tetcut/mechanics/tensor_mass.hpp"

namespace tetcut {
namespace {

using mechanics::reaction_force;
using mechanics::TensorMassModel;

struct Pressed {
  TetMesh mesh = testing::load_bundled("cylinder.msh");
  TensorMassModel model{mesh, testing::four_materials()};
  Vec3 centre{};
  double radius = 0.5;

  // The vertices within `radius` of the top's centre pushed down by `depth` (mesh units), the
  // rest of the tissue at rest: the tool's press before the tissue has moved.
  explicit Pressed(double depth) {
    double top = -1e300;
    for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v)
      if (mesh.is_live(VertId{v})) top = std::max(top, mesh.position(VertId{v}).z);
    centre = {0, 0, top - depth};
    const double unit = model.params().length_unit;
    for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v) {
      const VertId id{v};
      if (!mesh.is_live(id)) continue;
      const Vec3 p = mesh.position(id);
      if (norm(p - Vec3{0, 0, top}) <= radius) model.set_displacement(id, {0, 0, -depth * unit});
    }
  }
};

TEST(ReactionForce, APressedToolIsPushedBackAgainstItsPress) {
  Pressed press(0.05);
  std::vector<Vec3> forces;
  const Vec3 f = reaction_force(press.mesh, press.model, press.centre, press.centre, press.radius, forces);
  EXPECT_GT(f.z, 0.0) << "the tissue pushes the tool up, out of it";
  EXPECT_GT(f.z, 10 * (std::abs(f.x) + std::abs(f.y))) << "and mostly along the press, the cylinder's axis";
  // A deeper press, a stronger push (the vertices the tool holds are not quite the same ones).
  Pressed deeper(0.1);
  const Vec3 g = reaction_force(deeper.mesh, deeper.model, deeper.centre, deeper.centre, deeper.radius, forces);
  EXPECT_GT(g.z, 1.5 * f.z);
}

TEST(ReactionForce, AToolHoldingAllOfTheTissueFeelsNothing) {
  Pressed press(0.05);
  std::vector<Vec3> forces;
  const Vec3 part = reaction_force(press.mesh, press.model, press.centre, press.centre, press.radius, forces);
  const Vec3 all = reaction_force(press.mesh, press.model, press.centre, press.centre, 1e6, forces);
  double size = 0;
  for (const Vec3& f : forces) size += norm(f);
  EXPECT_GT(size, 0.0);
  EXPECT_LT(norm(all), 1e-9 * size) << "the elastic forces of one body sum to zero";
  EXPECT_GT(norm(part), 1e-3 * size);
}

TEST(ReactionForce, ACapsuleCountsEveryVertexWithinItsRadiusOfTheSegmentOnce) {
  Pressed press(0.05);
  std::vector<Vec3> forces;
  // Along the top, from one side of the press to the other: the ball at either end misses
  // vertices the capsule holds, and no vertex is counted twice (a capsule no longer than
  // nothing is the ball).
  const Vec3 a = press.centre - Vec3{0.3, 0, 0}, b = press.centre + Vec3{0.3, 0, 0};
  const Vec3 capsule = reaction_force(press.mesh, press.model, a, b, 0.2, forces);
  const Vec3 ball_a = reaction_force(press.mesh, press.model, a, a, 0.2, forces);
  Vec3 expected{};
  const double unit = press.model.params().length_unit;
  for (std::uint32_t v = 0; v < press.mesh.vertex_capacity(); ++v) {
    const VertId id{v};
    if (!press.mesh.is_live(id)) continue;
    const Vec3 p = press.mesh.position(id) + (1.0 / unit) * press.model.displacement(id);
    // Within 0.2 of the segment, which runs along x at the centre's y and z.
    const double along = std::clamp(p.x - a.x, 0.0, b.x - a.x);
    if (norm(p - (a + Vec3{along, 0, 0})) <= 0.2) expected = expected + forces[v];
  }
  EXPECT_NEAR(capsule.x, expected.x, 1e-12 + 1e-9 * norm(expected));
  EXPECT_NEAR(capsule.z, expected.z, 1e-12 + 1e-9 * norm(expected));
  EXPECT_NE(capsule.z, ball_a.z);
}

}  // namespace
}  // namespace tetcut
