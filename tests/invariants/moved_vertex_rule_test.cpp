// I8's rule for a vertex that was there before an operation and moved (the improvement pass
// smooths within a cut's reach): reported in CheckOptions::moved, within the cut's reach, where
// its entry's weights put it, and with every tet around it remade. The meshes are raw arrays fed
// to the LocalChecker as views: the engine has no public way to move a vertex it did not just
// make, and the checker needs nothing but the arrays.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "tetcut/invariants/check.hpp"
#include "tetcut/predicates.hpp"

namespace tetcut::invariants::testing {
namespace {

using Tet = std::array<std::uint32_t, 4>;

// The unit cube's 8 corners and its centre (vertex 8), each face's two triangles coned to the
// centre: 12 congruent tets, all around the one interior vertex.
constexpr std::uint32_t kCentre = 8;

struct Mesh {
  std::vector<Vec3> positions;
  std::vector<Tet> tets;
  [[nodiscard]] RawMeshView view() const { return {.positions = positions, .tets = tets}; }
};

Mesh cube_around_its_centre() {
  Mesh mesh;
  for (int i = 0; i < 8; ++i)
    mesh.positions.push_back({static_cast<double>(i & 1), static_cast<double>((i >> 1) & 1), static_cast<double>(i >> 2)});
  mesh.positions.push_back({0.5, 0.5, 0.5});
  // Each face as a loop of corners (corner i at (i & 1, i >> 1 & 1, i >> 2)).
  const std::uint32_t faces[6][4] = {{0, 1, 3, 2}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 3, 7, 5}};
  for (const auto& f : faces) {
    for (const Tet& t : {Tet{f[0], f[1], f[2], kCentre}, Tet{f[0], f[2], f[3], kCentre}}) {
      Tet oriented = t;
      const auto& p = mesh.positions;
      if (orientation(p[t[0]], p[t[1]], p[t[2]], p[t[3]]) < 0) std::swap(oriented[1], oriented[2]);
      mesh.tets.push_back(oriented);
    }
  }
  return mesh;
}

std::vector<std::uint32_t> all_tets(const Mesh& mesh) {
  std::vector<std::uint32_t> ids(mesh.tets.size());
  for (std::uint32_t t = 0; t < ids.size(); ++t) ids[t] = t;
  return ids;
}

double volume6(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) { return dot(b - a, cross(c - a, d - a)); }

// `to` as an affine combination of the corners of the tet of `mesh` that holds it (barycentric
// coordinates): what the engine reports for a smoothed vertex.
RawMovedVertex move_entry(const Mesh& mesh, std::uint32_t vertex, const Vec3& to) {
  for (const Tet& t : mesh.tets) {
    const auto& p = mesh.positions;
    const double whole = volume6(p[t[0]], p[t[1]], p[t[2]], p[t[3]]);
    RawMovedVertex entry{.vertex = vertex, .from = t, .count = 4};
    bool inside = true;
    for (int i = 0; i < 4; ++i) {
      std::array<Vec3, 4> x = {p[t[0]], p[t[1]], p[t[2]], p[t[3]]};
      x[i] = to;
      entry.weight[i] = volume6(x[0], x[1], x[2], x[3]) / whole;
      inside = inside && entry.weight[i] >= 0.0;
    }
    if (inside) return entry;
  }
  ADD_FAILURE() << "no tet holds the new position";
  return {};
}

// A cut's ball below the cube, meeting none of its tets (so I10 has nothing to say), whose reach
// (radius + d_ref = 1.2) covers the centre at 0.8.
ToolRule tool_below(double d_ref = 1.0) { return {.centre = {0.5, 0.5, -0.3}, .radius = 0.2, .d_ref = d_ref}; }

const Vec3 kMovedCentre{0.53, 0.52, 0.51};

// The centre moved to kMovedCentre and its whole star remade under the same ids, checked with
// `options` (`moved` filled from `entries`).
CheckReport move_the_centre(CheckOptions options, const std::vector<RawMovedVertex>& entries,
                            const std::vector<std::uint32_t>& remade) {
  const Mesh before = cube_around_its_centre();
  LocalChecker local(before.view());
  Mesh after = before;
  after.positions[kCentre] = kMovedCentre;
  options.moved = entries;
  return local.after_operation(after.view(), remade, remade, options);
}

// An I8 violation whose detail names the centre (vertex 8) and says `words`, listing the centre.
::testing::AssertionResult i8_naming_the_centre(const CheckReport& report, const std::string& words) {
  const Violation* v = report.find(Invariant::kI8Bookkeeping);
  if (v == nullptr) return ::testing::AssertionFailure() << "no I8 violation: " << to_string(report);
  if (v->detail.find("vertex 8") == std::string::npos || v->detail.find(words) == std::string::npos)
    return ::testing::AssertionFailure() << "the I8 detail does not name vertex 8 with \"" << words << "\": " << v->detail;
  if (v->vertices != std::vector<std::uint32_t>{kCentre}) return ::testing::AssertionFailure() << "the I8 vertices are not the centre";
  return ::testing::AssertionSuccess();
}

TEST(MovedVertexRule, TheMeshIsValidBeforeTheMove) {
  const Mesh mesh = cube_around_its_centre();
  EXPECT_TRUE(check_raw(mesh.view()).ok()) << to_string(check_raw(mesh.view()));
}

TEST(MovedVertexRule, AReportedMoveWithinReachWithItsStarRemadePasses) {
  const Mesh before = cube_around_its_centre();
  const CheckReport report = move_the_centre({.tool = tool_below()}, {move_entry(before, kCentre, kMovedCentre)},
                                             all_tets(before));
  EXPECT_TRUE(report.ok()) << to_string(report);
  EXPECT_EQ(report.quality.tets, 12u);
}

TEST(MovedVertexRule, AnUnreportedMoveIsI8) {
  const Mesh before = cube_around_its_centre();
  const CheckReport report = move_the_centre({.tool = tool_below()}, {}, all_tets(before));
  EXPECT_TRUE(i8_naming_the_centre(report, "did not report it"));
}

TEST(MovedVertexRule, AMoveBeyondTheCutsReachIsI8) {
  const Mesh before = cube_around_its_centre();
  const CheckReport report = move_the_centre({.tool = tool_below(0.5)}, {move_entry(before, kCentre, kMovedCentre)},
                                             all_tets(before));
  EXPECT_TRUE(i8_naming_the_centre(report, "beyond the cut's reach"));
}

TEST(MovedVertexRule, AReportedMoveWhoseWeightsPutTheVertexElsewhereIsI8) {
  const Mesh before = cube_around_its_centre();
  RawMovedVertex entry = move_entry(before, kCentre, kMovedCentre);
  std::swap(entry.weight[0], entry.weight[1]);  // still summing to 1, another point
  const CheckReport report = move_the_centre({.tool = tool_below()}, {entry}, all_tets(before));
  EXPECT_TRUE(i8_naming_the_centre(report, "from where it is"));
}

TEST(MovedVertexRule, AMovedVertexWithAKeptTetIsI8NamingTheTet) {
  const Mesh before = cube_around_its_centre();
  std::vector<std::uint32_t> remade = all_tets(before);
  remade.erase(remade.begin() + 5);  // tet 5 keeps its id and its vertices, and changes shape
  const CheckReport report = move_the_centre({.tool = tool_below()}, {move_entry(before, kCentre, kMovedCentre)}, remade);
  EXPECT_TRUE(i8_naming_the_centre(report, "tet 5 around it was kept"));
  EXPECT_EQ(report.find(Invariant::kI8Bookkeeping)->tets, std::vector<std::uint32_t>{5});
}

TEST(MovedVertexRule, AMoveByAnOperationWithoutAToolIsI8) {
  const Mesh before = cube_around_its_centre();
  const CheckReport report = move_the_centre({}, {move_entry(before, kCentre, kMovedCentre)}, all_tets(before));
  EXPECT_TRUE(i8_naming_the_centre(report, "without a tool"));
}

TEST(MovedVertexRule, AVertexReportedMovedThatDidNotMoveIsI8) {
  const Mesh before = cube_around_its_centre();
  LocalChecker local(before.view());
  const std::vector<RawMovedVertex> entries = {{.vertex = kCentre, .from = {kCentre}, .weight = {1.0}, .count = 1}};
  const CheckReport report =
      local.after_operation(before.view(), all_tets(before), all_tets(before), {.tool = tool_below(), .moved = entries});
  EXPECT_TRUE(i8_naming_the_centre(report, "reported moved but it did not move"));
}

// The checker's copy of the positions follows a reported move: remaking the star again, without
// moving anything, is no move; moving back, reported, is one more.
TEST(MovedVertexRule, TheCheckerRemembersWhereAMovedVertexWent) {
  const Mesh before = cube_around_its_centre();
  LocalChecker local(before.view());
  Mesh after = before;
  after.positions[kCentre] = kMovedCentre;
  const std::vector<RawMovedVertex> there = {move_entry(before, kCentre, kMovedCentre)};
  const std::vector<std::uint32_t> star = all_tets(before);
  const CheckReport moved = local.after_operation(after.view(), star, star, {.tool = tool_below(), .moved = there});
  EXPECT_TRUE(moved.ok()) << to_string(moved);
  const CheckReport remade = local.after_operation(after.view(), star, star, {.tool = tool_below()});
  EXPECT_TRUE(remade.ok()) << to_string(remade);
  const std::vector<RawMovedVertex> back = {move_entry(after, kCentre, before.positions[kCentre])};
  const CheckReport moved_back = local.after_operation(before.view(), star, star, {.tool = tool_below(), .moved = back});
  EXPECT_TRUE(moved_back.ok()) << to_string(moved_back);
}

// I7 measures the hosts as they were: the created tets are located by their centroids (new
// positions) in the removed tets at their old positions. The cube's 12 tets are congruent; moving
// the centre towards +x flattens the tets on that face. With the floors at their maximum (F = 1,
// theta = 90: every created tet is held to its hosts' own quality) those are worse than the tets
// they replaced, named with their host; measured at the new positions, each host would be its
// created tet itself and nothing would be worse.
TEST(MovedVertexRule, I7LocatesHostsAtTheirOldPositionsAfterAMove) {
  const Mesh before = cube_around_its_centre();
  const std::vector<RawMovedVertex> entries = {move_entry(before, kCentre, kMovedCentre)};
  const CheckReport fine = move_the_centre({.tool = tool_below()}, entries, all_tets(before));
  EXPECT_FALSE(fine.find(Invariant::kI7Quality)) << to_string(fine);
  const CheckReport strict =
      move_the_centre({.quality_floor = 1.0, .min_dihedral_deg = 90.0, .tool = tool_below()}, entries, all_tets(before));
  const Violation* v = strict.find(Invariant::kI7Quality);
  ASSERT_NE(v, nullptr) << to_string(strict);
  EXPECT_LT(v->count, 12u);  // the tets on the far faces got no worse
  EXPECT_NE(v->detail.find("its hosts: " + std::to_string(v->tets[0]) + " ("), std::string::npos) << v->detail;
  EXPECT_FALSE(strict.find(Invariant::kI8Bookkeeping)) << to_string(strict);
}

}  // namespace
}  // namespace tetcut::invariants::testing
