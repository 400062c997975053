// The checker's own pieces (count_components) and its judgement of what the engine reports after
// a cut (check_fragments): a correct report passes, and each kind of wrong one is named, with the
// fragment and the tet.
//
// The cut here is a slab: a 4 x 1 x 1 box of unit cubes loses its second cube, which leaves the
// first cube (6 tets, volume 1, centroid (0.5, 0.5, 0.5)) detached from the last two (12 tets,
// volume 2, centroid (3, 0.5, 0.5)), the organ. Expected volumes and centroids are written from
// that geometry, not from the checker.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "test_support.hpp"

namespace tetcut::invariants::testing {
namespace {

// Tets whose centroid's x lies in (lo, hi).
std::vector<std::uint32_t> tets_between(const RawMeshView& mesh, double lo, double hi) {
  std::vector<std::uint32_t> out;
  for (std::uint32_t t = 0; t < mesh.tets.size(); ++t) {
    const auto& q = mesh.tets[t];
    if (mesh.has_tombstones && q[0] == kDeadTetMarker) continue;
    double x = 0.0;
    for (std::uint32_t v : q) x += 0.25 * mesh.positions[v].x;
    if (x > lo && x < hi) out.push_back(t);
  }
  return out;
}

// The box, cut: the slab x in [1, 2] removed through the engine.
struct SlabCut {
  TetMesh mesh = build_or_fail(make_box_mesh(4, 1, 1, {0, 0, 0}, {4, 1, 1}));
  std::vector<std::uint32_t> slab, detached, organ;

  SlabCut() {
    slab = tets_between(mesh.raw_view(), 1, 2);
    std::vector<TetId> removed;
    for (std::uint32_t t : slab) removed.push_back(TetId{t});
    mesh.remove_tets(removed);
    detached = tets_between(mesh.raw_view(), 0, 1);
    organ = tets_between(mesh.raw_view(), 2, 4);
  }

  // The right report for the detached cube, as a RawFragment over `tets`.
  static RawFragment cube(const std::vector<std::uint32_t>& tets) { return {tets, 1.0, {0.5, 0.5, 0.5}}; }
  RawFragment organ_piece() const { return {organ, 2.0, {3.0, 0.5, 0.5}}; }

