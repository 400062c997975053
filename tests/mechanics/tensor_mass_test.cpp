// The tensor-mass model's physics (tensor_mass.hpp): what linear elasticity on linear tets must
// do whatever the mesh (rigid motions cost nothing, a uniform strain is reproduced exactly), the
// masses, the explicit step against the sparse-matrix product, the stable step, and the
// configuration a tool meets.
#include <gtest/gtest.h>

#include <cmath>

#include "mechanics_test_support.hpp"
#include "tetcut/box_mesh.hpp"
#include "tetcut/cut.hpp"
#include "tetcut/mechanics/sparse_reference.hpp"
#include "tetcut/mechanics/tensor_mass.hpp"

namespace tetcut {
namespace {

using mechanics::Material;
using mechanics::ModelParams;
using mechanics::TensorMassModel;

TetMesh box_mesh(std::uint32_t n, Vec3 size = {1, 1, 1}) {
  BuildResult built = build_mesh(make_box_mesh(n, n, n, {0, 0, 0}, size));
  EXPECT_TRUE(built.ok());
  return std::move(*built.mesh);
}

ModelParams si_params() {
  ModelParams p;
  p.length_unit = 1.0;
  return p;
}

double largest_force(const std::vector<Vec3>& f) {
  double m = 0;
  for (const Vec3& x : f) m = std::max(m, norm(x));
  return m;
}

TEST(Material, LiverDefaultAndLameCoefficients) {
  const Material liver;
  EXPECT_EQ(liver.young, 3000.0);
  EXPECT_EQ(liver.poisson, 0.45);
  EXPECT_EQ(liver.density, 1000.0);
  const mechanics::Lame l = mechanics::lame(liver);
  EXPECT_NEAR(l.mu, 3000.0 / 2.9, 1e-9);
  EXPECT_NEAR(l.lambda, 3000.0 * 0.45 / (1.45 * 0.1), 1e-9);
  EXPECT_FALSE(mechanics::validate(liver));
  EXPECT_TRUE(mechanics::validate(Material{3000, 0.5, 1000}));
  EXPECT_TRUE(mechanics::validate(Material{-1, 0.3, 1000}));
  EXPECT_TRUE(mechanics::validate(Material{3000, 0.3, 0}));
}

TEST(TensorMass, RigidMotionsMakeNoForce) {
  const TetMesh mesh = box_mesh(3);
  TensorMassModel model(mesh, si_params());
  std::vector<Vec3> f;
  // A translation and an infinitesimal rotation strain nothing.
  for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v) model.set_displacement(VertId{v}, {1e-3, -2e-3, 5e-4});
  model.elastic_forces(f);
  const double scale = model.vertex_scale(VertId{0}) * 1e-3;
  EXPECT_LT(largest_force(f), 1e-12 * scale);
  const Vec3 omega{1e-3, 2e-3, -1.5e-3};
  for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v)
    model.set_displacement(VertId{v}, cross(omega, mesh.position(VertId{v})));
  model.elastic_forces(f);
  EXPECT_LT(largest_force(f), 1e-12 * scale);
  // Against the energy of a strain of the rotation's size, mu |omega|^2 V (V = 1).
  EXPECT_LT(std::abs(model.energy().elastic), 1e-12 * mechanics::lame(Material{}).mu * dot(omega, omega));
}

TEST(TensorMass, UniformStrainIsReproducedExactly) {
  // Patch test: u = E X with a symmetric strain E; interior vertices feel no force and the
  // elastic energy is V (lambda tr(E)^2 / 2 + mu E:E).
  const TetMesh mesh = box_mesh(4);
  TensorMassModel model(mesh, si_params());
  const double e[3][3] = {{1e-3, 2e-4, 0}, {2e-4, -5e-4, 3e-4}, {0, 3e-4, 2e-4}};
  for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v) {
    const Vec3 x = mesh.position(VertId{v});
    model.set_displacement(VertId{v}, {e[0][0] * x.x + e[0][1] * x.y + e[0][2] * x.z,
                                       e[1][0] * x.x + e[1][1] * x.y + e[1][2] * x.z,
                                       e[2][0] * x.x + e[2][1] * x.y + e[2][2] * x.z});
  }
  std::vector<Vec3> f;
  model.elastic_forces(f);
  std::uint32_t interior = 0;
  for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v) {
    if (mesh.is_boundary_vertex(VertId{v})) continue;
    ++interior;
    EXPECT_LT(norm(f[v]), 1e-12 * model.vertex_scale(VertId{v})) << "interior vertex " << v;
  }
  EXPECT_GT(interior, 0u);
  const mechanics::Lame l = mechanics::lame(Material{});
  double trace = e[0][0] + e[1][1] + e[2][2], ee = 0;
  for (auto& row : e)
    for (double x : row) ee += x * x;
  EXPECT_NEAR(model.energy().elastic, 0.5 * l.lambda * trace * trace + l.mu * ee, 1e-12);
}

