// StableStepEstimator (stable_step.hpp) against the converged reference: the critical step
// 2 / sqrt(lambda_max(M^-1 K)) by Lanczos on the assembled sparse stiffness
// (SparseStiffness::largest_eigenvalue). The estimate must lie between 1 / 1.5 of the critical
// step and the critical step itself, on the bundled liver and on a clamped beam, before a cut
// sweep and after it, kept as `tetcut simulate` keeps it (one update per cut) and made afresh.
// The sweeps use the basic strategy (paper 3.4), whose splits leave slivers: lambda_max grows
// 130-fold on the liver, 12-fold on the beam, so "after" is a different spectrum.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <vector>

#include "mechanics_test_support.hpp"
#include "tetcut/box_mesh.hpp"
#include "tetcut/cut.hpp"
#include "tetcut/mechanics/sparse_reference.hpp"
#include "tetcut/mechanics/stable_step.hpp"

namespace tetcut {
namespace {

using mechanics::ModelParams;
using mechanics::SparseStiffness;
using mechanics::StableStepEstimator;
using mechanics::TensorMassModel;

double lambda_max(const TensorMassModel& model) {
  const SparseStiffness::Eigenvalue e = SparseStiffness(model).largest_eigenvalue(model);
  EXPECT_TRUE(e.converged) << "residual " << e.residual << " after " << e.iterations << " iterations";
  return e.lambda;
}

void expect_within_range(const std::string& what, double estimate, double critical) {
  std::printf("%s: estimate %.4g s, critical step %.4g s, ratio %.3f\n", what.c_str(), estimate, critical,
              estimate / critical);
  EXPECT_LE(estimate, critical) << what << ": above the critical step";
  EXPECT_GE(estimate, critical / 1.5) << what << ": below 1 / 1.5 of the critical step";
}

struct Sweep {
  Vec3 from, to;
};

// Estimates before, then after every cut of the sweeps (checked against the reference after
// every `check_every`-th cut when it is not 0, and after the last), then afresh. `stiffens`: the
// sweep is meant to make tets small enough to raise the largest eigenvalue (a tool the mesh's
// tets are much coarser than); a sweep whose made tets keep the quality floor at the mesh's own
// scale may leave it as it was, and the estimate is checked after it all the same. Returns the
// cuts made, which the caller holds to a minimum: a sweep that cut nothing checked nothing.
std::uint32_t run(const std::string& name, TetMesh mesh, const std::function<bool(const Vec3&)>& fixed, double diameter,
         const std::vector<Sweep>& sweeps, double step, std::uint32_t check_every, bool stiffens) {
  TensorMassModel model(mesh, ModelParams{});
  EXPECT_GT(model.fix_where(mesh, fixed), 0u);
  StableStepEstimator estimator;
  const double before = lambda_max(model);
  expect_within_range(name + ", before the cuts", estimator.estimate(model).dt, 2 / std::sqrt(before));
  Cutter cutter(mesh, {.tool_diameter = diameter, .strategy = RemovalStrategy::kBasic});
  ChangeLog log;
  StableStepEstimator::Estimate kept;
  std::uint32_t cuts = 0;
  for (const Sweep& s : sweeps) {
    const double length = norm(s.to - s.from);
    for (double at = 0; at <= length; at += step) {
      log.clear();
      if (!cutter.cut(s.from + (at / length) * (s.to - s.from), &log).ok) continue;  // refused: nothing changed
      model.apply(mesh, log);
      kept = estimator.update(model);
      ++cuts;
      if (check_every != 0 && cuts % check_every == 0) {
        const double critical = 2 / std::sqrt(lambda_max(model));
        EXPECT_LE(kept.dt, critical) << name << ", cut " << cuts;
        EXPECT_GE(kept.dt, critical / 1.5) << name << ", cut " << cuts;
      }
    }
  }
  const double after = lambda_max(model);
  std::printf("%s: %u cuts, lambda_max %.4g -> %.4g 1/s2\n", name.c_str(), cuts, before, after);
  if (stiffens) {
    EXPECT_GT(after, 2 * before) << "the sweep was meant to leave small tets";
  }
  expect_within_range(name + ", after the sweep, updated cut by cut", kept.dt, 2 / std::sqrt(after));
  expect_within_range(name + ", after the sweep, made afresh", StableStepEstimator().estimate(model).dt,
                      2 / std::sqrt(after));
  return cuts;
}

TEST(StableStep, TheEstimateIsWithinTwoThirdsOfTheCriticalStepOnTheLiverBeforeAndAfterASweep) {
  // The README's sweep, the tissue held at x > 150 mm as in docs/mechanics.md's example.
  EXPECT_GT(run("liver", testing::load_bundled("liver.msh"), [](const Vec3& p) { return p.x > 150; }, 8.0,
                {{{95, 40, 100}, {95, 180, 100}}}, 4.0, 0, false),
            10u);
}

TEST(StableStep, TheEstimateIsWithinTwoThirdsOfTheCriticalStepOnABeamAlongASweep) {
  // 100 x 20 x 20 mm, 1,920 tets, clamped at x = 0; two passes across it, the estimate checked
  // after every third of its 46 cuts (each check a Lanczos run: under ASan, every cut took 5 s).
  BuildResult built = build_mesh(make_box_mesh(20, 4, 4, {0, 0, 0}, {100, 20, 20}));
  ASSERT_TRUE(built.ok());
  EXPECT_GT(run("beam", std::move(*built.mesh), [](const Vec3& p) { return p.x < 1e-9; }, 4.0,
                {{{50, -1, 20}, {50, 21, 20}}, {{30, -1, 10}, {30, 21, 10}}}, 1.0, 3, true),
            10u);
}

TEST(StableStep, TheReferenceIsTheCriticalStepOfTheIntegrator) {
  // Undamped, a step just below 2 / omega_max stays bounded and one just above grows without
  // bound: the reference is the step the integrator itself cannot pass.
  BuildResult built = build_mesh(make_box_mesh(6, 2, 2, {0, 0, 0}, {30, 10, 10}));
  ASSERT_TRUE(built.ok());
  const TetMesh mesh = std::move(*built.mesh);
  auto final_energy = [&](double dt) {
    TensorMassModel model(mesh, ModelParams{});
    model.fix_where(mesh, [](const Vec3& p) { return p.x < 1e-9; });
    for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v)
      if (!model.is_fixed(VertId{v})) model.set_displacement(VertId{v}, {1e-6 * std::sin(v), 1e-6 * std::cos(v), 0});
    const double start = model.energy().total();
    for (int i = 0; i < 4000; ++i) model.step(dt);
    return model.energy().total() / start;
  };
  TensorMassModel model(mesh, ModelParams{});
  model.fix_where(mesh, [](const Vec3& p) { return p.x < 1e-9; });
  const double critical = 2 / std::sqrt(lambda_max(model));
  EXPECT_LT(final_energy(0.99 * critical), 10.0);
  const double above = final_energy(1.01 * critical);
  EXPECT_TRUE(!std::isfinite(above) || above > 1e6) << above;
}

}  // namespace
}  // namespace tetcut
