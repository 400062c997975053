// quality_of and pool (invariants/src/quality_stats.cpp): the figures `tetcut stats` gives of the
// tets the cuts created are the full check's figures restricted to those tets, and pooling the
// figures of parts gives the figures of the whole.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <vector>

#include "core/random.hpp"
#include "tetcut/invariants/check.hpp"

namespace tetcut::invariants::testing {
namespace {

// Disjoint random tets (each its own four corners, positively oriented), slivers among them.
struct Soup {
  std::vector<Vec3> positions;
  std::vector<std::array<std::uint32_t, 4>> tets;
  [[nodiscard]] RawMeshView view() const { return {positions, tets}; }
};

Soup random_soup(int count) {
  SplitMix64 rng(0x29);
  Soup s;
  for (int i = 0; i < count; ++i) {
    const Vec3 offset{3.0 * i, 0, 0};
    Vec3 p[4];
    for (Vec3& x : p) x = offset + Vec3{rng.unit(), rng.unit(), rng.unit()};
    if (dot(p[1] - p[0], cross(p[2] - p[0], p[3] - p[0])) < 0) std::swap(p[2], p[3]);
    const auto base = static_cast<std::uint32_t>(s.positions.size());
    for (const Vec3& x : p) s.positions.push_back(x);
    s.tets.push_back({base, base + 1, base + 2, base + 3});
  }
  return s;
}

TEST(QualityStats, QualityOfEveryTetIsTheFullChecksQuality) {
  const Soup s = random_soup(200);
  std::vector<std::uint32_t> all(s.tets.size());
  for (std::uint32_t t = 0; t < all.size(); ++t) all[t] = t;
  const QualityStats q = quality_of(s.view(), all);
  const QualityStats full = check_raw(s.view()).quality;
  EXPECT_EQ(q.tets, full.tets);
  EXPECT_EQ(q.min_radius_ratio, full.min_radius_ratio);
  EXPECT_EQ(q.min_dihedral_deg, full.min_dihedral_deg);
  EXPECT_EQ(q.radius_ratio_histogram, full.radius_ratio_histogram);
  EXPECT_EQ(q.min_dihedral_histogram, full.min_dihedral_histogram);
  std::uint64_t binned = 0;
  for (std::uint64_t n : q.min_dihedral_histogram) binned += n;
  EXPECT_EQ(binned, q.tets);
  EXPECT_DOUBLE_EQ(q.mean_radius_ratio, full.mean_radius_ratio);
}

TEST(QualityStats, PoolingTheHalvesGivesTheWholeAndBadIdsAreSkipped) {
  const Soup s = random_soup(101);
  std::vector<std::uint32_t> first, second, all;
  for (std::uint32_t t = 0; t < s.tets.size(); ++t) {
    (t % 3 == 0 ? first : second).push_back(t);
    all.push_back(t);
  }
  QualityStats pooled;
  pool(pooled, quality_of(s.view(), first));
  pool(pooled, QualityStats{});  // nothing created: changes nothing
  pool(pooled, quality_of(s.view(), second));
  const QualityStats whole = quality_of(s.view(), all);
  EXPECT_EQ(pooled.tets, whole.tets);
  EXPECT_EQ(pooled.min_radius_ratio, whole.min_radius_ratio);
  EXPECT_EQ(pooled.min_dihedral_deg, whole.min_dihedral_deg);
  EXPECT_EQ(pooled.radius_ratio_histogram, whole.radius_ratio_histogram);
  EXPECT_EQ(pooled.min_dihedral_histogram, whole.min_dihedral_histogram);
  EXPECT_NEAR(pooled.mean_radius_ratio, whole.mean_radius_ratio, 1e-12);
  EXPECT_NEAR(pooled.mean_min_dihedral_deg, whole.mean_min_dihedral_deg, 1e-9);

  const std::uint32_t out_of_range[] = {static_cast<std::uint32_t>(s.tets.size()), 0xFFFFFFF0u};
  EXPECT_EQ(quality_of(s.view(), out_of_range).tets, 0u);
}

}  // namespace
}  // namespace tetcut::invariants::testing
