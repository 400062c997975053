// I7's mesh rule (invariants/src/no_degradation.hpp): the volume of tets below theta outside the
// tool does not grow over an operation, and the shared volume of two tets it is measured by.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "core/random.hpp"
#include "no_degradation.hpp"
#include "report_builder.hpp"
#include "tet_intersection.hpp"
#include "tet_quality.hpp"

namespace tetcut::invariants::detail {
namespace {

using Tet = std::array<Vec3, 4>;

double volume(const Tet& t) {
  return std::abs(dot(t[1] - t[0], cross(t[2] - t[0], t[3] - t[0]))) / 6.0;
}

const Tet kCorner = {Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}};

Tet shifted(const Tet& t, const Vec3& by) { return {t[0] + by, t[1] + by, t[2] + by, t[3] + by}; }

TEST(TetIntersection, ATetSharesItsWholeVolumeWithItselfInEitherOrientation) {
  EXPECT_NEAR(tet_intersection_volume(kCorner, kCorner), 1.0 / 6.0, 1e-15);
  const Tet flipped = {kCorner[1], kCorner[0], kCorner[2], kCorner[3]};
  EXPECT_NEAR(tet_intersection_volume(kCorner, flipped), 1.0 / 6.0, 1e-15);
}

// The corner tet and its copy moved by half along x share {x >= 1/2, y, z >= 0, x + y + z <= 1},
// a corner tet of edge 1/2; tets apart or touching at a face share nothing.
TEST(TetIntersection, KnownVolumes) {
  EXPECT_NEAR(tet_intersection_volume(kCorner, shifted(kCorner, {0.5, 0, 0})), 1.0 / 48.0, 1e-15);
  EXPECT_NEAR(tet_intersection_volume(kCorner, shifted(kCorner, {2, 0, 0})), 0.0, 1e-15);
  const Tet below = {Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, -1}};
  EXPECT_NEAR(tet_intersection_volume(kCorner, below), 0.0, 1e-15);
}

// Against any tet p, the volumes p shares with the four pieces of q (q split at a point inside
// it) add up to the volume it shares with q; the measure is symmetric and at most the smaller
// tet's volume.
TEST(TetIntersection, AdditiveOverASplitSymmetricAndBounded) {
  SplitMix64 rng(7);
  auto point = [&] { return Vec3{rng.unit(), rng.unit(), rng.unit()}; };
  int overlapping = 0;
  for (int trial = 0; trial < 500; ++trial) {
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
  EXPECT_GT(overlapping, 50);  // the property was tested on pairs that meet
}

// A flat tet A (below theta) above a fat one B (their shared face at z = 0), both removed.
// Created as A itself, the volume below theta stays; created as A moved down into B's volume,
// each created tet keeps its host's angle (its centroid still in A), so the per-tet floor holds,
// but the bad volume now covers good volume it did not: the mesh rule objects, naming the tet.
class MeshRule : public ::testing::Test {
 protected:
  std::vector<Vec3> positions = {
      {0, 0, 0}, {1, 0, 0}, {0.5, 0.9, 0}, {0.5, 0.3, 0.08},  // A: the triangle and a low apex
      {0.5, 0.3, -0.8},                                      // B's apex, well below
      {0, 0, -0.02}, {1, 0, -0.02}, {0.5, 0.9, -0.02}, {0.5, 0.3, 0.06}};  // A moved down by 0.02
  const RawTet a{0, 1, 2, 3}, b{0, 2, 1, 4}, a_down{5, 6, 7, 8};

  CheckReport run(const RawTet& created, const Vec3* tool_centre = nullptr, double tool_radius = 0) {
    NoDegradationCheck check;
    check.begin();
    check.add_removed(0, a);
    check.add_removed(1, b);
    const auto& p = positions;
    const Vec3 &w = p[created[0]], &x = p[created[1]], &y = p[created[2]], &z = p[created[3]];
    check.add_created(2, created, tet_radius_ratio(w, x, y, z), tet_min_dihedral_deg(w, x, y, z));
    ReportBuilder report;
    std::optional<ToolRule> tool;
    if (tool_centre) tool = ToolRule{.centre = *tool_centre, .radius = tool_radius};
    check.finish(positions, positions, 0.0, 15.0, tool ? &*tool : nullptr, report);
    CheckReport out;
    report.finish(out);
    return out;
  }
};

TEST_F(MeshRule, TheShapesAreWhatTheTestNeeds) {
  const auto& p = positions;
  EXPECT_LT(tet_min_dihedral_deg(p[0], p[1], p[2], p[3]), 15.0);
  EXPECT_GT(tet_min_dihedral_deg(p[0], p[2], p[1], p[4]), 15.0);
}

TEST_F(MeshRule, ABadTetKeptInItsOwnVolumePasses) {
  const CheckReport report = run(a);
  EXPECT_TRUE(report.ok()) << to_string(report);
}

TEST_F(MeshRule, ABadTetSpreadIntoGoodVolumeIsNamed) {
  const CheckReport report = run(a_down);
  const Violation* v = report.find(Invariant::kI7Quality);
  ASSERT_NE(v, nullptr);
  EXPECT_NE(v->detail.find("outside the tool grew from"), std::string::npos) << v->detail;
  EXPECT_NE(v->detail.find("2 ("), std::string::npos) << v->detail;
  EXPECT_NE(v->detail.find("its hosts: 0 ("), std::string::npos) << v->detail;
}

// Inside the tool's ball (by its centroid) the created tet is the cut's business, not the rule's.
TEST_F(MeshRule, ATetInTheToolIsNotCounted) {
  const Vec3 centre{0.5, 0.4, 0.02};
  EXPECT_TRUE(run(a_down, &centre, 0.3).ok());
  EXPECT_FALSE(run(a_down, &centre, 0.001).ok());
}

}  // namespace
}  // namespace tetcut::invariants::detail
