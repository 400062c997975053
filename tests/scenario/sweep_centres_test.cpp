// scenario::sweep_centres: where `tetcut cut`, a scenario's sweep, `tetcut simulate --sweep` and
// Python's Cutter.sweep put their cuts; scenario::sweep_cuts: the balls there, or the capsules
// joining them (swept).
#include <gtest/gtest.h>

#include <cmath>

#include "tetcut/scenario/sweep.hpp"

namespace tetcut::scenario {
namespace {

TEST(SweepCentres, TheEndIsCutWhenAWholeNumberOfStepsAwayInDecimalsThoughNotInDoubles) {
  const Vec3 from{-0.8, 0, -0.2}, to{0.6, 0, -0.2};
  ASSERT_LT(norm(to - from) / 0.05, 28.0);  // 27.999999999999996: floor() alone drops the end
  const std::vector<Vec3> centres = sweep_centres(from, to, 0.05);
  ASSERT_EQ(centres.size(), 29u);
  EXPECT_EQ(sweep_cut_count(from, to, 0.05), 29u);
  EXPECT_EQ(centres.front().x, from.x);
  EXPECT_NEAR(centres.back().x, to.x, 1e-12);
  for (std::size_t k = 1; k < centres.size(); ++k) EXPECT_NEAR(norm(centres[k] - centres[k - 1]), 0.05, 1e-12);
}

TEST(SweepCentres, ASweepShortOfItsEndStopsBeforeIt) {
  // 0.95 / 0.1 = 9.5: ten cuts, the last at 0.9; the end is not added as a shorter step.
  const std::vector<Vec3> centres = sweep_centres({0, 0, 0}, {0.95, 0, 0}, 0.1);
  ASSERT_EQ(centres.size(), 10u);
  EXPECT_NEAR(centres.back().x, 0.9, 1e-12);
  // Just past the tolerance (a millionth of a step short): still short.
  EXPECT_EQ(sweep_cut_count({0, 0, 0}, {1.0 - 1e-7, 0, 0}, 0.1), 10u);
}

TEST(SweepCentres, TheCentresAreThoseOfEverySweepBefore) {
  // The pinned scenario hashes rest on these bits: k * step / length along the segment.
  const Vec3 from{95, 15, 100}, to{95, 200, 100};
  const std::vector<Vec3> centres = sweep_centres(from, to, 4);
  const double length = norm(to - from);
  ASSERT_EQ(centres.size(), static_cast<std::size_t>(std::floor(length / 4)) + 1);
  for (std::size_t k = 0; k < centres.size(); ++k) {
    const Vec3 before = k == 0 ? from : from + (static_cast<double>(k) * 4 / length) * (to - from);
    EXPECT_EQ(centres[k].x, before.x);
    EXPECT_EQ(centres[k].y, before.y);
    EXPECT_EQ(centres[k].z, before.z);
  }
}

TEST(SweepCentres, AZeroLengthSweepIsOneCutAtItsStart) {
  const std::vector<Vec3> centres = sweep_centres({1, 2, 3}, {1, 2, 3}, 0.5);
  ASSERT_EQ(centres.size(), 1u);
  EXPECT_EQ(centres[0].y, 2.0);
  EXPECT_EQ(sweep_centres({0, 0, 0}, {0.3, 0, 0}, 1.0).size(), 1u);  // shorter than a step: its start alone
}

TEST(SweepCuts, ASweptSweepJoinsEachCentreToTheNextAndAPlainOneIsBalls) {
  const Vec3 from{-0.8, 0, -0.2}, to{0.6, 0, -0.2};
  const std::vector<Vec3> centres = sweep_centres(from, to, 0.05);
  const std::vector<CutTool> balls = sweep_cuts(from, to, 0.05, false);
  const std::vector<CutTool> capsules = sweep_cuts(from, to, 0.05, true);
  ASSERT_EQ(balls.size(), centres.size());
  ASSERT_EQ(capsules.size(), centres.size() - 1);
  for (std::size_t k = 0; k < balls.size(); ++k) {
    EXPECT_EQ(balls[k].centre, centres[k]);
    EXPECT_FALSE(balls[k].end);
  }
  for (std::size_t k = 0; k < capsules.size(); ++k) {
    EXPECT_EQ(capsules[k].centre, centres[k]);
    ASSERT_TRUE(capsules[k].end);
    EXPECT_EQ(*capsules[k].end, centres[k + 1]);  // the same bits: the capsules meet end to end
  }
  // One centre: one ball, swept or not.
  const std::vector<CutTool> one = sweep_cuts({1, 2, 3}, {1, 2, 3}, 0.5, true);
  ASSERT_EQ(one.size(), 1u);
  EXPECT_FALSE(one[0].end);
}

}  // namespace
}  // namespace tetcut::scenario
