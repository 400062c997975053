// Every selected tet is removed or counted (the removal core's first promise): after every cut
// of a sweep, on every bundled mesh and with every strategy, no live tet has its centroid in the
// tool's ball and all its edges within D_ref, unless the cut's report counts that many tets
// unresolved. Each sweep passes twice over the same line, so a second cut meets what the first
// left; the local checker runs after every cut.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "checked.hpp"
#include "test_meshes.hpp"
#include "tetcut/cut.hpp"
#include "tetcut/invariants/check.hpp"
#include "tetcut/io.hpp"
#include "tetcut/local_tables.hpp"

namespace tetcut::testing {
namespace {

// Live tets the cut should have taken: centroid in the closed ball, no edge over D_ref.
std::uint32_t left_in_ball(const TetMesh& mesh, const Vec3& centre, double radius, double d_ref) {
  std::uint32_t n = 0;
  for (std::uint32_t i = 0; i < mesh.tet_capacity(); ++i) {
    const TetId t{i};
    if (!mesh.is_live(t)) continue;
    const auto v = mesh.tet(t);
    Vec3 c{};
    for (VertId x : v) c = c + 0.25 * mesh.position(x);
    if (norm(c - centre) > radius) continue;
    bool short_edges = true;
    for (int e = 0; e < 6 && short_edges; ++e)
      short_edges = norm(mesh.position(v[kEdgeVerts[e][1]]) - mesh.position(v[kEdgeVerts[e][0]])) <= d_ref;
    n += short_edges ? 1u : 0u;
  }
  return n;
}

struct Box {
  Vec3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
};

Box bounds(const TetMesh& mesh) {
  Box b;
  for (std::uint32_t i = 0; i < mesh.vertex_capacity(); ++i) {
    if (!mesh.is_live(VertId{i})) continue;
    const Vec3& p = mesh.position(VertId{i});
    b.lo = {std::min(b.lo.x, p.x), std::min(b.lo.y, p.y), std::min(b.lo.z, p.z)};
    b.hi = {std::max(b.hi.x, p.x), std::max(b.hi.y, p.y), std::max(b.hi.z, p.z)};
  }
  return b;
}

struct SweepCase {
  const char* mesh;
  RemovalStrategy strategy;
};

class CutLeavesNothing : public ::testing::TestWithParam<SweepCase> {};

TEST_P(CutLeavesNothing, EverySelectedTetIsRemovedOrCounted) {
  const std::string path = std::string(TETCUT_CORPUS_DIR) + "/meshes/" + GetParam().mesh;
  ReadResult read = read_mesh(path);
  ASSERT_TRUE(read.mesh.has_value()) << path;
  TetMesh mesh = build_or_fail(*read.mesh);
  const Box box = bounds(mesh);
  const Vec3 size = box.hi - box.lo;
  // A tool a twelfth of the mesh's width, sweeping along x through the middle, into the surface
  // from above: cuts that start at the surface and go deeper on the second pass.
  CutParams params;
  params.tool_diameter = std::max({size.x, size.y, size.z}) / 12.0;
  params.strategy = GetParam().strategy;
  Cutter cutter(mesh, params);
  invariants::LocalChecker local(mesh);
  const double r = params.tool_diameter / 2, d_ref = params.d_ref_factor * params.tool_diameter;
  int cuts = 0, unresolved = 0;
  for (double depth : {0.15, 0.3})
    for (double x = box.lo.x; x <= box.hi.x; x += r) {
      const Vec3 centre{x, box.lo.y + 0.5 * size.y, box.hi.z - depth * size.z};
      const CutReport report = cutter.cut(centre);
      ASSERT_TRUE(report.ok) << report.failure;
      ++cuts;
      unresolved += static_cast<int>(report.unresolved);
      const invariants::CheckReport l = local.after_operation(mesh, cutter.last_removed(), cutter.last_created());
      ASSERT_TRUE(l.ok()) << invariants::to_string(l);
      EXPECT_LE(left_in_ball(mesh, centre, r, d_ref), report.unresolved)
          << "cut " << cuts << " at " << centre.x << "," << centre.y << "," << centre.z;
    }
  EXPECT_GT(cuts, 20);
  EXPECT_TRUE(mesh_is_valid(mesh));
  // Combined and wide end with the fallback, which only a degenerate split can stop. Basic (3.4)
  // makes slivers so flat (radius ratio 0 in double) that the fallback's split is refused now
  // and then: counted above, never left silently. Neighbours may leave what 3.5 cannot take.
  const RemovalStrategy s = GetParam().strategy;
  if (s == RemovalStrategy::kCombined || s == RemovalStrategy::kWide) EXPECT_EQ(unresolved, 0);
}

std::vector<SweepCase> cases() {
  std::vector<SweepCase> out;
  for (const char* m : {"cylinder.msh", "sheet.msh", "liver-coarse.msh", "liver-refined.msh", "liver-local.msh", "liver.msh"})
    for (RemovalStrategy s : {RemovalStrategy::kBasic, RemovalStrategy::kNeighbours, RemovalStrategy::kCombined,
                              RemovalStrategy::kWide})
      out.push_back({m, s});
  return out;
}

INSTANTIATE_TEST_SUITE_P(BundledMeshes, CutLeavesNothing, ::testing::ValuesIn(cases()), [](const auto& info) {
  std::string name = std::string(info.param.mesh);
  name = name.substr(0, name.find('.')) + "_" + to_string(info.param.strategy);
  for (char& c : name)
    if (c == '-') c = '_';
  return name;
});

// The cuts the issue reported: one basic cut into the bundled liver left 15 (and 8) tets in the
// ball and called itself resolved.
TEST(CutLeavesNothing, TheReportedBasicCutsOnTheLiver) {
  const std::string path = std::string(TETCUT_CORPUS_DIR) + "/meshes/liver.msh";
  ReadResult read = read_mesh(path);
  ASSERT_TRUE(read.mesh.has_value());
  for (const Vec3 centre : {Vec3{95, 60, 100}, Vec3{95, 100, 100}}) {
    TetMesh mesh = build_or_fail(*read.mesh);
    CutParams params;
    params.tool_diameter = 8;
    params.strategy = RemovalStrategy::kBasic;
    Cutter cutter(mesh, params);
    const CutReport report = cutter.cut(centre);
    ASSERT_TRUE(report.ok) << report.failure;
    EXPECT_EQ(report.unresolved, 0u);
    EXPECT_EQ(left_in_ball(mesh, centre, 4.0, 12.0), 0u);
    EXPECT_TRUE(mesh_is_valid(mesh));
  }
}

}  // namespace
}  // namespace tetcut::testing