  FragmentCheckReport check(std::span<const RawFragment> fragments, std::optional<std::uint32_t> piece_count = 2,
                            const CheckOptions& options = {}) const {
    return check_fragments(mesh.raw_view(), {fragments, organ.front(), piece_count}, options);
  }
};

// The violations, one per line, for failure messages.
std::string faults(const FragmentCheckReport& report) { return to_string(report); }

// Exactly one violation, of that fault and fragment.
void expect_only(const FragmentCheckReport& report, FragmentFault fault, std::uint32_t fragment) {
  ASSERT_EQ(report.violations.size(), 1u) << faults(report);
  EXPECT_EQ(report.violations[0].fault, fault) << faults(report);
  EXPECT_EQ(report.violations[0].fragment, fragment) << faults(report);
}

// ---- count_components ------------------------------------------------------------------------

TEST(Components, ABoxIsOnePiece) {
  const RawMesh box = make_box_mesh(3, 3, 3);
  const Components pieces = count_components(box);
  EXPECT_EQ(pieces.count, 1u);
  ASSERT_EQ(pieces.of_tet.size(), box.tets.size());
  EXPECT_TRUE(std::all_of(pieces.of_tet.begin(), pieces.of_tet.end(), [](std::uint32_t p) { return p == 0; }));
}

// A face is its vertex set: the pieces do not depend on how each tet lists its vertices (here
// the last three cycled, an even permutation: the orientation stays).
TEST(Components, PiecesDoNotDependOnTheOrderOfATetsVertices) {
  RawMesh box = make_box_mesh(3, 3, 3);
  for (std::uint32_t t = 0; t < box.tets.size(); ++t)
    for (std::uint32_t turn = 0; turn < t % 3; ++turn) {
      auto& q = box.tets[t];
      q = {q[0], q[2], q[3], q[1]};
    }
  EXPECT_EQ(count_components(box).count, 1u);
}

TEST(Components, ASlabRemovedAcrossABoxLeavesTwoPiecesAndNoPieceForTheDead) {
  const SlabCut cut;
  ASSERT_EQ(cut.slab.size(), 6u);
  ASSERT_EQ(cut.detached.size(), 6u);
  ASSERT_EQ(cut.organ.size(), 12u);
  const Components pieces = count_components(cut.mesh.raw_view());
  EXPECT_EQ(pieces.count, 2u);
  ASSERT_EQ(pieces.of_tet.size(), cut.mesh.tet_capacity());
  for (std::uint32_t t : cut.slab) EXPECT_EQ(pieces.of_tet[t], kNoComponent) << "tet " << t;
  const std::uint32_t a = pieces.of_tet[cut.detached[0]], b = pieces.of_tet[cut.organ[0]];
  EXPECT_NE(a, b);
  for (std::uint32_t t : cut.detached) EXPECT_EQ(pieces.of_tet[t], a) << "tet " << t;
  for (std::uint32_t t : cut.organ) EXPECT_EQ(pieces.of_tet[t], b) << "tet " << t;
}

// Box b's tets come first in the array, so it is piece 0 whatever the geometry says.
TEST(Components, TwoDisjointBoxesAreTwoPiecesNumberedByTheirLowestTet) {
  const RawMesh a = make_box_mesh(2, 1, 1);
  const RawMesh b = make_box_mesh(1, 2, 1, {5, 0, 0});
  const RawMesh both = weld(b, a);
  ASSERT_EQ(both.positions.size(), a.positions.size() + b.positions.size());
  const Components pieces = count_components(both);
  EXPECT_EQ(pieces.count, 2u);
  for (std::uint32_t t = 0; t < both.tets.size(); ++t)
    EXPECT_EQ(pieces.of_tet[t], t < b.tets.size() ? 0u : 1u) << "tet " << t;
}

// Face-connected, not vertex- or edge-connected: b touches a along an edge, c touches a at a
// corner, and they are three pieces.
TEST(Components, BoxesSharingOnlyAnEdgeOrAVertexAreSeparatePieces) {
  const RawMesh a = make_box_mesh(1, 1, 1);
  const RawMesh b = make_box_mesh(1, 1, 1, {1, 1, 0});
  const RawMesh c = make_box_mesh(1, 1, 1, {-1, -1, -1});
  const RawMesh all = weld(weld(a, b), c);
  ASSERT_EQ(all.positions.size(), 3u * 8u - 2u - 1u);  // the edge's two vertices and the corner welded
  EXPECT_EQ(count_components(all).count, 3u);
}

// A face met three times (I3 broken) still joins: face-connected is all it asks.
TEST(Components, AFaceOfThreeTetsJoinsThemAll) {
  RawMesh raw;
  raw.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, -1}, {1, 1, 1}, {5, 5, 5}, {6, 5, 5}, {5, 6, 5}};
  raw.tets = {{0, 1, 2, 3}, {6, 7, 8, 3}, {0, 2, 1, 4}, {1, 0, 2, 5}};
  const Components pieces = count_components(raw);
  EXPECT_EQ(pieces.count, 2u);
  EXPECT_EQ(pieces.of_tet, (std::vector<std::uint32_t>{0, 1, 0, 0}));
}

