// The checker's own quality measures (invariants/src/tet_quality.cpp, written from the
// definitions) and the engine's (engine/src/core/quality.cpp, other formulas) agree to rounding:
// two witnesses of I7, neither a copy of the other.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "core/quality.hpp"
#include "core/random.hpp"
#include "tet_quality.hpp"

namespace tetcut::invariants::testing {
namespace {

using detail::tet_min_dihedral_deg;
using detail::tet_radius_ratio;

constexpr double kRatioTolerance = 1e-12;     // radius ratio is in [0, 1]
constexpr double kDihedralTolerance = 1e-9;   // degrees

const Vec3 kRegular[4] = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};

TEST(CheckerQuality, TheRegularTetMeasuresOneAndArccosOneThird) {
  const Vec3* p = kRegular;
  EXPECT_NEAR(tet_radius_ratio(p[0], p[1], p[2], p[3]), 1.0, 1e-15);
  EXPECT_NEAR(tet_min_dihedral_deg(p[0], p[1], p[2], p[3]), std::acos(1.0 / 3.0) * 180.0 / std::numbers::pi, 1e-12);
}

TEST(CheckerQuality, AFlatTetMeasuresZero) {
  const Vec3 a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0}, d{0.3, 0.3, 0};
  EXPECT_EQ(tet_radius_ratio(a, b, c, d), 0.0);
  EXPECT_EQ(tet_min_dihedral_deg(a, b, c, d), 0.0);
  EXPECT_EQ(tet_min_dihedral_deg(a, b, {2, 0, 0}, {0, 0, 1}), 0.0);  // a degenerate face
}

TEST(CheckerQuality, AnInvertedTetMeasuresAsItsMirrorImage) {
  const Vec3 a{0, 0, 0}, b{1, 0.1, 0}, c{0.2, 1, 0}, d{0.3, 0.2, 0.7};
  auto mirror = [](const Vec3& p) { return Vec3{-p.x, p.y, p.z}; };
  EXPECT_EQ(tet_radius_ratio(mirror(a), mirror(b), mirror(c), mirror(d)), tet_radius_ratio(a, b, c, d));
  EXPECT_EQ(tet_min_dihedral_deg(mirror(a), mirror(b), mirror(c), mirror(d)), tet_min_dihedral_deg(a, b, c, d));
  EXPECT_GT(tet_radius_ratio(a, b, c, d), 0.5);
}

// Random tets (corners uniform in a cube, so slivers and needles come up too) and the same tets
// scaled far from the origin: the two implementations agree to rounding.
TEST(CheckerQuality, AgreesWithTheEnginesMeasuresOnRandomTets) {
  SplitMix64 rng(0x17);
  double worst_ratio = 0.0, worst_dihedral = 0.0, smallest_ratio = 1.0;
  for (int i = 0; i < 20000; ++i) {
    const double scale = i % 2 == 0 ? 1.0 : 1e3;
    const Vec3 offset = i % 4 == 3 ? Vec3{1e4, -2e4, 3e4} : Vec3{};
    Vec3 p[4];
    for (Vec3& x : p) x = offset + scale * Vec3{rng.unit(), rng.unit(), rng.unit()};
    const double ratio = tet_radius_ratio(p[0], p[1], p[2], p[3]);
    const double engine_ratio = radius_ratio(p[0], p[1], p[2], p[3]);
    const double dihedral = tet_min_dihedral_deg(p[0], p[1], p[2], p[3]);
    const double engine_dihedral = min_dihedral_angle_deg(p[0], p[1], p[2], p[3]);
    ASSERT_NEAR(ratio, engine_ratio, kRatioTolerance) << "tet " << i;
    ASSERT_NEAR(dihedral, engine_dihedral, kDihedralTolerance) << "tet " << i;
    worst_ratio = std::max(worst_ratio, std::abs(ratio - engine_ratio));
    worst_dihedral = std::max(worst_dihedral, std::abs(dihedral - engine_dihedral));
    smallest_ratio = std::min(smallest_ratio, ratio);
  }
  // The sample reached slivers, where the formulas differ most.
  EXPECT_LT(smallest_ratio, 1e-3);
  ::testing::Test::RecordProperty("worst_ratio_difference", ::testing::PrintToString(worst_ratio));
  ::testing::Test::RecordProperty("worst_dihedral_difference_deg", ::testing::PrintToString(worst_dihedral));
  ::testing::Test::RecordProperty("smallest_ratio", ::testing::PrintToString(smallest_ratio));
}

}  // namespace
}  // namespace tetcut::invariants::testing
