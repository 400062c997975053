// Uncuttable tissue (Cutter::set_uncuttable(), the paper's Fig. 7: the portal vein freed from the
// resected liver): a box with a labelled vessel through it, cut down to the vessel and along it
// by every strategy. After every cut, checked three ways that owe the engine's own record
// nothing: the independent checker; every sample point of the vessel as it was still lies in a
// live tet (point location over the raw tets), and one the engine calls uncuttable; and the
// labels the change logs carry (mechanics::TetLabels, a geometric rule of its own) say "vessel"
// for exactly the tets the engine keeps. The same cuts without protection take part of the
// vessel, so the checks can fail.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <vector>

#include "mechanics_test_support.hpp"
#include "tetcut/box_mesh.hpp"
#include "tetcut/canonical_hash.hpp"
#include "tetcut/cut.hpp"
#include "tetcut/invariants/check.hpp"
#include "tetcut/mechanics/tet_labels.hpp"
#include "tetcut/mesh_builder.hpp"

namespace tetcut {
namespace {

constexpr std::uint32_t kVessel = 2, kParenchyma = 1;

Vec3 centroid(const TetMesh& mesh, TetId t) {
  const auto v = mesh.tet(t);
  return 0.25 * (mesh.position(v[0]) + mesh.position(v[1]) + mesh.position(v[2]) + mesh.position(v[3]));
}

double volume(const TetMesh& mesh, TetId t) {
  const auto v = mesh.tet(t);
  const Vec3 a = mesh.position(v[0]);
  return dot(mesh.position(v[1]) - a, cross(mesh.position(v[2]) - a, mesh.position(v[3]) - a)) / 6.0;
}

// Whether p lies in the closed tet, to a rounding: its barycentric coordinates, each >= -1e-12.
bool holds(const TetMesh& mesh, TetId t, const Vec3& p) {
  const auto v = mesh.tet(t);
  const Vec3 x[4] = {mesh.position(v[0]), mesh.position(v[1]), mesh.position(v[2]), mesh.position(v[3])};
  auto vol = [](const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) { return dot(b - a, cross(c - a, d - a)); };
  const double whole = vol(x[0], x[1], x[2], x[3]);
  for (int i = 0; i < 4; ++i) {
    Vec3 y[4] = {x[0], x[1], x[2], x[3]};
    y[i] = p;
    if (vol(y[0], y[1], y[2], y[3]) / whole < -1e-12) return false;
  }
  return true;
}

// An 8^3 box (3,072 tets, edge 1/8) with a vessel along x: the tets whose centroid lies within
// 0.2 of the line y = z = 0.5.
struct VesselBox {
  TetMesh mesh;
  std::vector<std::uint32_t> labels;
  std::vector<TetId> vessel;
  std::vector<Vec3> samples;  // the vessel's tets' centroids and corner-ward points, as built
  double vessel_volume = 0.0;
};

VesselBox vessel_box() {
  BuildResult built = build_mesh(make_box_mesh(8, 8, 8));
  EXPECT_TRUE(built.ok());
  VesselBox box{std::move(*built.mesh), {}, {}, {}, 0.0};
  box.labels.assign(box.mesh.tet_capacity(), kParenchyma);
  for (std::uint32_t t = 0; t < box.mesh.tet_capacity(); ++t) {
    const Vec3 c = centroid(box.mesh, TetId{t});
    if (std::hypot(c.y - 0.5, c.z - 0.5) >= 0.2) continue;
    box.labels[t] = kVessel;
    box.vessel.push_back(TetId{t});
    box.vessel_volume += volume(box.mesh, TetId{t});
    box.samples.push_back(c);
    const auto v = box.mesh.tet(TetId{t});
    for (VertId corner : v) box.samples.push_back(0.8 * box.mesh.position(corner) + 0.2 * c);
  }
  return box;
}

// Down to the vessel from the top face, then along it: tools that meet it at every depth.
std::vector<Vec3> cuts_to_the_vessel() {
  std::vector<Vec3> centres;
  for (const double z : {0.95, 0.82, 0.7, 0.6})
    for (double x = 0.1; x <= 0.9; x += 0.1) centres.push_back({x, 0.5, z});
  return centres;
}

double uncuttable_volume(Cutter& cutter) {
  const TetMesh& mesh = cutter.mesh();
  double sum = 0.0;
  for (std::uint32_t t = 0; t < mesh.tet_capacity(); ++t)
    if (mesh.is_live(TetId{t}) && cutter.uncuttable(TetId{t})) sum += volume(mesh, TetId{t});
  return sum;
}

// The vessel's samples not inside a live uncuttable tet (brute force over the raw tets).
std::size_t samples_lost(Cutter& cutter, const std::vector<Vec3>& samples) {
  const TetMesh& mesh = cutter.mesh();
  std::size_t lost = 0;
  for (const Vec3& p : samples) {
    bool found = false;
    for (std::uint32_t t = 0; t < mesh.tet_capacity() && !found; ++t)
      found = mesh.is_live(TetId{t}) && cutter.uncuttable(TetId{t}) && holds(mesh, TetId{t}, p);
    lost += found ? 0 : 1;
  }
  return lost;
}

class Uncuttable : public ::testing::TestWithParam<RemovalStrategy> {};

TEST_P(Uncuttable, EveryCutLeavesTheVesselWholeAndTakesTheTissueAroundIt) {
  VesselBox box = vessel_box();
  ASSERT_GT(box.vessel.size(), 100u);
  const double total_before = box.mesh.total_volume();
  mechanics::TetLabels labels(box.mesh, box.labels);
  Cutter cutter(box.mesh, {.tool_diameter = 0.3, .strategy = GetParam()});
  ASSERT_FALSE(cutter.set_uncuttable(box.vessel));
  invariants::LocalChecker checker(box.mesh.raw_view());
  checker.set_uncuttable(box.vessel);  // the checker's own record of the vessel, which I10 holds
  invariants::CheckOptions options;
  options.quality_rule = invariants::QualityRule::kNoDegradation;
  options.quality_floor = cutter.params().quality_floor;
  std::uint32_t met_the_vessel = 0, refused = 0;
  const std::vector<Vec3> centres = cuts_to_the_vessel();
  for (std::size_t i = 0; i < centres.size(); ++i) {
    const Vec3& centre = centres[i];
    ChangeLog log;
    const CutReport r = cutter.cut(centre, &log);
    if (!r.ok) {  // refused (the floor): nothing changed, nothing to check
      ++refused;
      continue;
    }
    EXPECT_EQ(labels.apply(box.mesh, log), 0u);
    met_the_vessel += r.uncuttable_in_tool > 0 ? 1 : 0;
    options.tool = invariants::ToolRule{.centre = centre, .radius = cutter.params().tool_diameter / 2,
                                        .d_ref = cutter.params().d_ref(), .left = cutter.last_left_in_tool()};
    options.min_dihedral_deg = std::min(cutter.params().min_dihedral_deg, cutter.last_min_dihedral_held());
    options.moved = cutter.last_moved();
    const invariants::CheckReport check =
        checker.after_operation(box.mesh.raw_view(), cutter.last_removed(), cutter.last_created(), options);
    ASSERT_TRUE(check.ok()) << invariants::id_string(check.violations.front().id) << ": " << check.violations.front().detail;
    // The engine's uncuttable tets fill the vessel as it was, no more and no less.
    ASSERT_NEAR(uncuttable_volume(cutter), box.vessel_volume, 1e-12 * box.vessel_volume) << "cut at " << centre.x << "," << centre.z;
    // Point location is the dear check (about 10 s of the ASan run when done after every cut):
    // after every third cut and the last.
    if (i % 3 == 2 || i + 1 == centres.size()) {
      ASSERT_EQ(samples_lost(cutter, box.samples), 0u) << "cut at " << centre.x << "," << centre.z;
    }
    // And they are the tets the change logs' labels call vessel.
    for (std::uint32_t t = 0; t < box.mesh.tet_capacity(); ++t) {
      if (!box.mesh.is_live(TetId{t})) continue;
      ASSERT_EQ(cutter.uncuttable(TetId{t}), labels.label(TetId{t}) == kVessel) << "tet " << t;
    }
  }
  EXPECT_LE(refused, 4u);
  EXPECT_GE(met_the_vessel, 8u);  // the cuts at z 0.7 and 0.6 reach into it
  // Tissue went: the channel the tools swept above the vessel (about 0.3 x 0.35 x 0.8).
  EXPECT_LT(box.mesh.total_volume(), total_before - 0.05);
  std::printf("%s: %u cuts met the vessel, %u refused, volume %.4f -> %.4f\n", to_string(GetParam()), met_the_vessel,
              refused, total_before, box.mesh.total_volume());
  // A removal request for a vessel tet is refused, the mesh as it was.
  const std::uint64_t hash = canonical_hash(box.mesh);
  for (std::uint32_t t = 0; t < box.mesh.tet_capacity(); ++t)
    if (box.mesh.is_live(TetId{t}) && cutter.uncuttable(TetId{t})) {
      const CutReport r = cutter.remove(TetId{t});
      EXPECT_FALSE(r.ok);
      EXPECT_NE(r.failure.find("uncuttable"), std::string::npos) << r.failure;
      break;
    }
  EXPECT_EQ(canonical_hash(box.mesh), hash);
}

INSTANTIATE_TEST_SUITE_P(Strategies, Uncuttable,
                         ::testing::Values(RemovalStrategy::kBasic, RemovalStrategy::kNeighbours,
                                           RemovalStrategy::kCombined, RemovalStrategy::kWide),
                         [](const auto& info) { return std::string(to_string(info.param)); });

// A harsher set than one vessel: a quarter of the tets, scattered (TetLabels' hashed label 1),
// so that nearly every cut meets uncuttable tets and interfaces everywhere; on two bundled meshes,
// along the lancet and at seeded random points, every strategy.
TEST_P(Uncuttable, ScatteredUncuttableTetsOnTheBundledMeshesSurviveEveryCut) {
  for (const char* name : {"cylinder.msh", "liver-coarse.msh"}) {
    SCOPED_TRACE(name);
    TetMesh mesh = testing::load_bundled(name);
    const std::vector<std::uint32_t> initial = testing::hashed_labels(mesh);
    mechanics::TetLabels labels(mesh, initial);
    std::vector<TetId> kept;
    std::vector<Vec3> samples;
    double kept_volume = 0.0;
    for (std::uint32_t t = 0; t < mesh.tet_capacity(); ++t) {
      if (initial[t] != 1) continue;
      kept.push_back(TetId{t});
      kept_volume += volume(mesh, TetId{t});
      if (t % 3 == 0) samples.push_back(centroid(mesh, TetId{t}));
    }
    Cutter cutter(mesh, {.tool_diameter = 0.8 * mesh.mean_edge_length(), .strategy = GetParam()});
    ASSERT_FALSE(cutter.set_uncuttable(kept));
    invariants::LocalChecker checker(mesh.raw_view());
    checker.set_uncuttable(kept);
    invariants::CheckOptions options;
    options.quality_rule = invariants::QualityRule::kNoDegradation;
    options.quality_floor = cutter.params().quality_floor;
    const BoundingBox box = bounding_box(mesh);
    std::vector<Vec3> centres = testing::lancet_sweep(box, 12);
    std::uint64_t state = 0x9e3779b97f4a7c15ull;
    auto uniform = [&] {
      state = state * 6364136223846793005ull + 1442695040888963407ull;
      return static_cast<double>(state >> 11) / 9007199254740992.0;
    };
    for (int i = 0; i < 12; ++i) {
      const Vec3 size = box.hi - box.lo;
      centres.push_back({box.lo.x + uniform() * size.x, box.lo.y + uniform() * size.y, box.lo.z + uniform() * size.z});
    }
    std::uint32_t met = 0, removed = 0;
    for (const Vec3& centre : centres) {
      ChangeLog log;
      const CutReport r = cutter.cut(centre, &log);
      if (!r.ok) continue;
      EXPECT_EQ(labels.apply(mesh, log), 0u);
      met += r.uncuttable_in_tool;
      removed += r.tets_removed;
      options.tool = invariants::ToolRule{.centre = centre, .radius = cutter.params().tool_diameter / 2,
                                          .d_ref = cutter.params().d_ref(), .left = cutter.last_left_in_tool()};
      options.min_dihedral_deg = std::min(cutter.params().min_dihedral_deg, cutter.last_min_dihedral_held());
      options.moved = cutter.last_moved();
      const invariants::CheckReport check =
          checker.after_operation(mesh.raw_view(), cutter.last_removed(), cutter.last_created(), options);
      ASSERT_TRUE(check.ok()) << invariants::id_string(check.violations.front().id) << ": " << check.violations.front().detail;
      ASSERT_NEAR(uncuttable_volume(cutter), kept_volume, 1e-11 * kept_volume);
      for (std::uint32_t t = 0; t < mesh.tet_capacity(); ++t) {
        if (!mesh.is_live(TetId{t})) continue;
        ASSERT_EQ(cutter.uncuttable(TetId{t}), labels.label(TetId{t}) == 1) << "tet " << t;
      }
    }
    EXPECT_GT(met, 10u);
    EXPECT_GT(removed, 10u);
    EXPECT_EQ(samples_lost(cutter, samples), 0u);
  }
}

TEST(Uncuttable, WithoutProtectionTheSameCutsTakeTheVessel) {
  VesselBox box = vessel_box();
  Cutter cutter(box.mesh, {.tool_diameter = 0.3});
  ASSERT_FALSE(cutter.set_uncuttable(box.vessel));
  ASSERT_FALSE(cutter.set_uncuttable({}));  // lifted
  for (const Vec3& centre : cuts_to_the_vessel()) (void)cutter.cut(centre);
  // The checks above would fail: part of the vessel is gone.
  std::size_t lost = 0;
  for (const Vec3& p : box.samples) {
    bool found = false;
    for (std::uint32_t t = 0; t < box.mesh.tet_capacity() && !found; ++t)
      found = box.mesh.is_live(TetId{t}) && holds(box.mesh, TetId{t}, p);
    lost += found ? 0 : 1;
  }
  EXPECT_GT(lost, box.samples.size() / 10);
}

TEST(Uncuttable, TheSetFollowsCompactionAndAResetClearsIt) {
  VesselBox box = vessel_box();
  Cutter cutter(box.mesh, {.tool_diameter = 0.3});
  ASSERT_FALSE(cutter.set_uncuttable(box.vessel));
  for (const Vec3& centre : cuts_to_the_vessel()) (void)cutter.cut(centre);
  const double before = uncuttable_volume(cutter);
  (void)cutter.compact();
  EXPECT_NEAR(uncuttable_volume(cutter), before, 1e-12 * before);
  EXPECT_EQ(samples_lost(cutter, box.samples), 0u);
  cutter.reset();
  EXPECT_EQ(uncuttable_volume(cutter), 0.0);
}

TEST(Uncuttable, ADeadTetIsRefusedAndTheSetKept) {
  VesselBox box = vessel_box();
  Cutter cutter(box.mesh, {.tool_diameter = 0.3});
  ASSERT_FALSE(cutter.set_uncuttable(box.vessel));
  const TetId beyond{box.mesh.tet_capacity() + 5};
  const auto refusal = cutter.set_uncuttable(std::span<const TetId>(&beyond, 1));
  ASSERT_TRUE(refusal);
  EXPECT_NE(refusal->find("not live"), std::string::npos);
  EXPECT_TRUE(cutter.uncuttable(box.vessel.front()));
}

}  // namespace
}  // namespace tetcut