// Tombstones written into the raw arrays: they are no piece, and a piece they held together
// falls apart; without the tombstone flag the same marker is an ordinary (bad) vertex id.
TEST(Components, DeadIdsAreNoPieceAndJoinNothing) {
  RawMesh raw = make_box_mesh(3, 1, 1, {0, 0, 0}, {3, 1, 1});
  const std::vector<std::uint32_t> middle = tets_between(raw, 1, 2);
  ASSERT_EQ(middle.size(), 6u);
  for (std::uint32_t t : middle) raw.tets[t][0] = kDeadTetMarker;
  RawMeshView view = raw;
  view.has_tombstones = true;
  const Components pieces = count_components(view);
  EXPECT_EQ(pieces.count, 2u);
  for (std::uint32_t t : middle) EXPECT_EQ(pieces.of_tet[t], kNoComponent) << "tet " << t;
  EXPECT_EQ(std::count(pieces.of_tet.begin(), pieces.of_tet.end(), kNoComponent), 6);

  for (auto& q : raw.tets) q[0] = kDeadTetMarker;
  view = raw;
  view.has_tombstones = true;
  EXPECT_EQ(count_components(view).count, 0u);
}

// ---- check_fragments -------------------------------------------------------------------------

TEST(FragmentCheck, ACorrectReportPasses) {
  const SlabCut cut;
  const RawFragment fragments[] = {SlabCut::cube(cut.detached)};
  const FragmentCheckReport report = cut.check(fragments);
  EXPECT_TRUE(report.ok()) << faults(report);
  EXPECT_TRUE(report.notes.empty());
  EXPECT_EQ(report.components.count, 2u);

  // The same tets in another order, held as the engine holds them (TetId), and no piece count.
  std::vector<TetId> shuffled;
  for (std::uint32_t t : cut.detached) shuffled.push_back(TetId{t});
  std::shuffle(shuffled.begin(), shuffled.end(), std::mt19937(3));
  const RawFragment as_engine[] = {{shuffled, 1.0, {0.5, 0.5, 0.5}}};
  EXPECT_TRUE(cut.check(as_engine, std::nullopt).ok()) << faults(cut.check(as_engine, std::nullopt));

  // Nothing detached: no fragment, no organ.
  EXPECT_TRUE(check_fragments(cut.mesh.raw_view(), {{}, std::nullopt, 2}).ok());
}

TEST(FragmentCheck, AMissingTetIsNamed) {
  const SlabCut cut;
  std::vector<std::uint32_t> tets = cut.detached;
  const std::uint32_t dropped = tets.back();
  tets.pop_back();
  const RawFragment fragments[] = {SlabCut::cube(tets)};
  const FragmentCheckReport report = cut.check(fragments);
  expect_only(report, FragmentFault::kMissingTet, 0);
  EXPECT_EQ(report.violations[0].tets, std::vector<std::uint32_t>{dropped});
  EXPECT_EQ(report.violations[0].count, 1u);
}

TEST(FragmentCheck, AnExtraTetFromTheOrganIsNamed) {
  const SlabCut cut;
  std::vector<std::uint32_t> tets = cut.detached;
  const std::uint32_t extra = cut.organ[3];
  tets.insert(tets.begin(), extra);  // first: the fragment's piece is its majority's, not its first tet's
  const RawFragment fragments[] = {SlabCut::cube(tets)};
  const FragmentCheckReport report = cut.check(fragments);
  expect_only(report, FragmentFault::kForeignTet, 0);
  EXPECT_EQ(report.violations[0].tets, std::vector<std::uint32_t>{extra});
}

TEST(FragmentCheck, AWrongVolumeIsNamedAndRoundingIsNot) {
  const SlabCut cut;
  RawFragment fragments[] = {SlabCut::cube(cut.detached)};
  fragments[0].volume = 1.0 + 1e-12;
  EXPECT_TRUE(cut.check(fragments).ok()) << faults(cut.check(fragments));
  fragments[0].volume = 1.0 + 1e-6;
  expect_only(cut.check(fragments), FragmentFault::kVolume, 0);
  fragments[0].volume = -1.0;  // a signed sum of negative tets is no volume
  expect_only(cut.check(fragments), FragmentFault::kVolume, 0);
}

