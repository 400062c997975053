// For the invariants a raw mesh can break (I1, I3, I4, I7, I9): a valid mesh passes, and
// breaking exactly one invariant makes the checker name it. I5/I6 are in manifold_test.cpp,
// I2/I8 (engine state) in engine_state_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <map>
#include <numeric>

#include "test_support.hpp"

namespace tetcut::invariants::testing {
namespace {

TEST(Invariants, IdsAndDescriptionsNameEachInvariant) {
  EXPECT_STREQ(id_string(Invariant::kI1References), "I1");
  EXPECT_STREQ(id_string(Invariant::kI5VertexShell), "I5");
  EXPECT_STREQ(id_string(Invariant::kI9Volume), "I9");
  EXPECT_STREQ(description(Invariant::kI5VertexShell), "manifold vertex shells");
  EXPECT_STREQ(description(Invariant::kI6EdgeShell), "manifold edge shells");
}

TEST(Invariants, AValidBoxPassesEveryLevelWithStatistics) {
  const RawMesh raw = make_box_mesh(3, 3, 3);
  for (CheckLevel level : {CheckLevel::kLocal, CheckLevel::kFull, CheckLevel::kExact}) {
    CheckOptions options;
    options.level = level;
    const CheckReport report = check_raw(raw, options);
    EXPECT_TRUE(report.ok()) << to_string(report);
    EXPECT_TRUE(report.notes.empty());
    EXPECT_EQ(report.tets_checked, 162u);
    EXPECT_EQ(report.vertices_checked, 64u);
    EXPECT_NEAR(report.volume, 1.0, 1e-12);
    EXPECT_EQ(report.quality.tets, 162u);
    EXPECT_GT(report.quality.min_radius_ratio, 0.5);
    EXPECT_LE(report.quality.min_radius_ratio, report.quality.mean_radius_ratio);
    EXPECT_GT(report.quality.min_dihedral_deg, 30.0);
    const auto& h = report.quality.radius_ratio_histogram;
    EXPECT_EQ(std::accumulate(h.begin(), h.end(), std::uint64_t{0}), 162u);
  }
  const TetMesh mesh = build_or_fail(raw);
  EXPECT_TRUE(check_mesh(mesh.raw_view()).ok()) << to_string(check_mesh(mesh.raw_view()));
  EXPECT_TRUE(check_mesh(mesh.raw_view(), exact()).ok()) << to_string(check_mesh(mesh.raw_view(), exact()));
}

TEST(Invariants, I1RepeatedVertexIsNamed) {
  RawMesh raw = make_box_mesh(2, 2, 2);
  raw.tets[5][2] = raw.tets[5][0];
  const CheckReport report = check_raw(raw);
  ASSERT_TRUE(has(report, Invariant::kI1References)) << to_string(report);
  EXPECT_EQ(report.find(Invariant::kI1References)->tets, std::vector<std::uint32_t>{5});
  EXPECT_EQ(report.find(Invariant::kI1References)->count, 1u);
}

TEST(Invariants, I1DanglingReferenceIsNamedWithoutCrashing) {
  RawMesh raw = make_box_mesh(2, 2, 2);
  raw.tets[7][3] = 1000;
  raw.tets[8][0] = kDeadTetMarker;  // a raw mesh has no tombstones: this is dangling too
  const CheckReport report = check_raw(raw, exact());
  ASSERT_TRUE(has(report, Invariant::kI1References)) << to_string(report);
  EXPECT_EQ(report.find(Invariant::kI1References)->count, 2u);
  EXPECT_EQ(report.find(Invariant::kI1References)->tets, (std::vector<std::uint32_t>{7, 8}));
}

TEST(Invariants, I1NonFinitePositionIsNamed) {
  RawMesh raw = make_box_mesh(1, 1, 1);
  raw.positions[3].y = std::numeric_limits<double>::quiet_NaN();
  const CheckReport report = check_raw(raw, exact());
  EXPECT_TRUE(has(report, Invariant::kI1References)) << to_string(report);
}

TEST(Invariants, I1DuplicateTetIsNamedAndOnlyThat) {
  RawMesh raw = make_box_mesh(2, 2, 2);
  auto copy = raw.tets[10];
  std::rotate(copy.begin(), copy.begin() + 2, copy.end());  // same vertex set, other order
  raw.tets.push_back(copy);
  const CheckReport report = check_raw(raw);
  EXPECT_EQ(names(report), "I1") << to_string(report);
  ASSERT_TRUE(has(report, Invariant::kI1References));
  EXPECT_EQ(report.find(Invariant::kI1References)->tets, (std::vector<std::uint32_t>{10, 48}));
}

TEST(Invariants, I3FaceSharedByThreeTetsIsNamed) {
  RawMesh raw = make_box_mesh(1, 1, 1);
  // An interior face of the Kuhn cube (two tets have it), and a third tet on it.
  std::map<std::array<std::uint32_t, 3>, int> faces;
  for (const auto& t : raw.tets)
    for (int skip = 0; skip < 4; ++skip) {
      std::array<std::uint32_t, 3> f{};
      for (int i = 0, n = 0; i < 4; ++i)
        if (i != skip) f[n++] = t[i];
      std::sort(f.begin(), f.end());
      ++faces[f];
    }
  const auto shared = std::find_if(faces.begin(), faces.end(), [](const auto& kv) { return kv.second == 2; });
  ASSERT_NE(shared, faces.end());
  const auto [a, b, c] = shared->first;
  raw.positions.push_back({3.0, -2.0, 0.7});
  raw.tets.push_back({a, b, c, static_cast<std::uint32_t>(raw.positions.size() - 1)});
  orient_positive(raw);
  const CheckReport report = check_raw(raw);
  ASSERT_TRUE(has(report, Invariant::kI3Conformity)) << to_string(report);
  EXPECT_EQ(report.find(Invariant::kI3Conformity)->count, 1u);
  EXPECT_EQ(report.find(Invariant::kI3Conformity)->vertices, (std::vector<std::uint32_t>{a, b, c}));
}

TEST(Invariants, I3SelfIntersectingBoundaryIsNamedOnlyAtTheExactLevel) {
  // Two boxes as separate components, overlapping in space: every shell is manifold, only the
  // geometry is wrong.
  RawMesh raw = make_box_mesh(2, 2, 2);
  const RawMesh other = make_box_mesh(2, 2, 2, {0.5, 0.5, 0.5}, {1, 1, 1});
  const auto offset = static_cast<std::uint32_t>(raw.positions.size());
  raw.positions.insert(raw.positions.end(), other.positions.begin(), other.positions.end());
  for (auto t : other.tets) raw.tets.push_back({t[0] + offset, t[1] + offset, t[2] + offset, t[3] + offset});

  EXPECT_TRUE(check_raw(raw).ok()) << to_string(check_raw(raw));
  const CheckReport report = check_raw(raw, exact());
  EXPECT_EQ(names(report), "I3") << to_string(report);
  const Violation* v = report.find(Invariant::kI3Conformity);
  ASSERT_NE(v, nullptr);
  EXPECT_GT(v->count, 1u);
  EXPECT_NE(v->detail.find("intersects itself"), std::string::npos) << v->detail;
}

TEST(Invariants, I3TouchingButDisjointBoxesDoNotIntersect) {
  // Two boxes at distance 1e-9: close, but the exact predicates say they do not meet.
  RawMesh raw = make_box_mesh(1, 1, 1);
  const RawMesh other = make_box_mesh(1, 1, 1, {1.0 + 1e-9, 0.0, 0.0}, {1, 1, 1});
  const auto offset = static_cast<std::uint32_t>(raw.positions.size());
  raw.positions.insert(raw.positions.end(), other.positions.begin(), other.positions.end());
  for (auto t : other.tets) raw.tets.push_back({t[0] + offset, t[1] + offset, t[2] + offset, t[3] + offset});
  const CheckReport report = check_raw(raw, exact());
  EXPECT_TRUE(report.ok()) << to_string(report);
}

TEST(Invariants, I3GeometryIsSkippedWithANoteWhenTheBoundaryIsNotAManifold) {
  RawMesh raw = make_box_mesh(1, 1, 1);
  raw = weld(raw, make_box_mesh(1, 1, 1, {1, 1, 1}, {1, 1, 1}));  // touching at one corner
  const CheckReport report = check_raw(raw, exact());
  EXPECT_TRUE(has(report, Invariant::kI5VertexShell));
  ASSERT_EQ(report.notes.size(), 1u);
  EXPECT_NE(report.notes[0].find("skipped"), std::string::npos) << report.notes[0];
}

TEST(Invariants, I4InvertedTetIsNamedAndOnlyThat) {
  RawMesh raw = make_box_mesh(2, 2, 2);
  std::swap(raw.tets[3][1], raw.tets[3][2]);
  const CheckReport report = check_raw(raw);
  EXPECT_EQ(names(report), "I4") << to_string(report);
  EXPECT_EQ(report.find(Invariant::kI4Orientation)->tets, std::vector<std::uint32_t>{3});
  EXPECT_NE(report.find(Invariant::kI4Orientation)->detail.find("inverted"), std::string::npos);
}

TEST(Invariants, I4FlatTetIsNamedByTheExactPredicate) {
  // A vertex pushed exactly into the plane of its opposite face.
  RawMesh raw{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.25, 0.25, 0.0}}, {{0, 1, 2, 3}}};
  const CheckReport report = check_raw(raw);
  EXPECT_EQ(names(report), "I4") << to_string(report);
  EXPECT_NE(report.find(Invariant::kI4Orientation)->detail.find("flat"), std::string::npos);
}

