// Every selected tet is removed or counted (the removal core's first promise): after every cut
// of a sweep, on every bundled mesh and with every strategy, the tets left in the tool (centroid
// in the ball, edges within D_ref) are exactly as many as the cut's report counts left (the tets
// of its unresolved requests, and pieces of kept tets that a removal-time split left there,
// requested once), and the checker's I10 agrees after every cut. Each sweep passes twice
// over the same line, so a second cut meets what the first left; the local checker runs after
// every cut.
//
// "Selected" is decided as paper 3.3 decides it, on the refined region: the tets of the
// refinement loop's result (paper 3.2) whose centroid lies in the tool's closed ball and whose
// edges are within D_ref. A removal-time split (3.4, 3.7, the fallback) makes smaller tets out
// of selected and kept tets alike; a piece of a kept tet stays kept wherever its centroid falls.
// So the test redoes the refinement loop on a copy of the mesh, through the public Refiner, and
// counts the live tets after the cut that are inside the tool, have short edges, and whose
// centroid lies in a selected tet of that reference region: tissue selected and left behind.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "checked.hpp"
#include "core/tool.hpp"
#include "refine/refine.hpp"
#include "test_meshes.hpp"
#include "tetcut/bounding_box.hpp"
#include "tetcut/cut.hpp"
#include "tetcut/generators/shapes.hpp"
#include "tetcut/detail/local_tables.hpp"
#include "tetcut/invariants/check.hpp"
#include "tetcut/io.hpp"

