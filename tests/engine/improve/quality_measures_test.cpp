// The improvement pass measures through fused forms of the reference measures (core/quality.hpp):
// tet_shape() must return radius_ratio() and max_dihedral_cosine() bit for bit (the floors are
// compared against them), and weighted_quality() the worse of the radius ratio and the weighted
// smallest dihedral sine to rounding; the cosine must say what the angle in degrees says.
#include <gtest/gtest.h>

#include <cmath>

#include "core/quality.hpp"
#include "core/random.hpp"

namespace tetcut {
namespace {

TEST(QualityMeasures, TheFusedFormsEqualTheReferenceOnesOnRandomTets) {
  SplitMix64 rng(7);
  auto point = [&] { return Vec3{rng.unit(), rng.unit(), rng.unit()}; };
  int positive = 0;
  for (int k = 0; k < 20000; ++k) {
    Vec3 p[4] = {point(), point(), point(), point()};
    if (k % 7 == 0) p[3] = 0.5 * (p[0] + p[1]) + 1e-9 * p[2];  // nearly flat ones too
    const TetShape s = tet_shape(p[0], p[1], p[2], p[3]);
    EXPECT_EQ(s.ratio, radius_ratio(p[0], p[1], p[2], p[3]));
    EXPECT_EQ(s.max_cosine, max_dihedral_cosine(p[0], p[1], p[2], p[3]));
    const double sine = min_dihedral_sine(p[0], p[1], p[2], p[3]);
    if (sine > 0.0) {
      ++positive;
      const double w = kDihedralSineWeight;
      const double expected = std::min(radius_ratio(p[0], p[1], p[2], p[3]), w * sine);
      EXPECT_NEAR(weighted_quality(p[0], p[1], p[2], p[3], w), expected, 1e-12 * expected + 1e-300);
      // The smallest angle from the largest cosine, as the checker measures it in degrees.
      EXPECT_NEAR(degrees_of_cosine(s.max_cosine), min_dihedral_angle_deg(p[0], p[1], p[2], p[3]), 1e-6);
    } else {
      EXPECT_EQ(weighted_quality(p[0], p[1], p[2], p[3], kDihedralSineWeight), 0.0);
    }
  }
  EXPECT_GT(positive, 1000);
}

TEST(QualityMeasures, ARegularTetAndAFlatOne) {
  const Vec3 a{1, 1, 1}, b{1, -1, -1}, c{-1, -1, 1}, d{-1, 1, -1};  // positively oriented
  const double q = weighted_quality(a, b, c, d, 1.0);
  EXPECT_NEAR(q, std::sqrt(8.0) / 3.0, 1e-12);  // the dihedral sine, 2 sqrt(2) / 3, below the ratio 1
  EXPECT_NEAR(degrees_of_cosine(tet_shape(a, b, c, d).max_cosine), 70.528779, 1e-5);
  EXPECT_EQ(weighted_quality(a, b, c, 0.5 * (a + b), 1.0), 0.0);
}

}  // namespace
}  // namespace tetcut