TEST(Invariants, I7QualityFloorIsEnforcedOnlyWhenSet) {
  RawMesh raw = make_box_mesh(2, 2, 2);
  CheckOptions options;
  options.radius_ratio_floor = 0.3;
  EXPECT_TRUE(check_raw(raw, options).ok());
  // The centre vertex pushed along the main diagonal: the tets of the corner cube it moves
  // into flatten (still positive), the others stretch.
  raw.positions[13] = {0.9, 0.9, 0.9};
  const CheckReport report = check_raw(raw, options);
  EXPECT_EQ(names(report), "I7") << to_string(report);
  EXPECT_LT(report.quality.min_radius_ratio, 0.3);
  CheckOptions no_floor;
  EXPECT_TRUE(check_raw(raw, no_floor).ok());
}

TEST(Invariants, I9VolumeIsComparedWithTheExpectedOne) {
  const RawMesh raw = make_box_mesh(3, 3, 3, {0, 0, 0}, {2, 1, 1});
  CheckOptions options;
  options.expected_volume = 2.0;
  EXPECT_TRUE(check_raw(raw, options).ok());
  options.expected_volume = 2.0 * (1 + 1e-6);
  const CheckReport report = check_raw(raw, options);
  EXPECT_EQ(names(report), "I9") << to_string(report);
}

TEST(Invariants, ReportsNameTheOperation) {
  RawMesh raw = make_box_mesh(1, 1, 1);
  std::swap(raw.tets[0][1], raw.tets[0][2]);
  CheckOptions options;
  options.operation = "cut 7";
  const CheckReport report = check_raw(raw, options);
  EXPECT_EQ(report.operation, "cut 7");
  const std::string text = to_string(report);
  EXPECT_NE(text.find("I4 orientation"), std::string::npos) << text;
  EXPECT_NE(text.find("after cut 7"), std::string::npos) << text;
}

}  // namespace
}  // namespace tetcut::invariants::testing
