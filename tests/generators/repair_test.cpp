// Repair: a manifold, positively oriented mesh with the smallest change, every change reported.
#include <gtest/gtest.h>

#include <algorithm>

#include "test_meshes.hpp"
#include "tetcut/canonical_hash.hpp"
#include "tetcut/generators/repair.hpp"
#include "tetcut/generators/singularities.hpp"
#include "tetcut/invariants/check.hpp"
#include "tetcut/mesh_builder.hpp"

namespace tetcut::generators {
namespace {

using test::glue;
using test::vertex_at;

void expect_manifold(const RepairResult& r) {
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_TRUE(find_singularities(*r.mesh).empty());
  const BuildResult b = build_mesh(*r.mesh, BuildOptions{.reorient_inverted = false, .require_manifold = true});
  EXPECT_TRUE(b.ok()) << (b.problems.empty() ? "" : b.problems.front().message);
  invariants::CheckOptions options;
  options.level = invariants::CheckLevel::kExact;
  const auto report = invariants::check_raw(*r.mesh, options);
  for (const auto& v : report.violations) ADD_FAILURE() << invariants::id_string(v.id) << ": " << v.detail;
}

std::vector<std::uint32_t> removed_tets(const RepairReport& report) {
  std::vector<std::uint32_t> out;
  for (const auto& c : report.changes)
    if (c.action != RepairAction::kReoriented) out.push_back(c.tet);
  std::sort(out.begin(), out.end());
  return out;
}

TEST(Repair, AManifoldMeshIsLeftUnchanged) {
  const RawMesh box = make_box_mesh(2, 2, 2);
  const RepairResult r = repair_mesh(box);
  expect_manifold(r);
  EXPECT_TRUE(r.report.unchanged());
  EXPECT_EQ(r.mesh->tets, box.tets);
  EXPECT_EQ(r.mesh->positions, box.positions);
}

TEST(Repair, InvertedTetsAreReorientedNotRemoved) {
  const RawMesh box = make_box_mesh(2, 2, 2);
  RawMesh flipped = box;
  std::vector<std::uint32_t> inverted;
  for (std::uint32_t t = 0; t < flipped.tets.size(); t += 3) {
    std::swap(flipped.tets[t][0], flipped.tets[t][1]);
    inverted.push_back(t);
  }
  const RepairResult r = repair_mesh(flipped);
  expect_manifold(r);
  EXPECT_EQ(r.report.count(RepairAction::kReoriented), inverted.size());
  EXPECT_EQ(r.report.removed_tets(), 0u);
  EXPECT_EQ(canonical_hash(*r.mesh), canonical_hash(box));
}

TEST(Repair, ASingularVertexKeepsTheLargerComponent) {
  // A 2x2x2 box and a unit cube touching its corner (2,2,2): the unit cube's tets at the corner go.
  const RawMesh big = make_box_mesh(2, 2, 2, {0, 0, 0}, {2, 2, 2});
  const RawMesh m = glue(big, make_box_mesh(1, 1, 1, {2, 2, 2}));
  const auto corner = vertex_at(m, {2, 2, 2});
  std::uint32_t small_at_corner = 0, big_at_corner = 0;
  for (std::uint32_t t = 0; t < m.tets.size(); ++t)
    if (test::contains(m.tets[t], corner)) ++(t < big.tets.size() ? big_at_corner : small_at_corner);
  ASSERT_EQ(big_at_corner, small_at_corner);  // a tie: the first component (the big box) stays

  const RepairResult r = repair_mesh(m);
  expect_manifold(r);
  const auto removed = removed_tets(r.report);
  EXPECT_EQ(removed.size(), small_at_corner);
  for (auto t : removed) {
    EXPECT_GE(t, big.tets.size());
    EXPECT_TRUE(test::contains(m.tets[t], corner));
  }
  EXPECT_EQ(r.report.count(RepairAction::kRemovedSingularVertex), removed.size());
  EXPECT_EQ(r.report.singular_vertices_fixed, 1u);
}

TEST(Repair, ASingularEdgeKeepsTheLargerComponentOfItsShell) {
  const RawMesh big = make_box_mesh(2, 2, 1, {0, 0, 0}, {2, 2, 1});
  const RawMesh m = glue(big, make_box_mesh(1, 1, 1, {2, 2, 0}));
  const RepairResult r = repair_mesh(m);
  expect_manifold(r);
  EXPECT_GE(r.report.singular_edges_fixed, 1u);
  // Both halves of the edge's shell have two tets: the tie keeps the first (the big box's).
  for (const auto& c : r.report.changes)
    if (c.action == RepairAction::kRemovedSingularEdge) {
      EXPECT_GE(c.tet, big.tets.size());
    }
  EXPECT_EQ(r.report.count(RepairAction::kRemovedSingularEdge), 2u);
  // The unit cube still touches the big box at the edge's ends; each vertex then keeps its larger
  // side. Never more than a handful of tets go.
  EXPECT_LE(r.report.removed_tets(), 4u);
}

TEST(Repair, APinchedLinkIsOpenedByRemovingPartOfTheShell) {
  const RawMesh pinched = test::pinched_box();
  const auto centre = vertex_at(pinched, {1, 1, 1});
  std::uint32_t shell = 0;
  for (const auto& t : pinched.tets) shell += test::contains(t, centre) ? 1 : 0;
  const RepairResult r = repair_mesh(pinched);
  expect_manifold(r);
  EXPECT_GT(r.report.removed_tets(), 0u);
  EXPECT_LT(r.report.removed_tets(), shell) << "the whole shell of the pinched vertex went";
}

TEST(Repair, FlatDuplicateAndInvalidTetsAreRemovedAndTheirVerticesDropped) {
  const RawMesh box = make_box_mesh(1, 1, 2);
  RawMesh m = box;
  const auto n = static_cast<std::uint32_t>(m.positions.size());
  m.positions.push_back({5, 0, 0});
  m.positions.push_back({6, 0, 0});
  m.positions.push_back({5, 1, 0});
  m.positions.push_back({6, 1, 0});  // four coplanar points
  m.tets.push_back({n, n + 1, n + 2, n + 3});
  m.tets.push_back(box.tets[3]);          // duplicate
  m.tets.push_back({0, 0, 1, 2});         // repeated vertex
  m.tets.push_back({0, 1, 2, n + 40});    // dangling
  const RepairResult r = repair_mesh(m);
  expect_manifold(r);
  EXPECT_EQ(r.report.count(RepairAction::kRemovedFlat), 1u);
  EXPECT_EQ(r.report.count(RepairAction::kRemovedDuplicate), 1u);
  EXPECT_EQ(r.report.count(RepairAction::kRemovedInvalid), 2u);
  EXPECT_EQ(r.report.dropped_vertices, (std::vector<std::uint32_t>{n, n + 1, n + 2, n + 3}));
  EXPECT_EQ(canonical_hash(*r.mesh), canonical_hash(box));
}

TEST(Repair, AThirdTetOnAFaceIsRemoved) {
  RawMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, 2}, {0.2, 0.2, -1}};
  m.tets = {{0, 1, 2, 3}, {0, 1, 2, 4}, {0, 2, 1, 5}};  // tets 0 and 1 overlap above the face
  const RepairResult r = repair_mesh(m);
  expect_manifold(r);
  EXPECT_EQ(removed_tets(r.report), (std::vector<std::uint32_t>{1}));
  EXPECT_EQ(r.report.count(RepairAction::kRemovedOverSharedFace), 1u);
}

TEST(Repair, AMeshThatEmptiesOutGetsAClearMessage) {
  RawMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  m.tets = {{0, 1, 2, 3}};
  const RepairResult r = repair_mesh(m);
  EXPECT_FALSE(r.ok());
  EXPECT_NE(r.error.find("cannot be repaired"), std::string::npos) << r.error;
  EXPECT_EQ(r.report.count(RepairAction::kRemovedFlat), 1u);
}

TEST(Repair, IsDeterministic) {
  const RawMesh m = glue(make_box_mesh(2, 2, 1, {0, 0, 0}, {2, 2, 1}), make_box_mesh(1, 1, 1, {2, 2, 0}));
  const RepairResult a = repair_mesh(m);
  const RepairResult b = repair_mesh(m);
  ASSERT_TRUE(a.ok() && b.ok());
  EXPECT_EQ(a.mesh->tets, b.mesh->tets);
  EXPECT_EQ(a.report.changes.size(), b.report.changes.size());
}

}  // namespace
}  // namespace tetcut::generators
