// StableStepEstimator: power iterations on M^-1 K over the free vertices (stable_step.hpp).
#include "tetcut/mechanics/stable_step.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tetcut::mechanics {
namespace {

// Direction: no structure a mesh's modes could be orthogonal to.
Vec3 direction(std::uint32_t v) {
  const double x = v;
  return {std::sin(1.0 + x), std::cos(2.0 * x), std::sin(5.0 * x + 0.3)};
}

bool is_free(const TensorMassModel& model, std::uint32_t v) {
  return model.tets_at(VertId{v}) > 0 && !model.is_fixed(VertId{v});
}

// trace(K_vv) / m_v (1/s2): three times the mean Rayleigh quotient of a displacement of v alone,
// the order of the stiffest mode v takes part in.
double local_stiffness(const TensorMassModel& model, std::uint32_t v) {
  const Tensor3& k = model.vertex_stiffness(VertId{v});
  return (k[0] + k[4] + k[8]) / model.mass(VertId{v});
}

}  // namespace

// The seed on `vertices`: each vertex's x.Mx share in proportion to the square of its local
// stiffness, so that the stiffest places (a sliver's corners, a vertex left with one small tet)
// start with most of it and the power iteration has little left to find; the whole seed worth
// `share` of x.Mx, added to x.
void StableStepEstimator::add_seed(const TensorMassModel& model, std::span<const std::uint32_t> vertices, double share) {
  double sum = 0;
  for (std::uint32_t v : vertices) {
    const double d = local_stiffness(model, v);
    weight_[v] = d / std::sqrt(model.mass(VertId{v}));  // so that m_v weight_v^2 = d^2
    sum += model.mass(VertId{v}) * weight_[v] * weight_[v] * dot(direction(v), direction(v));
  }
  if (!(sum > 0)) return;
  const double scale = std::sqrt(share / sum);
  for (std::uint32_t v : vertices) x_[v] = x_[v] + (scale * weight_[v]) * direction(v);
}

StableStepEstimator::Estimate StableStepEstimator::estimate(const TensorMassModel& model, std::uint32_t iterations) {
  const std::uint32_t n = model.vertex_capacity();
  x_.assign(n, Vec3{});
  weight_.resize(n);
  seeds_.clear();
  for (std::uint32_t v = 0; v < n; ++v)
    if (is_free(model, v)) seeds_.push_back(v);
  add_seed(model, seeds_, 1.0);
  started_ = true;
  return iterate(model, iterations);
}

StableStepEstimator::Estimate StableStepEstimator::update(const TensorMassModel& model, std::uint32_t iterations) {
  if (!started_) return estimate(model, std::max(iterations, kColdIterations));
  const std::uint32_t n = model.vertex_capacity();
  x_.resize(n, Vec3{});
  mass_.resize(n, 0.0);
  weight_.resize(n);
  // The iterate was M-normalised (x.Mx = 1). What is left of it on the vertices still free: a
  // cut that removed the tets the stiffest mode lived on takes most of it, and what remains is
  // made of softer modes: start afresh then.
  double left = 0;
  seeds_.clear();
  for (std::uint32_t v = 0; v < n; ++v) {
    if (!is_free(model, v)) continue;
    left += model.mass(VertId{v}) * dot(x_[v], x_[v]);
    // Its mass changed: a corner of a tet the cut made or removed, where its new stiff modes
    // live (a sliver's, a vertex's that lost most of its tets).
    if (model.mass(VertId{v}) != mass_[v]) seeds_.push_back(v);
  }
  if (left < kRestartBelow) return estimate(model, std::max(iterations, kColdIterations));
  // A small part of x.Mx: a mode stiffer than the old top outgrows the rest within an iteration
  // or two, while a softer one barely moves theta. (Seeds as large as the iterate swamp it:
  // theta falls to the changed region's own, softer, level.)
  add_seed(model, seeds_, kSeedShare * left);
  return iterate(model, iterations);
}

StableStepEstimator::Estimate StableStepEstimator::iterate(const TensorMassModel& model, std::uint32_t iterations) {
  const std::uint32_t n = model.vertex_capacity();
  mass_.resize(n);
  for (std::uint32_t v = 0; v < n; ++v) mass_[v] = model.mass(VertId{v});
  Estimate e;
  for (std::uint32_t v = 0; v < n; ++v)
    if (!is_free(model, v)) x_[v] = Vec3{};
  for (std::uint32_t it = 0; it < iterations; ++it) {
    model.stiffness_product(x_, kx_);
    double xkx = 0, xmx = 0;
    for (std::uint32_t v = 0; v < n; ++v) {
      if (!is_free(model, v)) continue;
      xkx += dot(x_[v], kx_[v]);
      xmx += model.mass(VertId{v}) * dot(x_[v], x_[v]);
    }
    if (!(xmx > 0)) break;  // nothing free, or an iterate that vanished
    e.theta = xkx / xmx;
    e.iterations = it + 1;
    // x <- M^-1 K x, M-normalised.
    double next = 0;
    for (std::uint32_t v = 0; v < n; ++v) {
      if (!is_free(model, v)) {
        x_[v] = Vec3{};
        continue;
      }
      x_[v] = (1.0 / model.mass(VertId{v})) * kx_[v];
      next += model.mass(VertId{v}) * dot(x_[v], x_[v]);
    }
    if (!(next > 0)) break;
    const double scale = 1.0 / std::sqrt(next);
    for (std::uint32_t v = 0; v < n; ++v) x_[v] = scale * x_[v];
  }
  e.dt = e.theta > 0 ? 2.0 / std::sqrt(kMargin * e.theta) : std::numeric_limits<double>::infinity();
  return e;
}

}  // namespace tetcut::mechanics
