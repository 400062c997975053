// The engine's shared volume of two tets (core/tet_intersection.hpp), which the improvement
// pass's mesh rule weighs: known volumes, and additivity over a split on random pairs (the
// checker's own implementation is tested the same way, tests/invariants/mesh_rule_test.cpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "core/random.hpp"
#include "core/tet_intersection.hpp"

namespace tetcut::detail {
namespace {

using Tet = std::array<Vec3, 4>;

double volume(const Tet& t) { return std::abs(dot(t[1] - t[0], cross(t[2] - t[0], t[3] - t[0]))) / 6.0; }

const Tet kCorner = {Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}};

Tet shifted(const Tet& t, const Vec3& by) { return {t[0] + by, t[1] + by, t[2] + by, t[3] + by}; }

TEST(TetIntersection, ATetSharesItsWholeVolumeWithItselfInEitherOrientation) {
  EXPECT_NEAR(tet_intersection_volume(kCorner, kCorner), 1.0 / 6.0, 1e-15);
  const Tet flipped = {kCorner[1], kCorner[0], kCorner[2], kCorner[3]};
  EXPECT_NEAR(tet_intersection_volume(kCorner, flipped), 1.0 / 6.0, 1e-15);
}

// The corner tet and its copy moved by half along x share a corner tet of edge 1/2; tets apart,
// or touching at a face, share nothing.
TEST(TetIntersection, KnownVolumes) {
  EXPECT_NEAR(tet_intersection_volume(kCorner, shifted(kCorner, {0.5, 0, 0})), 1.0 / 48.0, 1e-15);
  EXPECT_NEAR(tet_intersection_volume(kCorner, shifted(kCorner, {2, 0, 0})), 0.0, 1e-15);
  const Tet below = {Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, -1}};
  EXPECT_NEAR(tet_intersection_volume(kCorner, below), 0.0, 1e-15);
}

// Against any tet p, the volumes p shares with the four pieces of q (q split at a point inside
// it) add up to what it shares with q; the measure is symmetric and at most the smaller tet's
// volume. Random pairs reach the most faces a clip makes (the fixed capacities' worst case).
TEST(TetIntersection, AdditiveOverASplitSymmetricAndBounded) {
  SplitMix64 rng(11);
  auto point = [&] { return Vec3{rng.unit(), rng.unit(), rng.unit()}; };
  int overlapping = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const Tet p = {point(), point(), point(), point()}, q = {point(), point(), point(), point()};
    if (volume(p) < 1e-3 || volume(q) < 1e-3) continue;
    const double whole = tet_intersection_volume(p, q);
    EXPECT_NEAR(whole, tet_intersection_volume(q, p), 1e-12);
    EXPECT_LE(whole, std::min(volume(p), volume(q)) + 1e-12);
    const Vec3 inner = 0.1 * q[0] + 0.2 * q[1] + 0.3 * q[2] + 0.4 * q[3];
    double pieces = 0;
    for (int i = 0; i < 4; ++i) {
      Tet piece = q;
      piece[i] = inner;
      pieces += tet_intersection_volume(p, piece);
    }
    EXPECT_NEAR(pieces, whole, 1e-12) << "trial " << trial;
    overlapping += whole > 0 ? 1 : 0;
  }
  EXPECT_GT(overlapping, 200);
}

}  // namespace
}  // namespace tetcut::detail
