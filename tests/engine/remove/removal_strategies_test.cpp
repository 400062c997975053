// Paper 3.4-3.7: a vertex singularity and an edge singularity, each resolved by each strategy;
// the neighbour strategy failing where it must and the combined one succeeding there; and the
// bookkeeping a simulator relies on (change log, atomicity, statistics).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "removal_test_support.hpp"
#include "remove/neighbour_search.hpp"
#include "tetcut/canonical_hash.hpp"
#include "tetcut/io.hpp"

namespace tetcut::testing {
namespace {

constexpr RemovalStrategy kAll[] = {RemovalStrategy::kBasic, RemovalStrategy::kNeighbours,
                                    RemovalStrategy::kCombined, RemovalStrategy::kWide};

// The first tet of `mesh` whose removability names a singularity of `kind`.
TetId first_singular(const TetMesh& mesh, SingularityKind kind) {
  for (std::uint32_t i = 0; i < mesh.tet_capacity(); ++i)
    if (mesh.is_live(TetId{i}) && removability(mesh, TetId{i}).kind == kind) return TetId{i};
  return kNoTet;
}

// The requested tet's region is gone: its centroid is in no tet any more, and the volume went
// down by at least its volume.
void expect_region_gone(const TetMesh& mesh, const Vec3& centre, double volume_before, double tet_volume) {
  EXPECT_FALSE(tet_containing(mesh, centre).valid());
  EXPECT_LE(mesh.total_volume(), volume_before - tet_volume * (1 - 1e-12));
}

// A mesh with a singularity of `kind`. Vertex: a 3x3x3 box, where an interior tet (no boundary
// face) has a vertex on the surface. Edge: one cube of six tets around its diagonal, one tet
// gone; the tet facing the gap would leave the diagonal with a run of tets on each side.
TetMesh mesh_with_singularity(SingularityKind kind) {
  if (kind == SingularityKind::kVertex) return box(3, 3, 3);
  TetMesh mesh = box(1, 1, 1);
  const TetId gap[1] = {TetId{0}};
  mesh.remove_tets(gap);
  return mesh;
}

// Every distinct edge singularity 3.5 searched has one configuration in the
// report (the neighbours and combined strategies; basic and wide do not run 3.5), and those
// with a removable candidate are the ones the neighbours resolved.
void expect_edge_search_logged(RemovalStrategy strategy, const RemovalReport& report) {
  const bool searches = strategy == RemovalStrategy::kNeighbours || strategy == RemovalStrategy::kCombined;
  EXPECT_EQ(report.edge_search.total(), searches ? report.edge_singularities : 0u);
  std::uint64_t with_removable = 0;
  for (int c = 0; c < EdgeSearchTally::kConfigurations; ++c)
    for (int k = 0; k < 3; ++k)
      if (EdgeSearchTally::verdict(static_cast<std::uint16_t>(c), k) == EdgeCandidateVerdict::kRemovable) {
        with_removable += report.edge_search.counts[static_cast<std::size_t>(c)];
        break;
      }
  if (searches && report.repeated_requests == 0) {
    EXPECT_EQ(with_removable, report.edge_resolved_by_neighbours);
  }
}

// The one configuration a report with a single edge singularity logged.
std::uint16_t logged_configuration(const RemovalReport& report) {
  for (int c = 0; c < EdgeSearchTally::kConfigurations; ++c)
    if (report.edge_search.counts[static_cast<std::size_t>(c)] != 0) return static_cast<std::uint16_t>(c);
  ADD_FAILURE() << "no edge search logged";
  return 0;
}

class ASingularity : public ::testing::TestWithParam<SingularityKind> {};

TEST_P(ASingularity, IsResolvedByEachStrategy) {
  const SingularityKind kind = GetParam();
  for (RemovalStrategy strategy : kAll) {
    SCOPED_TRACE(to_string(strategy));
    TetMesh mesh = mesh_with_singularity(kind);
    const TetId t = first_singular(mesh, kind);
    ASSERT_TRUE(t.valid());
    const Vec3 centre = centroid(mesh, t);
    const double before = mesh.total_volume(), vol = mesh.volume(t);
    invariants::LocalChecker local(mesh.raw_view());
    Remover remover({.strategy = strategy});
    RemovalResult result;
    ASSERT_TRUE(remove_checked(remover, mesh, t, local, &result));
    EXPECT_EQ(result.first.kind, kind);
    // Basic at the edge: T's edges from the singular edge's ends to its other vertices are
    // cube edges on the surface, the configuration where 3.4's set is not removable
    // (docs/removal-proof.md); the fallback removes T instead.
    const RemovalOutcome basic = kind == SingularityKind::kVertex ? RemovalOutcome::kRefinement : RemovalOutcome::kFallback;
    EXPECT_EQ(result.outcome, strategy == RemovalStrategy::kBasic ? basic : RemovalOutcome::kNeighbours);
    EXPECT_TRUE(mesh_is_valid(mesh));
    expect_region_gone(mesh, centre, before, vol);
    const auto& report = remover.report();
    if (kind == SingularityKind::kVertex) {
      EXPECT_GT(result.tets_removed, 1u);
      EXPECT_EQ(report.vertex_singularities, 1u);
      EXPECT_EQ(report.removed, 1u);
    } else {
      EXPECT_EQ(report.edge_singularities, 1u);
      if (strategy != RemovalStrategy::kBasic) {
        // T with the smaller of its left and right sets: at most 3 of the 5 tets.
        EXPECT_GE(result.tets_removed, 2u);
        EXPECT_LE(result.tets_removed, 3u);
        EXPECT_DOUBLE_EQ(report.mean_cardinality(), double(result.tets_removed));
      }
      expect_edge_search_logged(strategy, report);
      if (strategy == RemovalStrategy::kNeighbours || strategy == RemovalStrategy::kCombined) {
        // Item 7's log: the side tried first is removable here (T and one or two tets of the
        // cube's ring), so the other side is tested only when smaller, and the whole set never.
        const std::uint16_t config = logged_configuration(report);
        const auto left = EdgeSearchTally::verdict(config, 0), right = EdgeSearchTally::verdict(config, 1);
        EXPECT_TRUE(left == EdgeCandidateVerdict::kRemovable || right == EdgeCandidateVerdict::kRemovable)
            << to_string(left) << " / " << to_string(right);
        EXPECT_EQ(EdgeSearchTally::verdict(config, 2), EdgeCandidateVerdict::kSkipped);
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(RemovalStrategies, ASingularity,
                         ::testing::Values(SingularityKind::kVertex, SingularityKind::kEdge),
                         [](const auto& info) { return std::string(to_string(info.param)); });

TEST(RemovalStrategies, EdgeSingularitiesInABoxAreResolvedWithValidMeshes) {
  // Edge singularities away from a hand-built corner: hollow a 3x3x2 box by repeated requests
  // until one shows up, for each strategy (a few pick orders, as a box can also be emptied
  // without meeting one); every request leaves a valid mesh.
  for (RemovalStrategy strategy : kAll) {
    SCOPED_TRACE(to_string(strategy));
    std::uint32_t met = 0;
    for (std::uint64_t seed = 11; seed < 19 && met == 0; ++seed) {
      TetMesh mesh = box(3, 3, 2);
      invariants::LocalChecker local(mesh.raw_view());
      Remover remover({.strategy = strategy});
      BoundaryTetPicker picker(mesh, seed);
      for (int i = 0; i < 400 && remover.report().edge_singularities == 0; ++i) {
        const TetId t = picker.pick(mesh);
        if (!t.valid()) break;  // emptied
        ASSERT_TRUE(remove_checked(remover, mesh, t, local));
        picker.add(remover.last_exposed());
      }
      met = remover.report().edge_singularities;
      expect_edge_search_logged(strategy, remover.report());
      EXPECT_TRUE(mesh_is_valid(mesh));
    }
    EXPECT_GT(met, 0u);
  }
}

// The cone over a 16 x 16 grid: the requested tet in the middle has its bottom face on the
// surface and the apex (on the surface too) opposite: a vertex singularity at the apex. The
// border of the apex's shell is 8 squares (more than 10 tets) away and the shell (512 tets) is
// far larger than any set the search may take: the neighbour strategy must fail. So does 3.7,
// which refines along 3.5's path and finds none: combined ends with the fallback
// (docs/removal-proof.md). Basic (3.4) splits every edge at the apex and succeeds.
TEST(RemovalStrategies, NeighboursFailsBeyondItsDepthAndCombinedThenSucceeds) {
  const TetMesh original = build_or_fail(cone_over_grid(16));
  const Vec3 middle{8.3, 8.1, 0.2};
  const TetId t = tet_containing(original, middle);
  ASSERT_TRUE(t.valid());
  const Removability r = removability(original, t);
  ASSERT_EQ(r.paper_case, 2);
  ASSERT_EQ(r.kind, SingularityKind::kVertex);

  {
    TetMesh mesh = original;
    Remover remover({.strategy = RemovalStrategy::kNeighbours});
    ChangeLog log;
    mesh.begin_transaction();
    const RemovalResult result = remover.remove(mesh, t);
    mesh.commit(&log);
    EXPECT_EQ(result.outcome, RemovalOutcome::kUnresolved);
    EXPECT_EQ(canonical_hash(mesh), canonical_hash(original));
    EXPECT_TRUE(mesh.is_live(t));
    EXPECT_TRUE(log.removed.empty());
    EXPECT_TRUE(remover.last_removed().empty());
    EXPECT_EQ(remover.report().unresolved, 1u);
    // Met again: counted once.
    remover.remove(mesh, t);
    EXPECT_EQ(remover.report().requested, 1u);
    EXPECT_EQ(remover.report().repeated_requests, 1u);
    EXPECT_EQ(remover.report().unresolved, 1u);
    EXPECT_EQ(remover.report().vertex_singularities, 1u);
  }
  for (RemovalStrategy strategy : {RemovalStrategy::kCombined, RemovalStrategy::kBasic}) {
    SCOPED_TRACE(to_string(strategy));
    TetMesh mesh = original;
    invariants::LocalChecker local(mesh.raw_view());
    Remover remover({.strategy = strategy});
    RemovalResult result;
    const double before = mesh.total_volume(), vol = mesh.volume(t);
    ASSERT_TRUE(remove_checked(remover, mesh, t, local, &result));
    const bool combined = strategy == RemovalStrategy::kCombined;
    EXPECT_EQ(result.outcome, combined ? RemovalOutcome::kFallback : RemovalOutcome::kRefinement);
    EXPECT_GT(result.edges_split, 0u);
    EXPECT_TRUE(mesh_is_valid(mesh));
    expect_region_gone(mesh, middle, before, vol);
    EXPECT_EQ(remover.report().resolved_by_refinement, combined ? 0u : 1u);
    EXPECT_EQ(remover.report().resolved_by_fallback, combined ? 1u : 0u);
  }
}

TEST(RemovalStrategies, TheChangeLogReplaysToTheSameTets) {
  // A simulator applies the log to its own copy of the mesh before the request: removed ids die,
  // created ids hold the tets the mesh has now, each with parents it had (live before, removed
  // now: never a tet the request made and split again), and every new vertex is the stated
  // combination of vertices it had.
  const TetMesh before = build_or_fail(cone_over_grid(16));
  TetMesh mesh = before;
  const TetId t = tet_containing(mesh, {8.3, 8.1, 0.2});
  Remover remover;
  ChangeLog log;
  mesh.begin_transaction();
  const RemovalResult result = remover.remove(mesh, t);
  mesh.commit(&log);
  ASSERT_EQ(result.outcome, RemovalOutcome::kFallback);  // it splits (see above)
  EXPECT_FALSE(log.vertices.empty());
  for (const CreatedVertex& v : log.vertices) {
    ASSERT_GE(v.count, 2u);
    Vec3 expected{};
    double sum = 0.0;
    for (int i = 0; i < v.count; ++i) {
      EXPECT_TRUE(before.is_live(v.from[i]));
      EXPECT_FALSE(before.is_live(v.vertex) && v.vertex == v.from[i]);
      expected = expected + v.weight[i] * before.position(v.from[i]);
      sum += v.weight[i];
    }
    EXPECT_NEAR(sum, 1.0, 1e-15);
    EXPECT_NEAR(norm(mesh.position(v.vertex) - expected), 0.0, 1e-12);
  }
  // Net, and no id reused inside the request: what went is dead, what came is live.
  EXPECT_TRUE(std::equal(log.removed.begin(), log.removed.end(), remover.last_removed().begin(), remover.last_removed().end()));
  ASSERT_EQ(log.created.size(), remover.last_created().size());
  for (TetId r : log.removed) {
    EXPECT_TRUE(before.is_live(r));
    EXPECT_FALSE(mesh.is_live(r));
  }
  for (std::size_t i = 0; i < log.created.size(); ++i) {
    const CreatedTet& c = log.created[i];
    EXPECT_EQ(c.tet, remover.last_created()[i]);
    EXPECT_TRUE(mesh.is_live(c.tet));
    ASSERT_EQ(c.parents_count, 1u) << "a split's child has one parent";
    EXPECT_EQ(c.parent, log.parents_of(c)[0]);
    EXPECT_TRUE(before.is_live(c.parent));
    EXPECT_TRUE(std::binary_search(log.removed.begin(), log.removed.end(), c.parent)) << "parents are tets the request replaced";
  }
  EXPECT_TRUE(std::binary_search(log.removed.begin(), log.removed.end(), t));
}

TEST(RemovalStrategies, DirectRemovalsAgreeWithTheSetTest) {
  // verify_direct runs set_removable on every tet the O(1) test accepts. Here: the two agree on
  // a whole hollowing of a box (the wide strategy empties it without refining).
  TetMesh mesh = box(3, 3, 3);
  Remover remover({.strategy = RemovalStrategy::kWide, .verify_direct = true});
  BoundaryTetPicker picker(mesh, 3);
  invariants::LocalChecker local(mesh.raw_view());
  for (TetId t = picker.pick(mesh); t.valid(); t = picker.pick(mesh)) {
    RemovalResult result;
    ASSERT_TRUE(remove_checked(remover, mesh, t, local, &result));
    EXPECT_FALSE(result.set_test_disagrees) << "tet " << t.value;
    picker.add(remover.last_exposed());
  }
  EXPECT_EQ(mesh.num_tets(), 0u);
  EXPECT_EQ(remover.report().unresolved, 0u);
  EXPECT_GT(remover.report().direct, 0u);
}

TEST(RemovalStrategies, TheNeighbourSearchKeepsThePathThat37RefinesAlong) {
  // Paper 3.7: "we also store the shortest path connecting the tetrahedron T to the shell
  // border"; the refinement reuses 3.5's instead of searching again. After a search on a vertex
  // singularity, path() must be T followed by exactly the shortest path (none: empty); after one
  // on an edge singularity, empty. Requests follow a hollowing of a small liver, where both kinds
  // occur.
  ReadResult read = read_mesh(std::string(TETCUT_CORPUS_DIR) + "/fuzz/meshes/liver-small.msh");
  ASSERT_TRUE(read.mesh);
  TetMesh mesh = build_or_fail(*read.mesh);
  BoundaryTetPicker picker(mesh, 37);
  Remover remover({.strategy = RemovalStrategy::kCombined});
  detail::NeighbourSearch search;
  SetRemovalWorkspace ws;
  std::vector<TetId> found, path;
  int with_path = 0, edges = 0;
  for (int i = 0; i < 3000; ++i) {
    const TetId t = picker.pick(mesh);
    if (!t.valid()) break;
    const Removability first = removability(mesh, t);
    if (!first.removable()) {
      search.find(mesh, ws, t, first, 10, 64, found);
      path.clear();
      if (first.kind == SingularityKind::kVertex && detail::shortest_path_to_border(mesh, ws, t, first.vertex, 10, path)) {
        path.insert(path.begin(), t);
        ++with_path;
      }
      edges += first.kind == SingularityKind::kEdge ? 1 : 0;
      ASSERT_EQ(std::vector<TetId>(search.path().begin(), search.path().end()), path) << "request " << i;
    }
    remover.remove(mesh, t);
    picker.add(remover.last_exposed());
  }
  EXPECT_GT(with_path, 20);
  EXPECT_GT(edges, 0);
}

// The live tets that contain every vertex of `verts` (scanned from the raw tets, not the shells).
std::uint32_t live_tets_with(const TetMesh& mesh, std::initializer_list<VertId> verts) {
  std::uint32_t n = 0;
  for (std::uint32_t i = 0; i < mesh.tet_capacity(); ++i) {
    if (!mesh.is_live(TetId{i})) continue;
    const auto tv = mesh.tet(TetId{i});
    n += std::all_of(verts.begin(), verts.end(), [&](VertId v) { return std::find(tv.begin(), tv.end(), v) != tv.end(); })
             ? 1u
             : 0u;
  }
  return n;
}

// Paper 3.4 as written: "if a topological singularity occurs at a vertex (resp. edge) then all
// edges adjacent to that vertex (resp. edge) are split and we then remove all refined tetrahedra
// adjacent to that vertex (resp. edge)". An interior tet of a box with several vertices on the
// surface has a singularity at each (at a vertex, or at an edge of T on the surface): 3.4 must
// resolve every one of them, so when its set goes, no tet is left at any singular vertex (its
// whole star went) nor on any singular edge. Where the set is not removable (docs/removal-
// proof.md) the fallback removes T instead, counted apart.
TEST(RemovalStrategies, BasicRefinesAtEverySingularityOfT) {
  const TetMesh original = box(3, 3, 3);
  SetRemovalWorkspace ws;
  int several = 0, refined = 0, fell_back = 0;
  for (std::uint32_t i = 0; i < original.tet_capacity(); ++i) {
    const TetId t{i};
    if (!original.is_live(t) || original.boundary_face_count(t) != 0) continue;
    std::vector<VertId> vertices;
    std::vector<Edge> edges;
    const TetId one[1] = {t};
    for (VertId x : original.tet(t)) {
      const Removability at_x = ws.check_at(original, one, x);
      if (at_x.kind == SingularityKind::kVertex) vertices.push_back(x);
      if (at_x.kind == SingularityKind::kEdge) edges.push_back(at_x.edge);
    }
    if (vertices.size() + edges.size() < 2) continue;
    ++several;
    SCOPED_TRACE("tet " + std::to_string(i));
    TetMesh mesh = original;
    invariants::LocalChecker local(mesh.raw_view());
    Remover remover({.strategy = RemovalStrategy::kBasic});
    RemovalResult result;
    ASSERT_TRUE(remove_checked(remover, mesh, t, local, &result));
    EXPECT_FALSE(mesh.is_live(t));
    if (result.outcome == RemovalOutcome::kFallback) {
      ++fell_back;
      continue;
    }
    ASSERT_EQ(result.outcome, RemovalOutcome::kRefinement);
    ++refined;
    for (VertId v : vertices) EXPECT_EQ(live_tets_with(mesh, {v}), 0u) << "singular vertex " << v.value;
    for (const Edge& e : edges) EXPECT_EQ(live_tets_with(mesh, {e.a, e.b}), 0u) << "singular edge " << e.a.value << "-" << e.b.value;
    EXPECT_TRUE(mesh_is_valid(mesh));
  }
  EXPECT_GT(several, 4);
  EXPECT_GT(refined, 0);
  std::printf("[basic] %d interior tets with several singularities: %d by 3.4's set, %d by the fallback\n", several,
              refined, fell_back);
}

// A cone over an L-shaped region of an n x n grid (the squares with i >= n/2 and j >= n/2 left
// out): the apex's shell is every tet, its border the cone's sides, and the reflex corner of the
// L is a border vertex that a path of tets can touch without ending there.
RawMesh cone_over_l(std::uint32_t n) {
  RawMesh raw = cone_over_grid(n);
  std::vector<std::array<std::uint32_t, 4>> kept;
  for (std::size_t k = 0; k < raw.tets.size(); ++k) {
    const std::uint32_t square = static_cast<std::uint32_t>(k / 2), i = square % n, j = square / n;
    if (i < n / 2 || j < n / 2) kept.push_back(raw.tets[k]);
  }
  raw.tets = kept;
  return raw;
}

// Paper 3.5 as written: the breadth-first search does not stop at the first path. Where the
// shortest path from T to the border of the singular vertex's shell is not removable (and no
// extension of it is), a further path within depth 10 is tested, and the smallest removable set
// found is kept. Checked on every singular tet of hand-made cones: whatever the search returns is
// removable by the set test and by the independent checker, and contains T; and there are tets
// whose first path fails where a later one succeeds.
TEST(RemovalStrategies, TheNeighbourSearchTriesFurtherPaths) {
  int later_path = 0, tested = 0;
  for (std::uint32_t n : {4u, 6u}) {
    for (const RawMesh& raw : {cone_over_grid(n), cone_over_l(n)}) {
      const TetMesh mesh = build_or_fail(raw);
      SetRemovalWorkspace ws;
      detail::NeighbourSearch search;
      std::vector<TetId> found, first_path;
      for (std::uint32_t i = 0; i < mesh.tet_capacity(); ++i) {
        const TetId t{i};
        const Removability first = removability(mesh, t);
        if (first.kind != SingularityKind::kVertex) continue;
        ++tested;
        const bool ok = search.find(mesh, ws, t, first, 10, 64, found);
        first_path.clear();
        ASSERT_TRUE(detail::shortest_path_to_border(mesh, ws, t, first.vertex, 10, first_path));
        first_path.insert(first_path.begin(), t);
        const bool first_removable = ws.check(mesh, first_path).removable();
        if (!ok) {
          EXPECT_FALSE(first_removable) << "tet " << i;
          continue;
        }
        EXPECT_TRUE(std::find(found.begin(), found.end(), t) != found.end());
        EXPECT_TRUE(ws.check(mesh, found).removable());
        EXPECT_TRUE(still_valid_without(mesh, found)) << "tet " << i;
        if (first_removable) {
          EXPECT_EQ(found.size(), first_path.size()) << "the shortest path, removable, is the smallest set";
        } else if (std::any_of(first_path.begin(), first_path.end(),
                               [&](TetId u) { return std::find(found.begin(), found.end(), u) == found.end(); })) {
          ++later_path;  // not the first path nor an extension of it: a further path won
        }
      }
    }
  }
  EXPECT_GT(tested, 20);
  EXPECT_GT(later_path, 0);
  std::printf("[3.5] %d vertex singularities, %d resolved by a path after the first\n", tested, later_path);
}

TEST(RemovalStrategies, AnEdgeConfigurationEncodesItsThreeVerdicts) {
  for (int l = 0; l < kEdgeCandidateVerdicts; ++l)
    for (int r = 0; r < kEdgeCandidateVerdicts; ++r)
      for (int w = 0; w < kEdgeCandidateVerdicts; ++w) {
        const auto c = EdgeSearchTally::configuration(EdgeCandidateVerdict(l), EdgeCandidateVerdict(r),
                                                      EdgeCandidateVerdict(w));
        ASSERT_LT(c, EdgeSearchTally::kConfigurations);
        EXPECT_EQ(EdgeSearchTally::verdict(c, 0), EdgeCandidateVerdict(l));
        EXPECT_EQ(EdgeSearchTally::verdict(c, 1), EdgeCandidateVerdict(r));
        EXPECT_EQ(EdgeSearchTally::verdict(c, 2), EdgeCandidateVerdict(w));
      }
}

TEST(RemovalStrategies, NamesRoundTrip) {
  for (RemovalStrategy s : kAll) EXPECT_EQ(parse_removal_strategy(to_string(s)), s);
  EXPECT_EQ(parse_removal_strategy("neighbors"), RemovalStrategy::kNeighbours);
  EXPECT_FALSE(parse_removal_strategy("fast").has_value());
}

}  // namespace
}  // namespace tetcut::testing