TEST(TensorMass, TensorsAreSymmetricAndMassesAddUpToTheVolume) {
  const TetMesh mesh = testing::load_bundled("liver-coarse.msh");
  const TensorMassModel model(mesh, ModelParams{});  // millimetres
  double mass = 0;
  for (std::uint32_t v = 0; v < model.vertex_capacity(); ++v) {
    mass += model.mass(VertId{v});
    const auto& k = model.vertex_stiffness(VertId{v});
    EXPECT_NEAR(k[1], k[3], 1e-12 * model.vertex_scale(VertId{v}));
    EXPECT_NEAR(k[2], k[6], 1e-12 * model.vertex_scale(VertId{v}));
    EXPECT_NEAR(k[5], k[7], 1e-12 * model.vertex_scale(VertId{v}));
    if (model.tets_at(VertId{v}) > 0) {
      EXPECT_GT(k[0] + k[4] + k[8], 0.0);
    }
  }
  const double volume_m3 = mesh.total_volume() * 1e-9;
  EXPECT_NEAR(mass, 1000.0 * volume_m3, 1e-12 * mass);
}

TEST(TensorMass, TheTensorLoopEqualsTheSparseMatrixProduct) {
  const TetMesh mesh = testing::load_bundled("liver-coarse.msh");
  TensorMassModel model(mesh, ModelParams{});
  for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v)
    model.set_displacement(VertId{v}, {1e-4 * std::sin(v), 1e-4 * std::cos(3.0 * v), 1e-4 * std::sin(7.0 * v)});
  std::vector<Vec3> loop, sparse;
  model.elastic_forces(loop);
  const mechanics::SparseStiffness k(model);
  k.elastic_forces(model, sparse);
  ASSERT_EQ(loop.size(), sparse.size());
  const double scale = largest_force(sparse);
  ASSERT_GT(scale, 0.0);
  for (std::size_t v = 0; v < loop.size(); ++v) EXPECT_LT(norm(loop[v] - sparse[v]), 1e-12 * scale) << v;
  EXPECT_EQ(k.nonzeros(), 9 * (std::size_t{mesh.num_vertices()} + 2 * std::size_t{model.edge_count()}));
}

// Largest eigenvalue of M^-1 K by power iteration (free vertices): omega_max^2.
double omega_max_squared(TensorMassModel& model, std::uint32_t vertices) {
  std::vector<Vec3> f;
  for (std::uint32_t v = 0; v < vertices; ++v)
    model.set_displacement(VertId{v}, {std::sin(1.0 + v), std::cos(2.0 * v), std::sin(5.0 * v + 0.3)});
  double lambda = 0;
  for (int it = 0; it < 400; ++it) {
    model.elastic_forces(f);
    double n = 0;
    for (std::uint32_t v = 0; v < vertices; ++v) {
      if (model.tets_at(VertId{v}) == 0) continue;
      f[v] = (-1.0 / model.mass(VertId{v})) * f[v];
      n = std::max(n, norm(f[v]));
    }
    double u = 0;
    for (std::uint32_t v = 0; v < vertices; ++v) u = std::max(u, norm(model.displacement(VertId{v})));
    lambda = n / u;
    for (std::uint32_t v = 0; v < vertices; ++v) model.set_displacement(VertId{v}, (1.0 / n) * f[v]);
  }
  return lambda;
}

TEST(TensorMass, TheCflStepIsBelowTheCriticalStep) {
  const TetMesh mesh = testing::load_bundled("liver-coarse.msh");
  TensorMassModel model(mesh, ModelParams{});
  const auto cfl = model.stable_time_step(mesh);
  EXPECT_GT(cfl.min_altitude, 0.0);
  EXPECT_NEAR(cfl.wave_speed, mechanics::pressure_wave_speed(Material{}), 1e-12);
  const double critical = 2.0 / std::sqrt(omega_max_squared(model, mesh.vertex_capacity()));
  std::printf("CFL step %.4g s, critical step 2 / omega_max %.4g s\n", cfl.dt, critical);
  EXPECT_LE(cfl.dt, critical);
  EXPECT_GT(cfl.dt, 0.05 * critical) << "the estimate is uselessly pessimistic";
}

TEST(TensorMass, ACantileverSettlesUnderGravityWithoutBlowingUp) {
  const TetMesh mesh = box_mesh(4, {100, 20, 20});  // mm
  ModelParams p;
  p.gravity = {0, 0, -9.81};
  p.damping = 50;
  TensorMassModel model(mesh, p);
  EXPECT_GT(model.fix_where(mesh, [](const Vec3& x) { return x.x < 1e-9; }), 0u);
  const double dt = 0.9 * model.stable_time_step(mesh).dt;
  for (int i = 0; i < 3000; ++i) model.step(dt);  // seconds of simulated time: many damping times
  double tip = 0;
  for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v) {
    const Vec3& u = model.displacement(VertId{v});
    ASSERT_TRUE(is_finite(u));
    if (model.is_fixed(VertId{v})) {
      EXPECT_EQ(norm(u), 0.0);
    }
    if (mesh.position(VertId{v}).x > 99.0) tip = std::min(tip, u.z);
  }
  EXPECT_LT(tip, 0.0) << "the free end sags";
  const mechanics::Energy e = model.energy();
  EXPECT_LT(e.kinetic, 1e-3 * std::abs(e.total())) << "settled";
  EXPECT_LT(e.total(), 0.0) << "gravity's work exceeds the stored energy at rest";
}

