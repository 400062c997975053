// The rendered surface (rendered_surface.hpp): the boundary triangles, outward, and one normal
// per surface vertex, the mesh's own boundary_normal(); one fan per vertex on a manifold mesh.
#include <gtest/gtest.h>

#include "mechanics_test_support.hpp"
#include "tetcut/box_mesh.hpp"
#include "tetcut/cut.hpp"
#include "tetcut/mechanics/differential.hpp"
#include "tetcut/mechanics/rendered_surface.hpp"

namespace tetcut {
namespace {

using mechanics::RenderedSurface;

TEST(RenderedSurface, ABoxHasItsSixFacesOutwardWithOneNormalPerVertex) {
  BuildResult built = build_mesh(make_box_mesh(3, 4, 5, {0, 0, 0}, {3, 4, 5}));
  ASSERT_TRUE(built.ok());
  const TetMesh& mesh = *built.mesh;
  const RenderedSurface surface(mesh);
  EXPECT_EQ(surface.triangle_count(), 2u * 2u * (3 * 4 + 4 * 5 + 5 * 3));
  const Vec3 middle{1.5, 2, 2.5};
  for (const auto& t : surface.triangle_slots()) {
    if (!t.v[0].valid()) continue;
    const Vec3 c = (1.0 / 3.0) * (mesh.position(t.v[0]) + mesh.position(t.v[1]) + mesh.position(t.v[2]));
    EXPECT_GT(dot(t.area_vector, c - middle), 0.0) << "a triangle faces inward";
  }
  EXPECT_FALSE(mechanics::fan_problem(surface));
  std::uint32_t on_surface = 0;
  for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v) {
    const VertId id{v};
    EXPECT_EQ(surface.triangles_at(id) > 0, mesh.is_boundary_vertex(id));
    if (surface.triangles_at(id) == 0) continue;
    ++on_surface;
    EXPECT_LT(norm(surface.normal(id) - mesh.boundary_normal(id)), 1e-12);
    EXPECT_NEAR(norm(surface.normal(id)), 1.0, 1e-15);
  }
  EXPECT_EQ(on_surface, 4u * 5 * 6 - 2u * 3 * 4);  // all grid points but the interior ones
}

TEST(RenderedSurface, ACutOpensACavityWhoseRimKeepsOneFanPerVertex) {
  TetMesh mesh = testing::load_bundled("cylinder.msh");
  const BoundingBox box = bounding_box(mesh);
  Cutter cutter(mesh, {.tool_diameter = box.diagonal() / 12});
  RenderedSurface surface(mesh);
  const std::uint32_t before = surface.triangle_count();
  // Centred on the surface: the cut opens a crater, whose rim vertices change fans.
  const Vec3 centre{box.hi.x, 0.5 * (box.lo.y + box.hi.y), 0.5 * (box.lo.z + box.hi.z)};
  ChangeLog log;
  ASSERT_TRUE(cutter.cut(cutter.tet_containing(centre).valid() ? centre : 0.5 * (box.lo + box.hi), &log).ok);
  ASSERT_FALSE(log.removed.empty());
  EXPECT_EQ(surface.apply(mesh, log), 0u);
  EXPECT_NE(surface.triangle_count(), before);
  EXPECT_FALSE(mechanics::fan_problem(surface));
  const RenderedSurface rebuilt(mesh);
  double worst = 0;
  const auto d = mechanics::compare(surface, rebuilt, mesh, mechanics::kDifferentialTolerance, &worst);
  EXPECT_FALSE(d) << *d;
}

}  // namespace
}  // namespace tetcut
