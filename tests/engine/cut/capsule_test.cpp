// The capsule tool (Cutter::cut_segment): its geometry against references computed another way,
// the index's capsule query against a scan, a zero-length capsule is the ball bit for bit, a
// capsule cut takes the capsule's tissue under the checker, what a stroke removes does not depend
// on how it is sampled, and balls at the same samples leave a bridge the capsules do not.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "checked.hpp"
#include "core/pieces.hpp"
#include "core/random.hpp"
#include "core/tool.hpp"
#include "cut/spatial_index.hpp"
#include "test_meshes.hpp"
#include "tetcut/box_mesh.hpp"
#include "tetcut/canonical_hash.hpp"
#include "tetcut/cut.hpp"
#include "tetcut/detail/local_tables.hpp"
#include "tetcut/invariants/check.hpp"
#include "tetcut/io.hpp"

namespace tetcut::testing {
namespace {

// A plate 4 x 2 x 0.2 (19,200 tets of 0.1 x 0.1 x 0.05 cells) that a tool of diameter 0.5 cuts
// through its whole thickness.
TetMesh plate() { return build_or_fail(make_box_mesh(40, 20, 4, {0, 0, -0.1}, {4, 2, 0.2})); }
constexpr double kPlateTool = 0.5;

TetMesh load_corpus(const std::string& name) {
  ReadResult read = read_mesh(std::string(TETCUT_CORPUS_DIR) + "/meshes/" + name);
  if (!read.mesh) {
    ADD_FAILURE() << "cannot read " << name;
    return {};
  }
  return build_or_fail(*read.mesh);
}

Vec3 centroid_of(const TetMesh& mesh, TetId t) {
  const auto v = mesh.tet(t);
  return 0.25 * (mesh.position(v[0]) + mesh.position(v[1]) + mesh.position(v[2]) + mesh.position(v[3]));
}

// The tissue the selection takes for `stroke` (paper 3.3 with the capsule): live tets whose
// centroid is within the radius of the segment and whose edges are within D_ref.
std::uint32_t tissue_left(const TetMesh& mesh, const Tool& stroke, double d_ref) {
  std::uint32_t left = 0;
  for (std::uint32_t i = 0; i < mesh.tet_capacity(); ++i) {
    const TetId t{i};
    if (!mesh.is_live(t) || distance_to_axis(stroke, centroid_of(mesh, t)) > stroke.radius) continue;
    const auto v = mesh.tet(t);
    bool short_edges = true;
    for (int e = 0; e < 6; ++e)
      short_edges = short_edges && norm(mesh.position(v[kEdgeVerts[e][1]]) - mesh.position(v[kEdgeVerts[e][0]])) <= d_ref;
    left += short_edges ? 1 : 0;
  }
  return left;
}

// Cuts the capsule a-b and holds the cut to the local checker with the capsule as I10's tool.
::testing::AssertionResult checked_cut_segment(Cutter& cutter, invariants::LocalChecker& local, const Vec3& a,
                                               const Vec3& b, CutReport* out = nullptr) {
  const CutReport report = cutter.cut_segment(a, b);
  if (out) *out = report;
  if (!report.ok) return ::testing::AssertionFailure() << "cut refused: " << report.failure;
  invariants::CheckOptions options = cut_check(cutter, a);
  options.tool->end = b;
  const invariants::CheckReport l =
      local.after_operation(cutter.mesh().raw_view(), cutter.last_removed(), cutter.last_created(), options);
  if (!l.ok()) return ::testing::AssertionFailure() << invariants::to_string(l);
  return ::testing::AssertionSuccess();
}

TEST(Capsule, DistanceToTheAxisIsToTheNearestPointOfTheSegment) {
  const Tool capsule = Tool::capsule({0, 0, 0}, {2, 0, 0}, 0.5);
  EXPECT_DOUBLE_EQ(distance_to_axis(capsule, {1, 1, 0}), 1.0) << "beside the middle";
  EXPECT_DOUBLE_EQ(distance_to_axis(capsule, {-3, 4, 0}), 5.0) << "beyond a";
  EXPECT_DOUBLE_EQ(distance_to_axis(capsule, {5, 0, 4}), 5.0) << "beyond b";
  const Vec3 centre{1, 2, 3}, p{4, -1, 0.5};
  EXPECT_EQ(distance_to_axis(Tool::ball(centre, 1), p), norm(p - centre)) << "a ball's distance, bit for bit";
  EXPECT_FALSE(capsule.is_ball());
  EXPECT_TRUE(Tool::ball(centre, 1).is_ball());
}

// intersects() decides a capsule by clipping its segment to the tet and measuring it against
// the faces; the reference samples the segment densely and takes the least distance_to_tet(),
// which is at most the true distance plus half the spacing of the samples (the distance is
// 1-Lipschitz along the segment). Where the reference decides, the two agree.
TEST(Capsule, IntersectsAgreesWithASampledDistance) {
  SplitMix64 rng(17);
  auto coordinate = [&] { return 4.0 * rng.unit() - 2.0; };
  constexpr int kSamples = 400;
  int meets = 0, misses = 0, through = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    Vec3 q[4];
    for (Vec3& x : q) x = {coordinate(), coordinate(), coordinate()};
    if (dot(q[1] - q[0], cross(q[2] - q[0], q[3] - q[0])) < 0) std::swap(q[2], q[3]);
    const Tool capsule = Tool::capsule({coordinate(), coordinate(), coordinate()}, {coordinate(), coordinate(), coordinate()},
                                       trial % 10 == 0 ? 0.01 : 1.5 * rng.unit() * rng.unit());
    double sampled = INFINITY;
    for (int k = 0; k <= kSamples; ++k) {
      const Vec3 p = capsule.a + (static_cast<double>(k) / kSamples) * (capsule.b - capsule.a);
      sampled = std::min(sampled, distance_to_tet(p, q[0], q[1], q[2], q[3]));
    }
    const double error = 0.5 * norm(capsule.b - capsule.a) / kSamples + 1e-9;
    const bool surely_meets = sampled <= capsule.radius, surely_misses = sampled - error > capsule.radius;
    if (!surely_meets && !surely_misses) continue;
    ASSERT_EQ(intersects(capsule, q[0], q[1], q[2], q[3]), surely_meets) << "trial " << trial;
    (surely_meets ? meets : misses)++;
    through += sampled == 0.0 ? 1 : 0;
  }
  EXPECT_GT(meets, 300);
  EXPECT_GT(misses, 300);
  EXPECT_GT(through, 50) << "segments that cross the tet";
}

// The share of a tet in the capsule: exact for tets wholly in or out, the midpoint rule between.
TEST(Capsule, ShareInTheToolIsExactForTetsWhollyInOrOut) {
  const Tool capsule = Tool::capsule({0, 0, 0}, {10, 0, 0}, 1.0);
  const Vec3 in[4] = {{4, 0, 0}, {4.5, 0, 0}, {4, 0.5, 0}, {4, 0, 0.5}};
  const Vec3 out[4] = {{4, 2, 0}, {4.5, 2, 0}, {4, 2.5, 0}, {4, 2, 0.5}};
  const Vec3 across[4] = {{4, -0.5, -0.5}, {4.2, 3, 0}, {4, 0, 3}, {4.4, 3, 3}};
  EXPECT_EQ(share_in_tool(capsule, in[0], in[1], in[2], in[3]), 1.0) << "inside the middle, far from either end";
  EXPECT_EQ(share_in_tool(capsule, out[0], out[1], out[2], out[3]), 0.0);
  const double share = share_in_tool(capsule, across[0], across[1], across[2], across[3]);
  EXPECT_GT(share, 0.0);
  EXPECT_LT(share, 1.0);
}

TEST(Capsule, TheIndexFindsWhatAScanFinds) {
  TetMesh mesh = build_or_fail(make_box_mesh(6, 5, 4, {0, 0, 0}, {6, 5, 4}));
  SpatialIndex index(1.0);
  index.build(mesh);
  SplitMix64 rng(23);
  std::vector<TetId> got, scanned;
  int found = 0;
  for (int q = 0; q < 300; ++q) {
    auto point = [&] { return Vec3{rng.unit() * 8 - 1, rng.unit() * 7 - 1, rng.unit() * 6 - 1}; };
    const Tool capsule = Tool::capsule(point(), point(), rng.unit() * 1.2);
    index.query(mesh, capsule, got);
    scan_tets_meeting(mesh, capsule, scanned);
    ASSERT_EQ(got, scanned) << "query " << q;
    found += got.empty() ? 0 : 1;
  }
  EXPECT_GT(found, 200);
}

// cut_segment(c, c) is cut(c): same mesh bits, same report, cut after cut.
TEST(Capsule, AZeroLengthSegmentIsTheBallBitForBit) {
  TetMesh ball_mesh = load_corpus("liver-coarse.msh");
  TetMesh capsule_mesh = ball_mesh;
  const BoundingBox box = bounding_box(ball_mesh);
  const CutParams params{.tool_diameter = box.diagonal() / 25};
  Cutter balls(ball_mesh, params), capsules(capsule_mesh, params);
  int removed = 0;
  for (const Vec3& centre : lancet_sweep(box, 12)) {
    const CutReport a = balls.cut(centre), b = capsules.cut_segment(centre, centre);
    ASSERT_EQ(a.ok, b.ok);
    EXPECT_EQ(a.tets_removed, b.tets_removed);
    EXPECT_EQ(a.volume_removed, b.volume_removed);
    ASSERT_EQ(canonical_hash(ball_mesh), canonical_hash(capsule_mesh));
    removed += static_cast<int>(a.tets_removed);
  }
  EXPECT_GT(removed, 20);
}

TEST(Capsule, NonFiniteEndsAreRefusedAndTheMeshKept) {
  TetMesh mesh = plate();
  const std::uint64_t before = canonical_hash(mesh);
  Cutter cutter(mesh, {.tool_diameter = kPlateTool});
  const CutReport r = cutter.cut_segment({1, 1, 0}, {NAN, 1, 0});
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.refusal, CutRefusal::kParameters);
  EXPECT_EQ(canonical_hash(mesh), before);
}