// The tolerance is 1e-9 of the bounding box diagonal, sqrt(18) here.
TEST(FragmentCheck, AWrongCentroidIsNamedAndRoundingIsNot) {
  const SlabCut cut;
  RawFragment fragments[] = {SlabCut::cube(cut.detached)};
  fragments[0].centroid.y += 1e-12;
  EXPECT_TRUE(cut.check(fragments).ok()) << faults(cut.check(fragments));
  fragments[0].centroid.y += 1e-7;
  expect_only(cut.check(fragments), FragmentFault::kCentroid, 0);
  fragments[0].centroid = {1.0, 0.5, 0.5};  // the centroid of the cube the cut removed
  expect_only(cut.check(fragments), FragmentFault::kCentroid, 0);
}

// The Kuhn cube's six tets have equal volumes, so any weighting gives its centre. Split one of
// them at a point near a corner: the piece and its centroid stay, the tets' volumes differ, and
// the plain mean of their centroids moves away from the piece's centroid.
TEST(FragmentCheck, TheCentroidIsWeightedByVolume) {
  SlabCut cut;
  const TetId host{cut.detached[0]};
  const auto q = cut.mesh.tet(host);
  const Vec3 p = 0.7 * cut.mesh.position(q[0]) + 0.1 * cut.mesh.position(q[1]) + 0.1 * cut.mesh.position(q[2]) +
                 0.1 * cut.mesh.position(q[3]);
  const VertId inner = cut.mesh.add_vertex(p);
  std::vector<TetMesh::TetVerts> children;
  for (int i = 0; i < 4; ++i) {
    TetMesh::TetVerts child = q;
    child[i] = inner;
    children.push_back(child);
  }
  const TetId removed[] = {host};
  cut.mesh.replace_tets(removed, children);
  const std::vector<std::uint32_t> tets = tets_between(cut.mesh.raw_view(), 0, 1);
  ASSERT_EQ(tets.size(), 9u);

  RawFragment fragments[] = {SlabCut::cube(tets)};
  EXPECT_TRUE(cut.check(fragments).ok()) << faults(cut.check(fragments));

  Vec3 plain_mean{};
  for (std::uint32_t t : tets)
    for (std::uint32_t v : cut.mesh.raw_tets()[t]) plain_mean = plain_mean + (0.25 / 9.0) * cut.mesh.positions()[v];
  ASSERT_GT(norm(plain_mean - Vec3{0.5, 0.5, 0.5}), 1e-3);
  fragments[0].centroid = plain_mean;
  expect_only(cut.check(fragments), FragmentFault::kCentroid, 0);
}

TEST(FragmentCheck, ADuplicatedFragmentIsNamed) {
  const SlabCut cut;
  const RawFragment fragments[] = {SlabCut::cube(cut.detached), SlabCut::cube(cut.detached)};
  const FragmentCheckReport report = cut.check(fragments);
  const FragmentViolation* same = report.find(FragmentFault::kSamePiece);
  ASSERT_NE(same, nullptr) << faults(report);
  EXPECT_EQ(same->fragment, 1u);
  EXPECT_NE(same->detail.find("fragment 1 is piece"), std::string::npos) << same->detail;
  EXPECT_NE(same->detail.find("which fragment 0 is already"), std::string::npos) << same->detail;
  // Every tet of fragment 1 was listed by fragment 0 already; fragment 0 itself is right.
  EXPECT_EQ(report.find(FragmentFault::kRepeatedTet, 1)->count, 6u);
  for (const FragmentViolation& v : report.violations) EXPECT_EQ(v.fragment, 1u) << v.detail;
}

TEST(FragmentCheck, TheOrganReportedAsAFragmentIsNamed) {
  const SlabCut cut;
  const RawFragment fragments[] = {SlabCut::cube(cut.detached), cut.organ_piece()};
  const FragmentCheckReport report = cut.check(fragments);
  expect_only(report, FragmentFault::kOrganListed, 1);
  EXPECT_EQ(report.violations[0].tets, std::vector<std::uint32_t>{cut.organ.front()});
}

