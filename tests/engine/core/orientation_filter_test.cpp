// The inline filter of orientation() (predicates.hpp) against Shewchuk's adaptive predicate it
// stands in front of: the same sign on every input, and above all on the inputs the filter exists
// for, points on or within rounding of a plane, where a plain determinant gets the sign wrong.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>

#include "tetcut/predicates.hpp"

namespace tetcut {
namespace {

struct Counts {
  std::uint64_t cases = 0, flat = 0, plain_wrong = 0;
};

// Compares the two on (a, b, c, d) and on its even and odd permutations (the sign must follow).
void expect_same(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, Counts& counts) {
  const Vec3 tet[4] = {a, b, c, d};
  const int swaps[3][4] = {{0, 1, 2, 3}, {1, 0, 2, 3}, {2, 0, 1, 3}};
  for (const auto& s : swaps) {
    const Vec3 &p = tet[s[0]], &q = tet[s[1]], &r = tet[s[2]], &t = tet[s[3]];
    const int exact = detail::orientation_exact(p, q, r, t);
    ASSERT_EQ(orientation(p, q, r, t), exact) << p.x << ' ' << p.y << ' ' << p.z << " | " << q.x << ' ' << q.y << ' ' << q.z
                                              << " | " << r.x << ' ' << r.y << ' ' << r.z << " | " << t.x << ' ' << t.y << ' '
                                              << t.z;
    ++counts.cases;
    counts.flat += exact == 0;
    const double plain = dot(q - p, cross(r - p, t - p));
    counts.plain_wrong += ((plain > 0) - (plain < 0)) != exact;
  }
}

TEST(OrientationFilter, AgreesWithTheExactPredicateOnGeneralPositions) {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> coordinate(-100.0, 100.0);
  auto point = [&] { return Vec3{coordinate(random), coordinate(random), coordinate(random)}; };
  Counts counts;
  for (int i = 0; i < 20000; ++i) expect_same(point(), point(), point(), point(), counts);
  EXPECT_EQ(counts.cases, 60000u);
}

// d on the plane of (a, b, c) as an affine combination, then nudged by a few ulps or not at all:
// the rounding of the combination leaves d just off the plane, on either side, or on it.
TEST(OrientationFilter, AgreesWithTheExactPredicateNearAPlane) {
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> coordinate(-100.0, 100.0), weight(-1.0, 2.0);
  std::uniform_int_distribution<int> ulps(-3, 3), scale(-30, 30);
  Counts counts;
  for (int i = 0; i < 100000; ++i) {
    const double s = std::ldexp(1.0, scale(random));  // tiny to huge meshes
    const Vec3 a{s * coordinate(random), s * coordinate(random), s * coordinate(random)};
    const Vec3 b{s * coordinate(random), s * coordinate(random), s * coordinate(random)};
    const Vec3 c{s * coordinate(random), s * coordinate(random), s * coordinate(random)};
    const double u = weight(random), v = weight(random);
    Vec3 d = a + u * (b - a) + v * (c - a);
    const int n = ulps(random);
    for (int k = 0; k < std::abs(n); ++k) d.z = std::nextafter(d.z, n > 0 ? INFINITY : -INFINITY);
    expect_same(a, b, c, d, counts);
  }
  // The test means something only if the inputs reach the cases a plain determinant misjudges.
  EXPECT_GT(counts.plain_wrong, 1000u);
}

// Exactly flat tets on small integer grids (every coordinate exact): the filter must leave each
// to the exact stages, which answer 0.
TEST(OrientationFilter, AgreesWithTheExactPredicateOnExactlyFlatTets) {
  std::mt19937_64 random(13);
  std::uniform_int_distribution<int> small(-8, 8);
  Counts counts;
  for (int i = 0; i < 20000; ++i) {
    const Vec3 a{double(small(random)), double(small(random)), 0.0};
    const Vec3 b{double(small(random)), double(small(random)), 0.0};
    const Vec3 c{double(small(random)), double(small(random)), 0.0};
    const Vec3 d{double(small(random)), double(small(random)), 0.0};
    // Tilted by an exact map (x, y, z) -> (x, y, x + 2y): still flat, no coordinate rounded.
    auto tilt = [](Vec3 p) { return Vec3{p.x, p.y, p.x + 2.0 * p.y}; };
    expect_same(tilt(a), tilt(b), tilt(c), tilt(d), counts);
  }
  EXPECT_EQ(counts.flat, counts.cases);
}

}  // namespace
}  // namespace tetcut