namespace tetcut::testing {
namespace {

using Corners = std::array<Vec3, 4>;

Corners corners(const TetMesh& mesh, TetId t) {
  const auto v = mesh.tet(t);
  return {mesh.position(v[0]), mesh.position(v[1]), mesh.position(v[2]), mesh.position(v[3])};
}

Vec3 centroid(const Corners& c) { return 0.25 * (c[0] + c[1] + c[2] + c[3]); }

// Centroid in the closed ball, no edge over D_ref: paper 3.3's selection.
bool in_tool(const Corners& c, const Tool& tool, double d_ref) {
  if (distance_to_axis(tool, centroid(c)) > tool.radius) return false;
  for (int e = 0; e < 6; ++e)
    if (norm(c[kEdgeVerts[e][1]] - c[kEdgeVerts[e][0]]) > d_ref) return false;
  return true;
}

double signed_volume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return dot(b - a, cross(c - a, d - a));
}

// p in the closed tet, up to a relative tolerance (a child's centroid is strictly inside its
// ancestor; the tolerance only absorbs rounding).
bool contains(const Corners& t, const Vec3& p) {
  const double whole = signed_volume(t[0], t[1], t[2], t[3]);
  const double eps = -1e-9 * std::abs(whole);
  return signed_volume(p, t[1], t[2], t[3]) >= eps && signed_volume(t[0], p, t[2], t[3]) >= eps &&
         signed_volume(t[0], t[1], p, t[3]) >= eps && signed_volume(t[0], t[1], t[2], p) >= eps;
}

// The selected tets of the refined region of a cut at `tool` on `mesh` (left unchanged): the
// refinement loop redone on a copy, as the Cutter runs it.
std::vector<Corners> reference_selection(const TetMesh& mesh, const CutParams& params, const Tool& tool) {
  TetMesh copy = mesh;
  std::vector<TetId> hit, region;
  for (std::uint32_t i = 0; i < copy.tet_capacity(); ++i) {
    const TetId t{i};
    if (!copy.is_live(t)) continue;
    const Corners c = corners(copy, t);
    if (intersects(tool, c[0], c[1], c[2], c[3])) hit.push_back(t);
  }
  RefineParams refine;
  refine.d_ref = params.d_ref_factor * params.tool_diameter;
  refine.p = params.p;
  refine.max_iterations = params.max_refine_iterations;
  refine.method = params.split_method;
  refine.focus = tool;
  refine.max_tets_created = params.max_tets_created;
  Refiner refiner;
  refiner.refine(copy, hit, refine, region);
  std::vector<Corners> selected;
  for (TetId t : region)
    if (copy.is_live(t) && in_tool(corners(copy, t), tool, refine.d_ref)) selected.push_back(corners(copy, t));
  return selected;
}

// Live tets inside the tool whose tissue was selected: pieces of a selected tet left behind.
std::uint32_t selected_left(const TetMesh& mesh, const std::vector<Corners>& selected, const Tool& tool, double d_ref) {
  std::uint32_t n = 0;
  for (std::uint32_t i = 0; i < mesh.tet_capacity(); ++i) {
    const TetId t{i};
    if (!mesh.is_live(t)) continue;
    const Corners c = corners(mesh, t);
    if (!in_tool(c, tool, d_ref)) continue;
    const Vec3 p = centroid(c);
    n += std::any_of(selected.begin(), selected.end(), [&](const Corners& s) { return contains(s, p); }) ? 1u : 0u;
  }
  return n;
}

// Live tets inside the tool, whatever their origin: a piece of a kept tet that a removal-time
// split (3.4, 3.7, the fallback) left there included.
std::uint32_t any_left(const TetMesh& mesh, const Tool& tool, double d_ref) {
  std::uint32_t n = 0;
  for (std::uint32_t i = 0; i < mesh.tet_capacity(); ++i)
    if (mesh.is_live(TetId{i}) && in_tool(corners(mesh, TetId{i}), tool, d_ref)) ++n;
  return n;
}

// Basic (3.4) splits around every singularity into slivers the improvement pass cannot always
// lift to the floor; such a cut is refused (the mesh as it was), which only basic may be.
bool refused_for_the_floor(const CutReport& report, RemovalStrategy strategy) {
  EXPECT_EQ(strategy, RemovalStrategy::kBasic) << report.failure;
  EXPECT_EQ(report.refusal, CutRefusal::kQualityFloor) << report.failure;
  return strategy == RemovalStrategy::kBasic && report.refusal == CutRefusal::kQualityFloor;
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
  const BoundingBox box = bounding_box(mesh);
  const Vec3 size = box.hi - box.lo;
  // A tool a twelfth of the mesh's width, sweeping along x through the middle, into the surface
  // from above: cuts that start at the surface and go deeper on the second pass.
  CutParams params;
  params.tool_diameter = std::max({size.x, size.y, size.z}) / 12.0;
  params.strategy = GetParam().strategy;
  Cutter cutter(mesh, params);
  invariants::LocalChecker local(mesh.raw_view());
  const double r = params.tool_diameter / 2, d_ref = params.d_ref_factor * params.tool_diameter;
  int cuts = 0, unresolved = 0;
  for (double depth : {0.15, 0.3})
    for (double x = box.lo.x; x <= box.hi.x; x += r) {
      const Vec3 centre{x, box.lo.y + 0.5 * size.y, box.hi.z - depth * size.z};
      const Tool tool = Tool::ball(centre, r);
      const std::vector<Corners> selected = reference_selection(mesh, params, tool);
      const CutReport report = cutter.cut(centre);
      if (!report.ok && refused_for_the_floor(report, GetParam().strategy)) continue;
      ASSERT_TRUE(report.ok) << report.failure;
      ++cuts;
      unresolved += static_cast<int>(report.unresolved);
      const invariants::CheckReport l =
          local.after_operation(mesh.raw_view(), cutter.last_removed(), cutter.last_created(), cut_check(cutter, centre));
      ASSERT_TRUE(l.ok()) << invariants::to_string(l);
      // What the report counts left (unresolved requests' tets and pieces) is what is there.
      EXPECT_LE(selected_left(mesh, selected, tool, d_ref), report.left_in_tool)
          << "cut " << cuts << " at " << centre.x << "," << centre.y << "," << centre.z;
      EXPECT_EQ(any_left(mesh, tool, d_ref), report.left_in_tool)
          << "cut " << cuts << " at " << centre.x << "," << centre.y << "," << centre.z;
    }
  EXPECT_GT(cuts, 20);
  EXPECT_TRUE(mesh_is_valid(mesh));
  // Combined and wide end with the fallback, which only a degenerate split can stop. Basic (3.4)
  // makes slivers so flat (radius ratio 0 in double) that the fallback's split is refused now
  // and then: counted above, never left silently. Neighbours may leave what 3.5 cannot take.
  const RemovalStrategy s = GetParam().strategy;
  if (s == RemovalStrategy::kCombined || s == RemovalStrategy::kWide) {
    EXPECT_EQ(unresolved, 0);
  }
  // Below the budget, a strategy with the fallback leaves a tet only when the splitter refused
  // the fallback's split; each such refusal is counted.
  if (s != RemovalStrategy::kNeighbours) {
    EXPECT_GE(cutter.removal_report().fallback_refused, cutter.removal_report().unresolved);
  }
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
  return test_name_of_mesh(info.param.mesh) + "_" + to_string(info.param.strategy);
});