// The engine took the small cube for the organ and reported the larger piece as detached.
TEST(FragmentCheck, AFragmentLargerThanTheOrganIsNamed) {
  const SlabCut cut;
  const RawFragment fragments[] = {cut.organ_piece()};
  const FragmentCheckReport report = check_fragments(cut.mesh.raw_view(), {fragments, cut.detached.front(), 2});
  expect_only(report, FragmentFault::kLargerThanOrgan, 0);
  EXPECT_NE(report.violations[0].detail.find("organ tet " + std::to_string(cut.detached.front())), std::string::npos)
      << report.violations[0].detail;
}

TEST(FragmentCheck, AWrongPieceCountIsNamed) {
  const SlabCut cut;
  const RawFragment fragments[] = {SlabCut::cube(cut.detached)};
  const FragmentCheckReport report = cut.check(fragments, 3);
  expect_only(report, FragmentFault::kPieceCount, kNoRawRef);
  EXPECT_NE(report.violations[0].detail.find("the engine counts 3 pieces, the checker 2"), std::string::npos)
      << report.violations[0].detail;
}

TEST(FragmentCheck, DeadRepeatedAndEmptyListingsAreNamed) {
  const SlabCut cut;
  std::vector<std::uint32_t> tets = cut.detached;
  tets.push_back(cut.slab[2]);       // removed by the cut
  tets.push_back(1000);              // never existed
  tets.push_back(cut.detached[1]);   // listed twice
  const std::vector<std::uint32_t> nothing;
  const RawFragment fragments[] = {SlabCut::cube(tets), SlabCut::cube(nothing)};
  const FragmentCheckReport report = cut.check(fragments);
  const FragmentViolation* dead = report.find(FragmentFault::kDeadTet, 0);
  ASSERT_NE(dead, nullptr) << faults(report);
  EXPECT_EQ(dead->tets, (std::vector<std::uint32_t>{cut.slab[2], 1000}));
  ASSERT_NE(report.find(FragmentFault::kRepeatedTet, 0), nullptr) << faults(report);
  EXPECT_EQ(report.find(FragmentFault::kRepeatedTet, 0)->tets, std::vector<std::uint32_t>{cut.detached[1]});
  EXPECT_NE(report.find(FragmentFault::kNoPiece, 1), nullptr) << faults(report);
  EXPECT_EQ(report.violations.size(), 3u) << faults(report);

  // An organ tet the cut removed.
  const RawFragment right[] = {SlabCut::cube(cut.detached)};
  expect_only(check_fragments(cut.mesh.raw_view(), {right, cut.slab[0], 2}), FragmentFault::kOrganTet, kNoRawRef);
}

// A person triaging reads which operation, which fragment, which tet and how many more.
TEST(FragmentCheck, MessagesNameTheOperationTheFragmentAndTheTet) {
  const SlabCut cut;
  const std::vector<std::uint32_t> two(cut.detached.begin(), cut.detached.begin() + 4);
  const RawFragment fragments[] = {SlabCut::cube(cut.detached), SlabCut::cube(two)};
  CheckOptions options;
  options.operation = "cut 7";
  const FragmentCheckReport report = cut.check(fragments, 2, options);
  const FragmentViolation* missing = report.find(FragmentFault::kMissingTet, 1);
  ASSERT_NE(missing, nullptr) << faults(report);
  EXPECT_EQ(missing->count, 2u);
  EXPECT_EQ(missing->detail.rfind("after cut 7: fragment 1 is piece ", 0), 0u) << missing->detail;
  EXPECT_NE(missing->detail.find("does not list its tet " + std::to_string(cut.detached[4])), std::string::npos)
      << missing->detail;
  EXPECT_NE(missing->detail.find("(and 1 more)"), std::string::npos) << missing->detail;
  EXPECT_NE(to_string(report).find("fragments: a tet of the piece not listed: after cut 7: fragment 1"),
            std::string::npos)
      << to_string(report);
}

}  // namespace
}  // namespace tetcut::invariants::testing
