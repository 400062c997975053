// Paper 3.3: the O(1) removability test, and the local test for sets, agree with what the
// independent checker finds after actually removing the tets.
#include <gtest/gtest.h>

#include <array>
#include <set>
#include <utility>

#include "core/random.hpp"
#include "refine/edge_split.hpp"
#include "removal_test_support.hpp"
#include "remove/set_removal.hpp"
#include "tetcut/detail/local_tables.hpp"
#include "tetcut/io.hpp"

namespace tetcut::testing {
namespace {

// (case, removable) pairs met while checking a mesh tet by tet.
using Seen = std::set<std::pair<int, bool>>;

// For every live tet: removability()'s verdict == the checker's verdict on the mesh without it,
// and set_removable({t}) says the same; the singular vertex or edge named belongs to the tet,
// and the tet named is t.
void expect_single_removals_agree(const TetMesh& mesh, Seen* seen) {
  SetRemovalWorkspace ws;
  for (std::uint32_t i = 0; i < mesh.tet_capacity(); ++i) {
    const TetId t{i};
    if (!mesh.is_live(t)) continue;
    const Removability r = removability(mesh, t);
    const TetId one[1] = {t};
    const bool valid_after = still_valid_without(mesh, one);
    EXPECT_EQ(r.removable(), valid_after) << "tet " << i << " case " << int(r.paper_case);
    EXPECT_EQ(ws.check(mesh, one).removable(), valid_after) << "tet " << i;
    EXPECT_EQ(r.paper_case, std::min(mesh.boundary_face_count(t), 3) + 1);
    if (r.kind == SingularityKind::kVertex) {
      EXPECT_GE(mesh.local_index(t, r.vertex), 0);
      EXPECT_TRUE(mesh.is_boundary_vertex(r.vertex));
    }
    if (r.kind == SingularityKind::kEdge) {
      EXPECT_EQ(r.paper_case, 3);
      EXPECT_GE(mesh.local_index(t, r.edge.a), 0);
      EXPECT_GE(mesh.local_index(t, r.edge.b), 0);
      // Named as the set test names an edge: where a repair search starts (wide_search.hpp).
      EXPECT_EQ(r.local_edge, mesh.local_edge(t, r.edge.a, r.edge.b));
    }
    if (!r.removable()) {
      EXPECT_EQ(r.tet, t);
    }
    if (seen) seen->insert({r.paper_case, r.removable()});
  }
}

TEST(Removability, Case4ASingleTetAndTwoTetsAreAlwaysRemovable) {
  TetMesh one = build_or_fail(single_tet());
  const Removability r = removability(one, TetId{0});
  EXPECT_TRUE(r.removable());
  EXPECT_EQ(r.paper_case, 4);

  RawMesh two = single_tet();
  two.positions.push_back({1, 1, 1});
  two.tets.push_back({1, 2, 3, 4});  // shares face (1, 2, 3) with the first tet
  TetMesh mesh = build_or_fail(two);
  Seen seen;
  expect_single_removals_agree(mesh, &seen);
  EXPECT_EQ(seen, (Seen{{4, true}}));
}

TEST(Removability, Case3RemovableAroundAnInteriorEdgeAndNotAroundABoundaryOne) {
  // One cube, six tets around its interior diagonal: two faces each on the cube's surface, the
  // edge opposite both is the diagonal, interior: removable.
  TetMesh mesh = box(1, 1, 1);
  for (std::uint32_t i = 0; i < 6; ++i) {
    const Removability r = removability(mesh, TetId{i});
    EXPECT_EQ(r.paper_case, 3);
    EXPECT_TRUE(r.removable());
  }
  // Once one goes the diagonal is on the surface: the tets not adjacent to the gap are case 3
  // with their opposite edge on the boundary, an edge singularity at the diagonal.
  const TetId first[1] = {TetId{0}};
  mesh.remove_tets(first);
  Seen seen;
  expect_single_removals_agree(mesh, &seen);
  EXPECT_TRUE(seen.count({3, false}));
  EXPECT_TRUE(seen.count({4, true}));
  int edge_singular = 0;
  for (std::uint32_t i = 1; i < 6; ++i) {
    const Removability r = removability(mesh, TetId{i});
    if (r.kind != SingularityKind::kEdge) continue;
    ++edge_singular;
    // The diagonal (0,0,0)-(1,1,1).
    const Vec3 a = mesh.position(r.edge.a), b = mesh.position(r.edge.b);
    EXPECT_DOUBLE_EQ(std::abs(a.x - b.x) + std::abs(a.y - b.y) + std::abs(a.z - b.z), 3.0);
  }
  EXPECT_EQ(edge_singular, 3);
}

TEST(Removability, Cases1And2BothOutcomesInABox) {
  // A 3x3x3 box has interior vertices (case 1 and 2 removable), tets with no boundary face
  // touching the surface at a vertex (case 1 not removable) and tets with one boundary face
  // whose opposite vertex is on the surface too (case 2 not removable).
  TetMesh mesh = box(3, 3, 3);
  Seen seen;
  expect_single_removals_agree(mesh, &seen);
  EXPECT_TRUE(seen.count({1, true}));
  EXPECT_TRUE(seen.count({1, false}));
  EXPECT_TRUE(seen.count({2, true}));
  EXPECT_TRUE(seen.count({2, false}));
  EXPECT_TRUE(seen.count({3, true}));
}

TEST(Removability, AgreesWithTheCheckerOnThinAndDentedBoxes) {
  // A one-layer slab (every vertex on the surface) and a box with a few tets already gone.
  Seen seen;
  expect_single_removals_agree(box(3, 2, 1), &seen);
  TetMesh dented = box(2, 2, 2);
  Remover remover;
  for (std::uint32_t i : {0u, 7u, 20u, 33u, 41u}) {
    if (dented.is_live(TetId{i})) remover.remove(dented, TetId{i});
    ASSERT_TRUE(mesh_is_valid(dented));
    expect_single_removals_agree(dented, &seen);
  }
  for (int c = 1; c <= 3; ++c) EXPECT_TRUE(seen.count({c, false})) << "case " << c;
}

// Grows `set` to `want` tets (at most `steps` tries) by random face neighbours of its tets: a
// random face-connected set.
void grow_connected(const TetMesh& mesh, std::vector<TetId>& set, std::size_t want, SplitMix64& rng, int steps) {
  for (int step = 0; step < steps && set.size() < want; ++step) {
    const TetId from = set[rng.below(static_cast<std::uint32_t>(set.size()))];
    const FaceRef n = mesh.neighbour(from, static_cast<int>(rng.below(4)));
    if (n.valid() && std::find(set.begin(), set.end(), n.tet) == set.end()) set.push_back(n.tet);
  }
}

TEST(SetRemoval, AgreesWithTheCheckerOnRandomConnectedSets) {
  // Random face-connected sets of 2..8 tets grown from random tets, near the surface and deep
  // inside: the local test says "removable" exactly when the checker finds the mesh without
  // them valid, and names a vertex or edge of the set when it does not.
  TetMesh mesh = box(3, 3, 3);
  SetRemovalWorkspace ws;
  SplitMix64 rng(7);
  int removable = 0, not_removable = 0;
  std::vector<TetId> set;
  for (int trial = 0; trial < 400; ++trial) {
    set.assign(1, TetId{rng.below(mesh.tet_capacity())});
    grow_connected(mesh, set, 2 + rng.below(7), rng, 40);
    const Removability check = ws.check(mesh, set);
    EXPECT_EQ(check.removable(), still_valid_without(mesh, set)) << "trial " << trial;
    if (check.removable()) {
      ++removable;
    } else {
      ++not_removable;
      EXPECT_TRUE(std::find(set.begin(), set.end(), check.tet) != set.end());
      if (check.kind == SingularityKind::kVertex) {
        EXPECT_GE(mesh.local_index(check.tet, check.vertex), 0);
      }
      if (check.kind == SingularityKind::kEdge) {
        EXPECT_EQ(mesh.vertex(check.tet, kEdgeVerts[check.local_edge][0]), check.edge.a);
        EXPECT_EQ(mesh.vertex(check.tet, kEdgeVerts[check.local_edge][1]), check.edge.b);
      }
    }
  }
  EXPECT_GT(removable, 20);
  EXPECT_GT(not_removable, 20);
}

TEST(SetRemoval, ATestedPrefixGivesTheVerdictOfAFullTest) {
  // The searches test a failing set extended by a few tets and tell the test what the failing
  // set's own test found (TestedPrefix), so that the vertices that passed and that no added tet
  // touches are not walked again. The answer, offence and all, must be the full test's.
  for (const char* name : {"liver-small.msh", "cylinder-small.msh"}) {
    ReadResult read = read_mesh(std::string(TETCUT_CORPUS_DIR) + "/fuzz/meshes/" + name);
    ASSERT_TRUE(read.mesh.has_value()) << name;
    const TetMesh mesh = build_or_fail(*read.mesh);
    SetRemovalWorkspace ws;
    SplitMix64 rng(404);
    std::vector<TetId> set;
    int reused = 0, became_removable = 0, still_failing = 0;
    auto grow = [&](std::size_t want) { grow_connected(mesh, set, want, rng, 200); };
    for (int trial = 0; trial < 600; ++trial) {
      set.assign(1, TetId{rng.below(mesh.tet_capacity())});
      grow(2 + rng.below(12));
      const Removability base = ws.check(mesh, set);
      if (base.removable()) continue;
      const TestedPrefix prefix{static_cast<std::uint32_t>(set.size()), base.vertices_passed};
      grow(set.size() + 1 + rng.below(6));
      const Removability full = ws.check(mesh, set);
      const Removability quick = ws.check(mesh, set, prefix);
      ASSERT_EQ(quick.removable(), full.removable()) << name << " trial " << trial;
      EXPECT_EQ(quick.vertices_passed, full.vertices_passed) << name << " trial " << trial;
      if (!full.removable()) {
        EXPECT_EQ(quick.kind, full.kind) << name << " trial " << trial;
        EXPECT_EQ(quick.tet, full.tet) << name << " trial " << trial;
        EXPECT_EQ(quick.vertex, full.vertex) << name << " trial " << trial;
        EXPECT_EQ(quick.local_edge, full.local_edge) << name << " trial " << trial;
      }
      reused += prefix.vertices > 0;
      (full.removable() ? became_removable : still_failing) += 1;
    }
    // The reuse happened, and both verdicts occur.
    EXPECT_GT(reused, 50) << name;
    EXPECT_GT(became_removable, 10) << name;
    EXPECT_GT(still_failing, 50) << name;
  }
}

// Random face-connected sets on the small fuzz meshes (irregular, with slivers near the surface).
template <class Body>
void for_random_sets(const char* name, std::uint64_t seed, int trials, Body&& body) {
  ReadResult read = read_mesh(std::string(TETCUT_CORPUS_DIR) + "/fuzz/meshes/" + name);
  ASSERT_TRUE(read.mesh.has_value()) << name;
  const TetMesh mesh = build_or_fail(*read.mesh);
  SplitMix64 rng(seed);
  std::vector<TetId> set;
  for (int trial = 0; trial < trials; ++trial) {
    set.assign(1, TetId{rng.below(mesh.tet_capacity())});
    grow_connected(mesh, set, 1 + rng.below(10), rng, 200);
    body(mesh, set, rng, trial);
  }
}

TEST(SetRemoval, TheTestAtOneVertexIsTheFullTestThere) {
  // check_at(set, v) is what 3.7 plans with: the set passes the full test iff it passes at each
  // of its vertices, and where the full test names an offence the test at that vertex names
  // the same one.
  for (const char* name : {"liver-small.msh", "cylinder-small.msh"}) {
    int failing = 0, passing = 0;
    for_random_sets(name, 505, 500, [&](const TetMesh& mesh, const std::vector<TetId>& set, SplitMix64&, int trial) {
      SetRemovalWorkspace ws;
      const Removability full = ws.check(mesh, set);
      std::set<std::uint32_t> vertices;
      for (TetId t : set)
        for (VertId v : mesh.tet(t)) vertices.insert(v.value);
      bool all_pass = true;
      for (std::uint32_t v : vertices) all_pass = all_pass && ws.check_at(mesh, set, VertId{v}).removable();
      ASSERT_EQ(all_pass, full.removable()) << name << " trial " << trial;
      (full.removable() ? passing : failing) += 1;
      if (full.removable()) return;
      if (full.kind == SingularityKind::kVertex) {
        const Removability there = ws.check_at(mesh, set, full.vertex);
        ASSERT_FALSE(there.removable()) << name << " trial " << trial;
        EXPECT_EQ(there.kind, full.kind) << name << " trial " << trial;
        EXPECT_EQ(there.vertex, full.vertex) << name << " trial " << trial;
        EXPECT_EQ(there.tet, full.tet) << name << " trial " << trial;
        return;
      }
      // An edge with two runs is found by the walk at one of its ends: that end names it alike.
      bool named = false;
      for (VertId end : {full.edge.a, full.edge.b}) {
        const Removability there = ws.check_at(mesh, set, end);
        named = named || (!there.removable() && there.kind == SingularityKind::kEdge && there.tet == full.tet &&
                          there.local_edge == full.local_edge);
      }
      EXPECT_TRUE(named) << name << " trial " << trial;
    });
    EXPECT_GT(failing, 50) << name;
    EXPECT_GT(passing, 50) << name;
  }
}

TEST(SetRemoval, SplittingAtAVertexKeepsTheVerdictThere) {
  // The lemma 3.7's plan rests on (docs/removal-proof.md, "3.7, planned"): split every edge from
  // v to the other vertices of a group G of tets at v; the corners of G (their children at v)
  // pass the test at v after the split iff G passes at v before it. Groups are random
  // face-connected sets of tets around a random vertex, on a surface vertex and off it.
  for (const char* name : {"liver-small.msh", "cylinder-small.msh"}) {
    int agree_pass = 0, agree_fail = 0;
    for_random_sets(name, 606, 300, [&](const TetMesh& base, const std::vector<TetId>& set, SplitMix64& rng,
                                         int trial) {
      const VertId v = base.vertex(set.front(), static_cast<int>(rng.below(4)));
      std::vector<TetId> group;
      for (TetId t : set)
        if (base.local_index(t, v) >= 0) group.push_back(t);
      SetRemovalWorkspace ws;
      const bool before = ws.check_at(base, group, v).removable();
      TetMesh mesh = base;
      std::vector<Edge> edges;
      for (TetId t : group)
        for (VertId w : mesh.tet(t))
          if (w != v) edges.push_back({v, w, t});
      EdgeSplitter splitter;
      ChangeLog log;
      mesh.begin_transaction();
      const SplitResult split = splitter.split(mesh, edges, SplitMethod::kTemplates);
      mesh.commit(&log);
      if (!split.ok()) return;  // a degenerate child refused: nothing to compare
      std::vector<TetId> corners;
      for (const CreatedTet& c : log.created)
        if (std::find(group.begin(), group.end(), c.parent) != group.end() && mesh.local_index(c.tet, v) >= 0)
          corners.push_back(c.tet);
      ASSERT_EQ(corners.size(), group.size()) << name << " trial " << trial << ": one corner per tet of G";
      const bool after = ws.check_at(mesh, corners, v).removable();
      ASSERT_EQ(after, before) << name << " trial " << trial;
      (before ? agree_pass : agree_fail) += 1;
    });
    EXPECT_GT(agree_pass, 30) << name;
    EXPECT_GT(agree_fail, 30) << name;
  }
}

TEST(SetRemoval, APathThatPinchesAVertexIsRefusedByTheEulerTest) {
  // Any two of the six tets around the cube's diagonal: two opposite ones leave the diagonal
  // with two separate runs of tets (a singular edge), which the checker names; the local test
  // must refuse exactly those pairs.
  TetMesh mesh = box(1, 1, 1);
  SetRemovalWorkspace ws;
  int refused = 0;
  for (std::uint32_t a = 0; a < 6; ++a)
    for (std::uint32_t b = a + 1; b < 6; ++b) {
      const TetId pair[2] = {TetId{a}, TetId{b}};
      const bool valid_after = still_valid_without(mesh, pair);
      EXPECT_EQ(ws.check(mesh, pair).removable(), valid_after) << a << "," << b;
      refused += !valid_after;
    }
  EXPECT_GT(refused, 0);
}

TEST(SetRemoval, AgreesWithTheCheckerOnIrregularMeshesAndShells) {
  // The vertex test follows the interface between kept and removed tets in each link instead of
  // walking whole shells, so it is held against the checker on irregular meshes (the small fuzz
  // meshes: surface vertices with wide fans, interior vertices with spherical links) and on the
  // sets that make its cases: random face-connected sets, a vertex's shell with a random part
  // kept (a disk, an annulus or pieces stay), and two separate pieces of one shell.
  int removable = 0, vertex_refusals = 0, edge_refusals = 0;
  for (const char* name : {"liver-small.msh", "cylinder-small.msh", "sheet-small.msh"}) {
    ReadResult read = read_mesh(std::string(TETCUT_CORPUS_DIR) + "/fuzz/meshes/" + name);
    ASSERT_TRUE(read.mesh.has_value()) << name;
    const TetMesh mesh = build_or_fail(*read.mesh);
    SetRemovalWorkspace ws;
    SplitMix64 rng(2026);
    std::vector<TetId> set, shell;
    auto grow_from = [&](TetId seed, std::uint32_t want, std::span<const TetId> within) {
      if (std::find(set.begin(), set.end(), seed) != set.end()) return;  // distinct tets only
      const std::size_t first = set.size();
      set.push_back(seed);
      for (int step = 0; step < 200 && set.size() - first < want; ++step) {
        const TetId from = set[first + rng.below(static_cast<std::uint32_t>(set.size() - first))];
        const FaceRef n = mesh.neighbour(from, static_cast<int>(rng.below(4)));
        if (!n.valid() || std::find(set.begin(), set.end(), n.tet) != set.end()) continue;
        if (!within.empty() && std::find(within.begin(), within.end(), n.tet) == within.end()) continue;
        set.push_back(n.tet);
      }
    };
    for (int trial = 0; trial < 600; ++trial) {
      set.clear();
      TetId seed{rng.below(mesh.tet_capacity())};
      const int kind = trial % 3;
      if (kind == 0) {
        grow_from(seed, 1 + rng.below(24), {});
      } else {
        const VertId v = mesh.vertex(seed, static_cast<int>(rng.below(4)));
        mesh.vertex_shell(v, shell);
        if (kind == 1) {
          // The whole shell but a random face-connected part of it.
          std::vector<TetId> kept;
          std::swap(set, kept);
          grow_from(shell[rng.below(static_cast<std::uint32_t>(shell.size()))], 1 + rng.below(static_cast<std::uint32_t>(shell.size())), shell);
          std::swap(set, kept);
          for (TetId t : shell)
            if (std::find(kept.begin(), kept.end(), t) == kept.end()) set.push_back(t);
          if (set.empty()) continue;
        } else {
          // Two random pieces of the shell.
          grow_from(shell[rng.below(static_cast<std::uint32_t>(shell.size()))], 1 + rng.below(4), shell);
          grow_from(shell[rng.below(static_cast<std::uint32_t>(shell.size()))], 1 + rng.below(4), shell);
        }
      }
      const Removability check = ws.check(mesh, set);
      ASSERT_EQ(check.removable(), still_valid_without(mesh, set)) << name << " trial " << trial << " kind " << kind;
      removable += check.removable();
      vertex_refusals += check.kind == SingularityKind::kVertex;
      edge_refusals += check.kind == SingularityKind::kEdge;
    }
  }
  // Every outcome occurs often enough for the agreement to mean something.
  EXPECT_GT(removable, 100);
  EXPECT_GT(vertex_refusals, 100);
  EXPECT_GT(edge_refusals, 100);
}

}  // namespace
}  // namespace tetcut::testing