// One capsule across the middle of a liver: the local checker with the capsule as I10's tool,
// and nothing the selection takes is left (the combined strategy resolves every request).
TEST(Capsule, ACapsuleCutTakesItsTissueUnderTheChecker) {
  TetMesh mesh = load_corpus("liver-coarse.msh");
  const BoundingBox box = bounding_box(mesh);
  const std::vector<Vec3> line = lancet_sweep(box, 10);
  Cutter cutter(mesh, {.tool_diameter = box.diagonal() / 25});
  invariants::LocalChecker local(mesh.raw_view());
  std::uint32_t removed = 0;
  for (std::size_t k = 0; k + 2 < line.size(); k += 2) {
    CutReport report;
    ASSERT_TRUE(checked_cut_segment(cutter, local, line[k], line[k + 2], &report)) << "segment " << k;
    const Tool stroke = Tool::capsule(line[k], line[k + 2], cutter.params().tool_diameter / 2);
    EXPECT_EQ(tissue_left(mesh, stroke, cutter.params().d_ref()), report.left_in_tool) << "segment " << k;
    EXPECT_EQ(report.left_in_tool, 0u);
    removed += report.tets_removed;
  }
  EXPECT_GT(removed, 50u);
  EXPECT_TRUE(mesh_is_valid(mesh));
}

