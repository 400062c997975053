// The pieces a cut detaches (CutReport::fragments, Cutter::last_fragments(), Cutter::pieces()):
// a slab cut through a plate detaches the piece built on the smaller side, with its tets, volume
// and centroid; a cut that detaches nothing reports nothing after a short walk; a bridge far from
// the cut stops a bounded search; pieces that were apart before are not reported as detached;
// debris below a volume goes in the same cut and its change log; and after every cut of sweeps
// the reported pieces are the mesh's own (face_connected_pieces, O(#T)).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "change_log_check.hpp"
#include "checked.hpp"
#include "core/pieces.hpp"
#include "test_meshes.hpp"
#include "tetcut/box_mesh.hpp"
#include "tetcut/cut.hpp"
#include "tetcut/invariants/check.hpp"

namespace tetcut::testing {
namespace {

// The plate of capsule_test.cpp: 4 x 2 x 0.2, cells 0.1 x 0.1 x 0.05.
TetMesh plate() { return build_or_fail(make_box_mesh(40, 20, 4, {0, 0, -0.1}, {4, 2, 0.2})); }
constexpr double kTool = 0.5;

// Two boxes, apart along x.
TetMesh two_boxes(Vec3 second_origin, Vec3 second_size, std::uint32_t second_cells) {
  RawMesh a = make_box_mesh(10, 10, 2, {0, 0, -0.1}, {1, 1, 0.2});
  const RawMesh b = make_box_mesh(second_cells, second_cells, 2, second_origin, second_size);
  const auto offset = static_cast<std::uint32_t>(a.positions.size());
  a.positions.insert(a.positions.end(), b.positions.begin(), b.positions.end());
  for (auto t : b.tets) {
    for (auto& v : t) v += offset;
    a.tets.push_back(t);
  }
  return build_or_fail(a);
}

double tet_volume(const TetMesh& mesh, TetId t) {
  const auto v = mesh.tet(t);
  const Vec3 &a = mesh.position(v[0]), &b = mesh.position(v[1]), &c = mesh.position(v[2]), &d = mesh.position(v[3]);
  return std::abs(dot(b - a, cross(c - a, d - a))) / 6.0;
}

// The reported pieces against the mesh's own pieces after the cut: each a whole piece, its
// volume and centroid those of its tets, not larger than the piece it came away from, and the
// piece count kept by the Cutter the mesh's; once by the independent checker's own union-find
// (invariants::check_fragments), once by the engine's face walk (face_connected_pieces).
::testing::AssertionResult fragments_are_the_meshs(const Cutter& cutter, const TetMesh& mesh) {
  std::vector<invariants::RawFragment> listed;
  std::optional<std::uint32_t> organ;
  for (const Fragment& f : cutter.last_fragments()) {
    if (f.removed) continue;
    listed.push_back({f.tets, f.volume, f.centroid});
    organ = f.organ.value;
  }
  const invariants::FragmentCheckReport checked =
      invariants::check_fragments(mesh.raw_view(), {.fragments = listed, .organ_tet = organ, .piece_count = cutter.pieces()});
  if (!checked.ok()) return ::testing::AssertionFailure() << invariants::to_string(checked);
  const Pieces pieces = face_connected_pieces(mesh);
  if (cutter.pieces() != pieces.count)
    return ::testing::AssertionFailure() << "the Cutter counts " << cutter.pieces() << " pieces, the mesh has " << pieces.count;
  for (const Fragment& f : cutter.last_fragments()) {
    if (f.removed) {
      for (TetId t : f.tets)
        if (mesh.is_live(t)) return ::testing::AssertionFailure() << "debris tet " << t.value << " is still there";
      continue;
    }
    if (f.tets.empty()) return ::testing::AssertionFailure() << "an empty piece";
    const std::uint32_t piece = pieces.of_tet[f.tets.front().value];
    std::uint32_t in_piece = 0;
    for (std::uint32_t p : pieces.of_tet) in_piece += p == piece ? 1 : 0;
    if (in_piece != f.tets.size())
      return ::testing::AssertionFailure() << "a reported piece has " << f.tets.size() << " tets, the mesh's " << in_piece;
    double volume = 0.0;
    Vec3 moment{};
    for (TetId t : f.tets) {
      if (!mesh.is_live(t) || pieces.of_tet[t.value] != piece)
        return ::testing::AssertionFailure() << "tet " << t.value << " is not in the reported piece";
      const double v = tet_volume(mesh, t);
      const auto q = mesh.tet(t);
      volume += v;
      moment = moment + (0.25 * v) * (mesh.position(q[0]) + mesh.position(q[1]) + mesh.position(q[2]) + mesh.position(q[3]));
    }
    if (std::abs(volume - f.volume) > 1e-9 * volume) return ::testing::AssertionFailure() << "volume " << f.volume << " vs " << volume;
    if (norm((1.0 / volume) * moment - f.centroid) > 1e-9) return ::testing::AssertionFailure() << "the centroid differs";
  }
  return ::testing::AssertionSuccess();
}

TEST(Fragments, ASlabCutThroughThePlateDetachesTheSmallerSide) {
  TetMesh mesh = plate();
  Cutter cutter(mesh, {.tool_diameter = kTool});
  EXPECT_EQ(cutter.pieces(), 1u);
  const CutReport r = cutter.cut_segment({1.0, -0.3, 0.0}, {1.0, 2.3, 0.0});
  ASSERT_TRUE(r.ok) << r.failure;
  ASSERT_EQ(r.fragments, 1u);
  EXPECT_FALSE(r.fragment_search_bounded);
  EXPECT_EQ(cutter.pieces(), 2u);
  const Fragment& left = cutter.last_fragments().front();
  // The two sides as built, x < 0.75 and x > 1.25 (the cut's selection takes whole tets: each
  // edge of the slot is within a cell, 0.1, of the tool's surface).
  EXPECT_NEAR(left.volume, 0.75 * 2 * 0.2, 0.1 * 2 * 0.2);
  EXPECT_LT(left.centroid.x, 0.75);
  double organ = 0.0;
  for (std::uint32_t i = 0; i < mesh.tet_capacity(); ++i)
    if (mesh.is_live(TetId{i})) organ += tet_volume(mesh, TetId{i});
  organ -= left.volume;
  EXPECT_NEAR(organ, 2.75 * 2 * 0.2, 0.1 * 2 * 0.2);
  EXPECT_NEAR(left.centroid.y, 1.0, 1e-2);
  EXPECT_TRUE(fragments_are_the_meshs(cutter, mesh));
  EXPECT_TRUE(mesh_is_valid(mesh));
  // The walk grew with the small side, not the organ: about twice its tets.
  EXPECT_LT(r.fragment_tets_visited, 3 * left.tets.size() + 500);
}

TEST(Fragments, ACutThatDetachesNothingReportsNothingAfterAShortWalk) {
  TetMesh mesh = plate();
  Cutter cutter(mesh, {.tool_diameter = kTool});
  const CutReport r = cutter.cut({2.0, 1.0, 0.0});
  ASSERT_TRUE(r.ok) << r.failure;
  EXPECT_EQ(r.fragments, 0u);
  EXPECT_EQ(cutter.pieces(), 1u);
  EXPECT_GT(r.fragment_tets_visited, 0u);
  EXPECT_LT(r.fragment_tets_visited, 2000u) << "of " << mesh.num_tets();
}

// The plate with a window (x in [1, 3], y in [0.5, 1.5]): a frame.
TetMesh frame() {
  TetMesh mesh = plate();
  std::vector<TetId> window;
  for (std::uint32_t i = 0; i < mesh.tet_capacity(); ++i) {
    const auto v = mesh.tet(TetId{i});
    const Vec3 c = 0.25 * (mesh.position(v[0]) + mesh.position(v[1]) + mesh.position(v[2]) + mesh.position(v[3]));
    if (c.x > 1 && c.x < 3 && c.y > 0.5 && c.y < 1.5) window.push_back(TetId{i});
  }
  mesh.remove_tets(window);
  return mesh;
}

// A cut through one bar of the frame leaves its two sides joined by the rest of the frame, far
// from the cut: the search walks around and finds one piece, or stops at a small bound and says
// so.
TEST(Fragments, ABridgeFarFromTheCutStopsABoundedSearch) {
  std::uint32_t unbounded_visits = 0;
  for (const std::uint32_t bound : {65536u, 300u}) {
    TetMesh mesh = frame();
    ASSERT_TRUE(mesh_is_valid(mesh));
    CutParams params{.tool_diameter = kTool};
    params.fragment_search_bound = bound;
    Cutter cutter(mesh, params);
    const CutReport r = cutter.cut_segment({2.0, -0.3, 0.0}, {2.0, 0.7, 0.0});
    ASSERT_TRUE(r.ok) << r.failure;
    EXPECT_EQ(r.fragments, 0u) << "bound " << bound;
    EXPECT_EQ(r.fragment_search_bounded, bound == 300u);
    EXPECT_EQ(cutter.pieces(), 1u);
    if (bound == 300u) {
      // The seeds are all visited; then the rounds stop at the bound.
      EXPECT_GE(r.fragment_tets_visited, 300u);
      EXPECT_LT(r.fragment_tets_visited, unbounded_visits);
    } else {
      unbounded_visits = r.fragment_tets_visited;
    }
  }
}

TEST(Fragments, PiecesApartBeforeTheCutAreNotDetachedByIt) {
  // A tool over the gap between two boxes takes from both; neither is detached.
  TetMesh mesh = two_boxes({1.2, 0, -0.1}, {1, 1, 0.2}, 10);
  Cutter cutter(mesh, {.tool_diameter = 0.6});
  EXPECT_EQ(cutter.pieces(), 2u);
  const CutReport r = cutter.cut({1.1, 0.5, 0.0});
  ASSERT_TRUE(r.ok) << r.failure;
  EXPECT_GT(r.tets_removed, 0u);
  EXPECT_EQ(r.fragments, 0u);
  EXPECT_EQ(cutter.pieces(), 2u);
  EXPECT_TRUE(fragments_are_the_meshs(cutter, mesh));
}

TEST(Fragments, AToolThatTakesAWholePieceCountsItGone) {
  TetMesh mesh = two_boxes({2, 0.4, -0.1}, {0.2, 0.2, 0.2}, 2);
  Cutter cutter(mesh, {.tool_diameter = 1.0});
  ASSERT_EQ(cutter.pieces(), 2u);
  const CutReport r = cutter.cut({2.1, 0.5, 0.0});
  ASSERT_TRUE(r.ok) << r.failure;
  EXPECT_EQ(cutter.pieces(), 1u);
  EXPECT_TRUE(fragments_are_the_meshs(cutter, mesh));
}

TEST(Fragments, DebrisBelowTheVolumeGoesInTheSameCutAndItsChangeLog) {
  TetMesh mesh = plate();
  const TetMesh before = mesh;
  CutParams params{.tool_diameter = kTool};
  params.debris_volume = 0.5;  // the left side (0.3) is debris, the right (1.1) is not
  Cutter cutter(mesh, params);
  ChangeLog log;
  const CutReport r = cutter.cut_segment({1.0, -0.3, 0.0}, {1.0, 2.3, 0.0}, &log);
  ASSERT_TRUE(r.ok) << r.failure;
  ASSERT_EQ(r.fragments, 1u);
  EXPECT_TRUE(cutter.last_fragments().front().removed);
  EXPECT_EQ(r.debris_pieces_removed, 1u);
  EXPECT_EQ(r.debris_tets_removed, cutter.last_fragments().front().tets.size());
  EXPECT_NEAR(r.debris_volume_removed, cutter.last_fragments().front().volume, 1e-12);
  EXPECT_LT(r.volume_removed, 0.35) << "the tissue removed does not count the debris";
  EXPECT_EQ(cutter.pieces(), 1u);
  EXPECT_TRUE(fragments_are_the_meshs(cutter, mesh));
  EXPECT_TRUE(mesh_is_valid(mesh));
  // The log takes the mesh from before to after, the debris included.
  expect_log_describes(before, mesh, log);
  EXPECT_EQ(before.num_tets() - log.removed.size() + log.created.size(), mesh.num_tets());
  // Uncuttable tissue is never debris.
  TetMesh again = plate();
  Cutter keeping(again, params);
  const std::vector<TetId> corner{TetId{0}};
  ASSERT_FALSE(keeping.set_uncuttable(corner).has_value());
  const CutReport k = keeping.cut_segment({1.0, -0.3, 0.0}, {1.0, 2.3, 0.0});
  ASSERT_TRUE(k.ok) << k.failure;
  EXPECT_EQ(k.debris_pieces_removed, 0u);
  EXPECT_EQ(keeping.pieces(), 2u);
}

// Sweeps that cut the plate into strips, ball by ball and capsule by capsule: after every cut the
// pieces reported and counted are the mesh's own.
TEST(Fragments, EveryCutOfSweepsReportsTheMeshsOwnPieces) {
  TetMesh mesh = plate();
  Cutter cutter(mesh, {.tool_diameter = kTool});
  int detached = 0, cuts = 0;
  for (const double x : {0.6, 1.4, 2.2, 3.0}) {
    const bool capsules = x > 2.0;
    for (double y = -0.3; y < 2.3; y += 0.2) {
      const CutReport r = capsules ? cutter.cut_segment({x, y, 0.0}, {x, y + 0.2, 0.0}) : cutter.cut({x, y, 0.0});
      ASSERT_TRUE(r.ok) << r.failure;
      ++cuts;
      detached += static_cast<int>(r.fragments);
      ASSERT_TRUE(fragments_are_the_meshs(cutter, mesh)) << "cut " << cuts;
    }
  }
  EXPECT_EQ(detached, 4);
  EXPECT_EQ(cutter.pieces(), 5u);
}

}  // namespace
}  // namespace tetcut::testing
