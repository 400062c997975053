// The largest stable time step of TensorMassModel::step, from the operator's spectrum rather
// than from its worst tet.
//
// Undamped, semi-implicit Euler on M u'' = -K u is stable for dt < 2 / omega_max, omega_max^2 the
// largest eigenvalue lambda_max of M^-1 K over the free vertices (damping only widens the range).
// The CFL rule (TensorMassModel::stable_time_step: smallest altitude over the pressure wave
// speed) sees one tet alone and lands anywhere around that: 0.88 of the critical step on the
// bundled liver, 1.10 (above it) on a 100 x 20 x 20 mm beam of 1,920 tets. This estimator
// iterates on the operator itself: power iterations x <- M^-1 K x, whose Rayleigh quotient
// theta = x.Kx / x.Mx rises towards lambda_max from below, each costing one step's product
// (stiffness_product). theta never exceeds lambda_max, so 2 / sqrt(theta) is at or above the
// critical step: kMargin (on lambda) covers what the few iterations leave, and
// dt = 2 / sqrt(kMargin theta) lies between 1 / 1.5 of the critical step and the step itself
// (0.89-0.90 of it on the liver and the beam, before and after a sweep that raises lambda_max
// 130-fold and 12-fold: tests/mechanics/stable_step_test.cpp, against the converged sparse
// reference, SparseStiffness::largest_eigenvalue).
//
// The start and the seeds put x where the stiff modes are: each vertex's share of x.Mx in
// proportion to the square of its local stiffness trace(K_vv) / m_v, so that a sliver's corners
// start with most of it. After cuts, update() goes on from the last iterate and seeds the
// vertices whose mass changed (the corners of the tets a cut made or removed: where its new
// stiff modes live) with kSeedShare of x.Mx; measured over every cut of the bundled resection
// and of the two sweeps above, 6 iterations leave theta at 0.93 of lambda_max or more (3 at 0.73,
// which kMargin would not cover).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "tetcut/mechanics/tensor_mass.hpp"
#include "tetcut/vec3.hpp"

namespace tetcut::mechanics {

class StableStepEstimator {
 public:
  // On lambda: dt = 2 / sqrt(kMargin theta). Covers theta down to 0.8 lambda_max; 20 cold or 6
  // warm iterations left at worst 0.98 and 0.93 on the meshes measured (see the top).
  static constexpr double kMargin = 1.25;
  static constexpr std::uint32_t kColdIterations = 20;
  static constexpr std::uint32_t kWarmIterations = 6;
  // update() starts afresh when less than this part of the iterate (x.Mx) is left on free
  // vertices after the cut.
  static constexpr double kRestartBelow = 0.5;
  // The part of x.Mx update() gives the seeds on the vertices whose mass a cut changed.
  static constexpr double kSeedShare = 0.3;

  struct Estimate {
    double dt = 0;          // s: 2 / sqrt(kMargin theta); infinite when no vertex is free
    double theta = 0;       // 1/s2: the last Rayleigh quotient, <= lambda_max
    std::uint32_t iterations = 0;
  };

  // From the stiffness-weighted start (the same estimate for the same model, every run).
  Estimate estimate(const TensorMassModel& model, std::uint32_t iterations = kColdIterations);
  // After the model changed (cuts applied): from the last iterate, the vertices whose mass
  // changed seeded. Without a previous estimate, or when the cuts took most of the iterate, a
  // cold one. O(iterations (#V + #E)), allocation-free once the model stops growing.
  Estimate update(const TensorMassModel& model, std::uint32_t iterations = kWarmIterations);

 private:
  Estimate iterate(const TensorMassModel& model, std::uint32_t iterations);
  void add_seed(const TensorMassModel& model, std::span<const std::uint32_t> vertices, double share);

  std::vector<Vec3> x_, kx_;          // by vertex id: the iterate and K times it
  std::vector<double> mass_;          // by vertex id: the masses of the last iteration
  std::vector<double> weight_;        // by vertex id: scratch for add_seed
  std::vector<std::uint32_t> seeds_;  // scratch: the vertices seeded
  bool started_ = false;
};

}  // namespace tetcut::mechanics