// A stroke cut as one capsule, as two halves and as ten tenths: what one removes and another
// keeps lies within D_ref of the capsule's surface (the refinement's resolution), and after each
// nothing the selection takes for the whole stroke is left.
TEST(Capsule, AStrokeRemovesTheSameTissueHoweverItIsSampled) {
  const Vec3 a{0.8, 0.5, 0.0}, b{3.2, 1.5, 0.0};
  const CutParams params{.tool_diameter = kPlateTool};
  const Tool stroke = Tool::capsule(a, b, kPlateTool / 2);
  struct Sampled {
    int pieces;
    TetMesh mesh;
    double volume_removed = 0.0;
  };
  std::vector<Sampled> runs;
  for (int pieces : {1, 2, 10}) {
    Sampled run{pieces, plate()};
    Cutter cutter(run.mesh, params);
    invariants::LocalChecker local(run.mesh.raw_view());
    for (int k = 0; k < pieces; ++k) {
      const Vec3 from = a + (static_cast<double>(k) / pieces) * (b - a), to = a + (static_cast<double>(k + 1) / pieces) * (b - a);
      CutReport report;
      ASSERT_TRUE(checked_cut_segment(cutter, local, from, to, &report)) << pieces << " pieces, piece " << k;
      run.volume_removed += report.volume_removed;
    }
    EXPECT_EQ(tissue_left(run.mesh, stroke, params.d_ref()), 0u) << pieces << " pieces";
    runs.push_back(std::move(run));
  }
  std::printf("stroke removed volume: 1 capsule %.6f, 2 capsules %.6f, 10 capsules %.6f\n", runs[0].volume_removed,
              runs[1].volume_removed, runs[2].volume_removed);
  const double d_ref = params.d_ref();
  for (Sampled& x : runs)
    for (Sampled& y : runs) {
      if (&x == &y) continue;
      Cutter finder(y.mesh, params);
      int differ = 0;
      for (std::uint32_t i = 0; i < x.mesh.tet_capacity(); ++i) {
        if (!x.mesh.is_live(TetId{i})) continue;
        const Vec3 c = centroid_of(x.mesh, TetId{i});
        if (finder.tet_containing(c) != kNoTet) continue;
        ++differ;  // kept by x, removed by y
        EXPECT_LE(std::abs(distance_to_axis(stroke, c) - stroke.radius), d_ref)
            << "kept with " << x.pieces << " capsules, removed with " << y.pieces << " at " << c.x << "," << c.y << "," << c.z;
      }
      EXPECT_LT(differ, 2000);
    }
  // The same tissue up to the refinement's resolution: the volumes within a tenth of each other.
  EXPECT_NEAR(runs[1].volume_removed, runs[0].volume_removed, 0.1 * runs[0].volume_removed);
  EXPECT_NEAR(runs[2].volume_removed, runs[0].volume_removed, 0.1 * runs[0].volume_removed);
}

