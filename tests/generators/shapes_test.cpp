// The TetGen generators: valid at the exact level, deterministic, and the shapes they promise.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "tetcut/canonical_hash.hpp"
#include "tetcut/generators/shapes.hpp"
#include "tetcut/invariants/check.hpp"
#include "tetcut/mesh_builder.hpp"
#include "tetcut/predicates.hpp"

namespace tetcut::generators {
namespace {

double total_volume(const RawMesh& m) {
  double v = 0.0;
  for (const auto& t : m.tets)
    v += signed_volume(m.positions[t[0]], m.positions[t[1]], m.positions[t[2]], m.positions[t[3]]);
  return v;
}

void expect_valid_exact(const RawMesh& m) {
  invariants::CheckOptions options;
  options.level = invariants::CheckLevel::kExact;
  const auto report = invariants::check_raw(m, options);
  for (const auto& v : report.violations) ADD_FAILURE() << invariants::id_string(v.id) << ": " << v.detail;
  EXPECT_TRUE(build_mesh(m, BuildOptions{.reorient_inverted = false, .require_manifold = true}).ok());
}

TEST(Cylinder, IsValidAtTheExactLevel) {
  const GenResult r = generate_cylinder({});
  ASSERT_TRUE(r.ok()) << r.error;
  expect_valid_exact(*r.mesh);
}

TEST(Cylinder, GenerationIsDeterministic) {
  const GenResult a = generate_cylinder({});
  const GenResult b = generate_cylinder({});
  ASSERT_TRUE(a.ok() && b.ok());
  EXPECT_EQ(canonical_hash(*a.mesh), canonical_hash(*b.mesh));
  EXPECT_EQ(a.mesh->tets, b.mesh->tets);  // bit for bit, not only up to numbering
}

TEST(Cylinder, FillsThePolygonalCylinder) {
  CylinderOptions o;
  o.radius = 2.0;
  o.height = 3.0;
  o.segments = 12;
  const GenResult r = generate_cylinder(o);
  ASSERT_TRUE(r.ok()) << r.error;
  const double polygon_area = 0.5 * o.segments * o.radius * o.radius * std::sin(2 * std::numbers::pi / o.segments);
  // Between the prism over the inscribed polygon and the true cylinder: odd rings are turned by
  // half a segment, so the side bulges out between the polygon and the circle.
  const double volume = total_volume(*r.mesh);
  EXPECT_GE(volume, polygon_area * o.height * (1 - 1e-12));
  EXPECT_LE(volume, std::numbers::pi * o.radius * o.radius * o.height);
}

TEST(Cylinder, RefusesImpossibleParameters) {
  CylinderOptions o;
  o.segments = 2;
  EXPECT_FALSE(generate_cylinder(o).ok());
  o = {};
  o.radius = -1.0;
  const GenResult r = generate_cylinder(o);
  EXPECT_FALSE(r.ok());
  EXPECT_NE(r.error.find("radius"), std::string::npos);
}

// The sheet's thickness in tets: thickness over the mean height (z extent) of its tets. A sheet
// with vertices only on its two faces measures 1 (every tet spans it).
double tets_across(const RawMesh& m, double thickness) {
  double extent = 0.0;
  for (const auto& t : m.tets) {
    double lo = m.positions[t[0]].z, hi = lo;
    for (auto v : t) {
      lo = std::min(lo, m.positions[v].z);
      hi = std::max(hi, m.positions[v].z);
    }
    extent += hi - lo;
  }
  return thickness / (extent / static_cast<double>(m.tets.size()));
}

TEST(Sheet, IsTwoTetrahedraThickOnAverage) {
  const SheetOptions o;
  const GenResult r = generate_sheet(o);
  ASSERT_TRUE(r.ok()) << r.error;
  const double across = tets_across(*r.mesh, o.thickness);
  RecordProperty("tets_across", std::to_string(across));
  EXPECT_GE(across, 1.5);
  EXPECT_LE(across, 2.5);
}

TEST(Sheet, IsValidAtTheExactLevelAndFillsItsBox) {
  const SheetOptions o;
  const GenResult r = generate_sheet(o);
  ASSERT_TRUE(r.ok()) << r.error;
  expect_valid_exact(*r.mesh);
  const double volume = o.length * o.width * o.thickness;
  EXPECT_NEAR(total_volume(*r.mesh), volume, 1e-9 * volume);
}

TEST(Box, IsValidDeterministicAndFillsItsBox) {
  BoxOptions o;
  o.size = {1.0, 2.0, 0.5};
  const GenResult a = generate_box(o);
  const GenResult b = generate_box(o);
  ASSERT_TRUE(a.ok() && b.ok());
  expect_valid_exact(*a.mesh);
  EXPECT_EQ(canonical_hash(*a.mesh), canonical_hash(*b.mesh));
  EXPECT_NEAR(total_volume(*a.mesh), 1.0, 1e-9);
}

TEST(Sphere, IsAClosedIcosphereOnTheSphereFilledDeterministically) {
  SphereOptions o;
  o.radius = 2.0;
  o.subdivisions = 2;
  const TriSurface surface = sphere_surface(o);
  EXPECT_EQ(surface.triangles.size(), 20u * 16u);
  EXPECT_EQ(surface.positions.size(), 162u);  // Euler: V = F / 2 + 2
  EXPECT_EQ(closed_surface_problem(surface), std::nullopt);
  for (const Vec3& p : surface.positions) EXPECT_NEAR(norm(p), 2.0, 1e-12);
  const GenResult a = generate_sphere(o);
  const GenResult b = generate_sphere(o);
  ASSERT_TRUE(a.ok() && b.ok()) << a.error;
  expect_valid_exact(*a.mesh);
  EXPECT_EQ(canonical_hash(*a.mesh), canonical_hash(*b.mesh));
  // Between the inscribed polyhedron's volume and the ball's: the surface's triangles are its
  // boundary, each with its normal outwards (a positive volume).
  double inscribed = 0.0;
  for (const auto& t : surface.triangles)
    inscribed += dot(surface.positions[t[0]], cross(surface.positions[t[1]], surface.positions[t[2]])) / 6.0;
  EXPECT_NEAR(total_volume(*a.mesh), inscribed, 1e-9 * inscribed);
  EXPECT_GT(inscribed, 0.95 * 4.0 / 3.0 * std::numbers::pi * 8.0);
  EXPECT_FALSE(generate_sphere({.radius = -1.0}).ok());
  EXPECT_FALSE(generate_sphere({.subdivisions = 8}).ok());
}

TriSurface tetrahedron_surface() {
  TriSurface s;
  s.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  s.triangles = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
  return s;
}

TEST(Surface, AnyClosedSurfaceIsFilledWithTheRequestedSize) {
  SurfaceOptions o;
  o.tetgen.max_volume = 0.001;
  const GenResult r = generate_from_surface(tetrahedron_surface(), o);
  ASSERT_TRUE(r.ok()) << r.error;
  expect_valid_exact(*r.mesh);
  EXPECT_GE(r.mesh->tets.size(), 1.0 / 6.0 / 0.001);
  for (const auto& t : r.mesh->tets)
    EXPECT_LE(signed_volume(r.mesh->positions[t[0]], r.mesh->positions[t[1]], r.mesh->positions[t[2]],
                            r.mesh->positions[t[3]]),
              0.001 * (1 + 1e-9));
  EXPECT_NEAR(total_volume(*r.mesh), 1.0 / 6.0, 1e-12);
}

TEST(Surface, PreservingTheBoundaryKeepsTheInputTriangles) {
  SurfaceOptions o;
  o.tetgen.preserve_boundary = true;
  o.tetgen.radius_edge_ratio = 0.0;
  const GenResult r = generate_from_surface(tetrahedron_surface(), o);
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_EQ(r.mesh->tets.size(), 1u);
  EXPECT_EQ(r.mesh->positions.size(), 4u);
}

TEST(Surface, AnOpenSurfaceIsRefusedWithTheEdgeNamed) {
  TriSurface s = tetrahedron_surface();
  s.triangles.pop_back();
  s.triangles.push_back({0, 2, 1});
  s.triangles.push_back({0, 2, 1});  // now edge (0,1) and others are on three triangles
  const GenResult r = generate_from_surface(s, {});
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error.find("edge"), std::string::npos) << r.error;
}

TEST(Surface, ASelfIntersectingSurfaceIsRefused) {
  // Two closed tetrahedra whose volumes overlap: closed and manifold edge-wise, but not embedded.
  TriSurface s = tetrahedron_surface();
  const TriSurface t = tetrahedron_surface();
  for (const auto& p : t.positions) s.positions.push_back({p.x + 0.25, p.y + 0.25, p.z + 0.25});
  for (const auto& f : t.triangles) s.triangles.push_back({f[0] + 4, f[1] + 4, f[2] + 4});
  const GenResult r = generate_from_surface(s, {});
  ASSERT_FALSE(r.ok());
  EXPECT_FALSE(r.error.empty());
}

TEST(Surface, ADanglingIndexIsRefused) {
  TriSurface s = tetrahedron_surface();
  s.triangles[0][0] = 9;
  const GenResult r = generate_from_surface(s, {});
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error.find("vertex 9"), std::string::npos) << r.error;
}

}  // namespace
}  // namespace tetcut::generators