// On a TetGen cylinder, random sweeps meet cuts whose 3.7 split cuts unselected neighbours and
// leaves pieces of them in the tool. Each such piece is requested and what stays is counted: nothing is left in the tool beyond
// what the report counts, and such pieces did occur (the case is exercised, not assumed).
TEST(CutLeavesNothing, PiecesOfKeptTetsInTheToolAreRemovedOrCounted) {
  generators::CylinderOptions shape;
  const generators::GenResult gen = generators::generate_cylinder(shape);
  ASSERT_TRUE(gen.ok()) << gen.error;
  int pieces = 0, cuts = 0, left = 0;
  for (RemovalStrategy strategy : {RemovalStrategy::kCombined, RemovalStrategy::kBasic}) {
    TetMesh mesh = build_or_fail(*gen.mesh);
    const BoundingBox box = bounding_box(mesh);
    const Vec3 size = box.hi - box.lo;
    CutParams params;
    params.strategy = strategy;
    params.tool_diameter = std::max({size.x, size.y, size.z}) / 10.0;
    Cutter cutter(mesh, params);
    invariants::LocalChecker local(mesh.raw_view());
    const double r = params.tool_diameter / 2, d_ref = params.d_ref_factor * params.tool_diameter;
    // Seeded sweeps across the cylinder at a few heights and depths (splitmix-like steps).
    std::uint64_t state = 32;
    auto uniform = [&] {
      state += 0x9E3779B97F4A7C15ull;
      std::uint64_t z = state;
      z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
      z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
      return double((z ^ (z >> 31)) >> 11) / double(1ull << 53);
    };
    for (int sweep = 0; sweep < 6; ++sweep) {
      const double y = box.lo.y + (0.2 + 0.6 * uniform()) * size.y, z = box.lo.z + (0.2 + 0.6 * uniform()) * size.z;
      for (double x = box.lo.x; x <= box.hi.x; x += r) {
        const Vec3 centre{x, y, z};
        const CutReport report = cutter.cut(centre);
        if (!report.ok && refused_for_the_floor(report, strategy)) continue;
        ASSERT_TRUE(report.ok) << report.failure;
        ++cuts;
        pieces += static_cast<int>(report.kept_pieces_requested);
        left += static_cast<int>(report.left_in_tool);
        const invariants::CheckReport l =
            local.after_operation(mesh.raw_view(), cutter.last_removed(), cutter.last_created(), cut_check(cutter, centre));
        ASSERT_TRUE(l.ok()) << invariants::to_string(l);
        EXPECT_EQ(any_left(mesh, Tool::ball(centre, r), d_ref), report.left_in_tool)
            << to_string(strategy) << " cut " << cuts << " at " << centre.x << "," << centre.y << "," << centre.z;
      }
    }
    EXPECT_TRUE(mesh_is_valid(mesh));
    std::printf("[leftovers] %s: %d pieces of kept tets requested, %d left in the tool\n", to_string(strategy), pieces,
                left);
    if (strategy == RemovalStrategy::kCombined) {
      // The reported case: 3.7 split unselected neighbours here, and their one request each
      // emptied the tool. (Basic's pieces, split again by their own 3.4, are counted instead.)
      EXPECT_GT(pieces, 0) << "no removal-time split left a piece of a kept tet in the tool";
      EXPECT_EQ(left, 0);
    }
    pieces = left = 0;
  }
  EXPECT_GT(cuts, 50);
}

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
    const Tool tool = Tool::ball(centre, 4.0);
    const std::vector<Corners> selected = reference_selection(mesh, params, tool);
    ASSERT_FALSE(selected.empty());
    Cutter cutter(mesh, params);
    const CutReport report = cutter.cut(centre);
    ASSERT_TRUE(report.ok) << report.failure;
    EXPECT_EQ(report.unresolved, 0u);
    EXPECT_EQ(selected_left(mesh, selected, tool, 12.0), 0u);
    EXPECT_TRUE(mesh_is_valid(mesh));
  }
}

}  // namespace
}  // namespace tetcut::testing