TEST(TensorMass, AVertexACutCreatesIsFixedWhenAllItsOriginsAre) {
  TetMesh mesh = box_mesh(4, {40, 40, 40});
  TensorMassModel model(mesh, ModelParams{});
  ASSERT_GT(model.fix_where(mesh, [](const Vec3& x) { return x.x <= 20; }), 0u);
  Cutter cutter(mesh, {.tool_diameter = 5});  // D_ref 7.5 against edges of 10: it refines
  ChangeLog log;
  ASSERT_TRUE(cutter.cut({20, 20, 40}, &log).ok);  // on the top face, across the fixed half's edge
  model.apply(mesh, log);
  std::uint32_t fixed = 0, free = 0;
  for (const CreatedVertex& v : log.vertices) {
    bool all = true;
    for (std::uint8_t i = 0; i < v.count; ++i) all = all && mesh.position(v.from[i]).x <= 20;
    EXPECT_EQ(model.is_fixed(v.vertex), all) << "vertex " << v.vertex.value;
    (all ? fixed : free) += 1;
  }
  EXPECT_GT(fixed, 0u);
  EXPECT_GT(free, 0u);
}

TEST(TensorMass, TheToolMeetsTheDeformedTissueAndCutsItsRestShape) {
  // The tool is where the simulator draws it, among the deformed tissue; the engine cuts the
  // rest mesh. rest_point() maps the tool's centre through the deformed tet that holds it.
  TetMesh mesh = testing::load_bundled("liver-coarse.msh");
  TensorMassModel model(mesh, ModelParams{});
  const BoundingBox box = bounding_box(mesh);
  const Vec3 mid = 0.5 * (box.lo + box.hi);
  const double shift = box.diagonal() / 10;  // mm: a deformation larger than the tool
  // An affine deformation: the shift along x and a 2 % stretch.
  auto displacement_mm = [&](const Vec3& x) { return Vec3{shift + 0.02 * (x.x - mid.x), 0, 0}; };
  for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v)
    model.set_displacement(VertId{v}, 1e-3 * displacement_mm(mesh.position(VertId{v})));
  const double diameter = box.diagonal() / 25;
  Cutter cutter(mesh, {.tool_diameter = diameter});
  // The tissue point to cut: the centroid nearest the box's middle (which may be outside a
  // liver) whose displaced place is inside the rest shape too (the start of the search).
  Vec3 centre{};
  double best = 1e300;
  for (std::uint32_t t = 0; t < mesh.tet_capacity(); ++t) {
    if (!mesh.is_live(TetId{t})) continue;
    const auto v = mesh.tet(TetId{t});
    const Vec3 c = 0.25 * (mesh.position(v[0]) + mesh.position(v[1]) + mesh.position(v[2]) + mesh.position(v[3]));
    if (norm(c - mid) < best && cutter.tet_containing(c + displacement_mm(c)).valid()) {
      best = norm(c - mid);
      centre = c;
    }
  }
  ASSERT_LT(best, 1e300);
  const Vec3 world = centre + displacement_mm(centre);  // where the tissue point `centre` now is
  const auto rest = model.rest_point(mesh, world, [&](const Vec3& p) { return cutter.tet_containing(p); });
  ASSERT_TRUE(rest);
  EXPECT_LT(norm(*rest - centre), 1e-9 * box.diagonal());
  // Cutting there removes the tissue the tool touched, around `centre` at rest, not the tissue
  // that lies under the tool in the rest configuration.
  const TetMesh before = mesh;
  ChangeLog log;
  ASSERT_TRUE(cutter.cut(*rest, &log).ok);
  ASSERT_FALSE(log.removed.empty());
  Vec3 mean{};
  double volume = 0;
  for (TetId t : log.removed) {
    const auto v = before.tet(t);
    const double w = before.volume(t);
    mean = mean + w * (0.25 * (before.position(v[0]) + before.position(v[1]) + before.position(v[2]) + before.position(v[3])));
    volume += w;
  }
  mean = (1.0 / volume) * mean;
  // The cavity is the tool's size to within a tet or a neighbour set (cut.hpp): its middle
  // within a diameter of the rest point, and a whole shift away from the tool's place at rest.
  EXPECT_LT(norm(mean - centre), diameter);
  EXPECT_GT(norm(mean - world), shift - diameter);
}

}  // namespace
}  // namespace tetcut
