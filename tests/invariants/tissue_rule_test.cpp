// I10, the tissue rule, on its own: the checker finds the tets a tool leaves with its own grid and
// its own distances, and judges what a cut reports it left.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/random.hpp"
#include "test_support.hpp"
#include "tissue_rule.hpp"

namespace tetcut::invariants::testing {
namespace {

// A 4 x 4 x 4 box of unit cubes (6 tets each, edges 1 to sqrt(3)), untouched: the local checker
// told of an empty operation with a tool judges the mesh as it stands.
TetMesh box() { return build_or_fail(make_box_mesh(4, 4, 4, {0, 0, 0}, {4, 4, 4})); }

Vec3 centroid(const TetMesh& mesh, TetId t) {
  Vec3 c{};
  for (VertId v : mesh.tet(t)) c = c + 0.25 * mesh.position(v);
  return c;
}

// The tets whose centroid lies within `radius` of `centre`, by a scan: what the rule takes when
// every edge is within D_ref.
std::vector<std::uint32_t> inside(const TetMesh& mesh, const Vec3& centre, double radius) {
  std::vector<std::uint32_t> out;
  for (std::uint32_t t = 0; t < mesh.tet_capacity(); ++t)
    if (mesh.is_live(TetId{t}) && norm(centroid(mesh, TetId{t}) - centre) <= radius) out.push_back(t);
  return out;
}

CheckReport judge(LocalChecker& checker, const TetMesh& mesh, const Vec3& centre, double radius, double d_ref,
                  const std::vector<std::uint32_t>& left) {
  CheckOptions options;
  options.tool = ToolRule{.centre = centre, .radius = radius, .d_ref = d_ref, .left = left};
  return checker.after_operation(mesh.raw_view(), std::vector<std::uint32_t>{}, std::vector<std::uint32_t>{}, options);
}

TEST(TissueRule, TissueInTheToolThatTheCutDoesNotReportIsAViolation) {
  const TetMesh mesh = box();
  LocalChecker checker(mesh.raw_view());
  const Vec3 centre{2.1, 2.05, 1.95};
  const std::vector<std::uint32_t> in_tool = inside(mesh, centre, 1.0);
  ASSERT_GT(in_tool.size(), 4u);
  // D_ref above the longest edge: every tet in the ball is tissue the cut should have taken.
  const CheckReport silent = judge(checker, mesh, centre, 1.0, 2.0, {});
  const Violation* v = silent.find(Invariant::kI10Tissue);
  ASSERT_NE(v, nullptr);
  EXPECT_EQ(v->count, in_tool.size());
  EXPECT_NE(v->detail.find("still there"), std::string::npos) << v->detail;
  // Reported, all of them: accepted.
  EXPECT_EQ(names(judge(checker, mesh, centre, 1.0, 2.0, in_tool)), "");
  // All but one: that one.
  std::vector<std::uint32_t> all_but_one(in_tool.begin() + 1, in_tool.end());
  const CheckReport one = judge(checker, mesh, centre, 1.0, 2.0, all_but_one);
  ASSERT_TRUE(has(one, Invariant::kI10Tissue));
  EXPECT_EQ(one.find(Invariant::kI10Tissue)->count, 1u);
  EXPECT_EQ(one.find(Invariant::kI10Tissue)->tets.front(), in_tool.front());
}

TEST(TissueRule, AReportedTetMustBeTissueTheCutTakes) {
  const TetMesh mesh = box();
  LocalChecker checker(mesh.raw_view());
  const Vec3 centre{2.1, 2.05, 1.95};
  std::vector<std::uint32_t> left = inside(mesh, centre, 1.0);
  // A tet far from the tool, a dead id and a duplicate: each named.
  const std::vector<std::uint32_t> far = inside(mesh, {0.5, 0.5, 0.5}, 0.6);
  ASSERT_FALSE(far.empty());
  for (const auto& [extra, what] : std::vector<std::pair<std::uint32_t, std::string>>{
           {far.front(), "not tissue"}, {mesh.tet_capacity() + 5, "not live"}, {left.front(), "twice"}}) {
    std::vector<std::uint32_t> reported = left;
    reported.push_back(extra);
    const CheckReport r = judge(checker, mesh, centre, 1.0, 2.0, reported);
    const Violation* v = r.find(Invariant::kI10Tissue);
    ASSERT_NE(v, nullptr) << what;
    EXPECT_NE(v->detail.find(what), std::string::npos) << v->detail;
  }
}

TEST(TissueRule, ATetMeetingTheToolWithAnEdgeLongerThanDRefIsAViolationWhereverItsCentroid) {
  const TetMesh mesh = box();
  LocalChecker checker(mesh.raw_view());
  // D_ref below the unit edge: every tet the ball meets has an edge too long, reported or not.
  const Vec3 centre{2.1, 2.05, 1.95};
  const CheckReport r = judge(checker, mesh, centre, 0.3, 0.5, {});
  const Violation* v = r.find(Invariant::kI10Tissue);
  ASSERT_NE(v, nullptr);
  EXPECT_NE(v->detail.find("not refined"), std::string::npos) << v->detail;
  // The count is the tets meeting the open ball, by brute force over sample points of each tet.
  std::uint64_t meeting = 0;
  for (std::uint32_t t = 0; t < mesh.tet_capacity(); ++t) {
    if (!mesh.is_live(TetId{t})) continue;
    const auto q = mesh.tet(TetId{t});
    const double d = detail::distance_to_tet(centre, mesh.position(q[0]), mesh.position(q[1]), mesh.position(q[2]),
                                             mesh.position(q[3]));
    meeting += d < 0.3 ? 1 : 0;
  }
  EXPECT_EQ(v->count, meeting);
  // A tool in the air meets nothing: no violation, whatever D_ref.
  EXPECT_EQ(names(judge(checker, mesh, {10, 10, 10}, 0.3, 0.5, {})), "");
}

TEST(TissueRule, UncuttableTetsAreNeitherTissueToTakeNorToRefine) {
  const TetMesh mesh = box();
  LocalChecker checker(mesh.raw_view());
  const Vec3 centre{2.1, 2.05, 1.95};
  const std::vector<std::uint32_t> in_tool = inside(mesh, centre, 1.0);
  checker.set_uncuttable(in_tool);
  EXPECT_EQ(names(judge(checker, mesh, centre, 1.0, 2.0, {})), "");
  // Reported left, an uncuttable tet is a misreport: the cut may not take it.
  const CheckReport r = judge(checker, mesh, centre, 1.0, 2.0, {in_tool.front()});
  ASSERT_TRUE(has(r, Invariant::kI10Tissue));
  EXPECT_NE(r.find(Invariant::kI10Tissue)->detail.find("uncuttable"), std::string::npos);
}

TEST(TissueRule, UncuttableTissueThatAnOperationRemovesIsAViolationAndItsSplitChildrenStayUncuttable) {
  TetMesh mesh = box();
  LocalChecker checker(mesh.raw_view());
  // A boundary tet, uncuttable, split at its centroid: its children fill it and stay uncuttable.
  TetId t{0};
  while (mesh.boundary_face_count(t) == 0) t = TetId{t.value + 1};
  const std::uint32_t kept[] = {t.value};
  checker.set_uncuttable(kept);
  const auto parent = mesh.tet(t);
  const VertId middle = mesh.add_vertex(centroid(mesh, t));
  std::vector<TetMesh::TetVerts> children;
  for (int i = 0; i < 4; ++i) {
    TetMesh::TetVerts child = parent;
    child[i] = middle;
    children.push_back(child);
  }
  std::vector<TetId> created;
  const TetId removed[] = {t};
  mesh.replace_tets(removed, children, &created);
  EXPECT_EQ(names(checker.after_operation(mesh.raw_view(), removed, created)), "");
  // The cut's tool over them, D_ref above every edge: the children are uncuttable, not tissue.
  EXPECT_EQ(names(judge(checker, mesh, centroid(mesh, created[0]), 0.05, 2.0, {})), "");
  // One child removed: uncuttable tissue went.
  const TetId gone[] = {created[0]};
  mesh.remove_tets(gone);
  const CheckReport r = checker.after_operation(mesh.raw_view(), gone, std::vector<TetId>{});
  ASSERT_TRUE(has(r, Invariant::kI10Tissue)) << names(r);
  EXPECT_NE(r.find(Invariant::kI10Tissue)->detail.find("uncuttable tissue went"), std::string::npos);
}

TEST(TissueRule, TheCheckersDistanceToATetAgreesWithSampling) {
  // Random tets and points: the distance is never above that of any sampled point of the tet,
  // nor below the best sample's by more than the sampling's resolution.
  SplitMix64 rng(10);
  auto point = [&] { return Vec3{rng.unit() * 2 - 1, rng.unit() * 2 - 1, rng.unit() * 2 - 1}; };
  for (int trial = 0; trial < 200; ++trial) {
    const Vec3 a = point(), b = point(), c = point(), d = point(), p = 2.0 * point();
    const double distance = detail::distance_to_tet(p, a, b, c, d);
    double best = 1e300;
    constexpr int n = 24;
    for (int i = 0; i <= n; ++i)
      for (int j = 0; i + j <= n; ++j)
        for (int k = 0; i + j + k <= n; ++k) {
          const double u = double(i) / n, v = double(j) / n, w = double(k) / n;
          best = std::min(best, norm(p - ((1 - u - v - w) * a + u * b + v * c + w * d)));
        }
    // Every point of the tet lies within a small sub-tet of the sampling's, whose diameter is at
    // most the longest edge over n.
    const double longest = std::max({norm(b - a), norm(c - a), norm(d - a), norm(c - b), norm(d - b), norm(d - c)});
    EXPECT_LE(distance, best + 1e-12);
    EXPECT_GE(distance, best - longest / n - 1e-12) << "trial " << trial;
  }
}

}  // namespace
}  // namespace tetcut::invariants::testing