// Balls 1.2 diameters apart along a stroke across the plate (a fast stroke sampled coarsely)
// leave the tissue between them: bridges that keep the plate one piece. The capsules between the
// same samples take it and cut the plate in two.
TEST(Capsule, BallsAtTheSamplesLeaveABridgeTheCapsulesDoNot) {
  const CutParams params{.tool_diameter = kPlateTool};
  std::vector<Vec3> samples;
  for (double y = -0.2; y <= 2.2 + 1e-9; y += 1.2 * kPlateTool) samples.push_back({2.0, y, 0.0});
  const Tool stroke = Tool::capsule(samples.front(), samples.back(), kPlateTool / 2);

  TetMesh by_balls = plate();
  Cutter balls(by_balls, params);
  for (const Vec3& c : samples) ASSERT_TRUE(balls.cut(c).ok);
  TetMesh by_capsules = plate();
  Cutter capsules(by_capsules, params);
  invariants::LocalChecker local(by_capsules.raw_view());
  for (std::size_t k = 0; k + 1 < samples.size(); ++k)
    ASSERT_TRUE(checked_cut_segment(capsules, local, samples[k], samples[k + 1])) << "capsule " << k;

  EXPECT_GT(tissue_left(by_balls, stroke, params.d_ref()), 100u) << "the bridge: tissue in the stroke the balls left";
  EXPECT_EQ(face_connected_pieces(by_balls).count, 1u) << "the bridge holds the plate together";
  EXPECT_EQ(tissue_left(by_capsules, stroke, params.d_ref()), 0u);
  EXPECT_EQ(face_connected_pieces(by_capsules).count, 2u) << "the capsules cut the plate in two";
}

}  // namespace
}  // namespace tetcut::testing
