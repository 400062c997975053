#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <map>
#include <numeric>
#include <set>
#include <bit>
#include <cmath>

#include "checked.hpp"
#include "core/quality.hpp"
#include "core/random.hpp"
#include "refine/edge_split.hpp"
#include "refine/split_templates.hpp"
#include "test_meshes.hpp"
#include "tetcut/canonical_hash.hpp"
#include "tetcut/detail/local_tables.hpp"
#include "tetcut/io.hpp"
#include "tetcut/predicates.hpp"

namespace tetcut {
namespace {

// A generic (irregular) positive tet whose local vertex i gets global id perm[i].
RawMesh single_tet_with_ids(const std::array<std::uint32_t, 4>& perm) {
  const Vec3 corner[4] = {{0.1, 0.05, 0.0}, {1.3, 0.1, 0.2}, {0.2, 1.1, 0.1}, {0.3, 0.2, 0.9}};
  RawMesh raw;
  raw.positions.resize(4);
  for (int i = 0; i < 4; ++i) raw.positions[perm[i]] = corner[i];
  raw.tets.push_back(perm);
  return raw;
}

std::vector<Edge> edges_of_mask(const TetMesh& mesh, TetId t, int mask) {
  std::vector<Edge> edges;
  for (int e = 0; e < 6; ++e)
    if ((mask >> e) & 1) edges.push_back({mesh.vertex(t, kEdgeVerts[e][0]), mesh.vertex(t, kEdgeVerts[e][1])});
  return edges;
}

// The paper's ten configurations, named by the shape of the split edges.
std::string configuration(int mask) {
  const int n = std::popcount(static_cast<unsigned>(mask));
  auto on_face = [&](int m) {
    for (int f = 0; f < 4; ++f) {
      bool all_on_face = true;
      for (int e = 0; e < 6; ++e)
        if ((m >> e) & 1) all_on_face = all_on_face && kEdgeVerts[e][0] != f && kEdgeVerts[e][1] != f;
      if (all_on_face) return true;
    }
    return false;
  };
  auto around_vertex = [&](int m) {
    for (int v = 0; v < 4; ++v) {
      bool all = true;
      for (int e = 0; e < 6; ++e)
        if ((m >> e) & 1) all = all && (kEdgeVerts[e][0] == v || kEdgeVerts[e][1] == v);
      if (all) return true;
    }
    return false;
  };
  switch (n) {
    case 1: return "1 edge";
    case 2: return on_face(mask) ? "2 edges on a face" : "2 opposite edges";
    case 3: return on_face(mask) ? "3 edges on a face" : around_vertex(mask) ? "3 edges around a vertex" : "3 edges along a path";
    case 4: {
      const int missing = 63 & ~mask;
      return on_face(missing) ? "4 edges, 2 unsplit on a face" : "4 edges, 2 unsplit opposite";
    }
    case 5: return "5 edges";
    default: return "6 edges";
  }
}

// Every subset of the 6 edges under every ordering of the vertex ids gives a valid
// mesh with the configuration's tet count and the parent's volume, under both face rules.
TEST(EdgeSplit, EverySubsetUnderEveryVertexOrderIsValidAndKeepsVolume) {
  std::map<std::string, std::set<std::uint32_t>> counts;
  for (SplitMethod method : {SplitMethod::kTemplates, SplitMethod::kBisection}) {
    for (FaceRule rule : {FaceRule::kLongerEdge, FaceRule::kVertexOrder}) {
      if (method == SplitMethod::kBisection && rule != FaceRule::kLongerEdge) continue;  // bisection has no face rule
      for (int mask = 1; mask < 64; ++mask) {
        std::array<std::uint32_t, 4> perm = {0, 1, 2, 3};
        do {
          TetMesh mesh = testing::build_or_fail(single_tet_with_ids(perm));
          const double volume = mesh.total_volume();
          EdgeSplitter splitter;
          splitter.set_face_rule(rule);
          const SplitResult r = splitter.split(mesh, edges_of_mask(mesh, TetId{0}, mask), method);
          ASSERT_TRUE(r.ok()) << to_string(r.refusal);
          ASSERT_TRUE(testing::mesh_is_valid(mesh, invariants::CheckLevel::kExact)) << "mask " << mask;
          EXPECT_NEAR(mesh.total_volume(), volume, 1e-12 * volume) << "mask " << mask;
          EXPECT_EQ(r.edges_split, static_cast<std::uint32_t>(std::popcount(static_cast<unsigned>(mask))));
          EXPECT_EQ(mesh.num_vertices(), 4 + r.edges_split);
          if (method == SplitMethod::kTemplates) {
            if (rule == FaceRule::kVertexOrder) {  // the paper's template, or its alternative interior
              const SplitTemplate& tpl = split_template(static_cast<std::uint8_t>(mask), vertex_order_index(perm));
              const FaceFans fans = face_fans(FaceRule::kVertexOrder, static_cast<std::uint8_t>(mask), perm, {});
              const SplitTemplate& other = split_template_alternative(static_cast<std::uint8_t>(mask), fans);
              EXPECT_TRUE(r.tets_created == tpl.count || (other.count > 0 && r.tets_created == other.count));
            }
            counts[configuration(mask)].insert(r.tets_created);
          }
        } while (std::next_permutation(perm.begin(), perm.end()));
      }
    }
  }
  // The paper's ten configurations and their tet counts.
  const std::map<std::string, std::set<std::uint32_t>> expected = {
      {"1 edge", {2}},
      {"2 edges on a face", {3}},
      {"2 opposite edges", {4}},
      {"3 edges on a face", {4}},
      {"3 edges around a vertex", {4}},
      {"3 edges along a path", {4, 5}},
      {"4 edges, 2 unsplit on a face", {5, 6}},
      {"4 edges, 2 unsplit opposite", {6}},
      {"5 edges", {7}},
      {"6 edges", {8}},
  };
  EXPECT_EQ(counts, expected);
}

// The area of the boundary surface: a face triangulated differently from its two sides opens a
// crack inside the mesh, whose two sides add to it.
double boundary_area(const TetMesh& m) {
  std::vector<FaceRef> faces;
  m.boundary_faces(faces);
  double area = 0;
  for (const FaceRef& f : faces) {
    const Vec3 a = m.position(m.vertex(f.tet, kFaceVerts[f.face][0])), b = m.position(m.vertex(f.tet, kFaceVerts[f.face][1])),
               c = m.position(m.vertex(f.tet, kFaceVerts[f.face][2]));
    area += 0.5 * norm(cross(b - a, c - a));
  }
  return area;
}

// Two tets sharing a face, each with its own subset of split edges: the shared face must be
// triangulated alike from both sides (no crack: the boundary area stays that of the pair). The
// shared face is scalene, so that kLongerEdge decides it from its lengths, and the pair is tried
// under every numbering of its five vertices' ids that the two orders of its tets give.
TEST(EdgeSplit, NeighboursWithDifferentSubsetsStayConformal) {
  const std::vector<Vec3> corners = {{0, 0, 0}, {1.2, 0.1, 0}, {0.1, 0.9, 0.05}, {0.05, 0.1, 1.4}, {1.1, 0.9, 0.8}};
  for (FaceRule rule : {FaceRule::kLongerEdge, FaceRule::kVertexOrder})
    for (const std::array<std::uint32_t, 5>& ids : {std::array<std::uint32_t, 5>{0, 1, 2, 3, 4}, {4, 2, 0, 3, 1}, {1, 3, 4, 0, 2}}) {
      RawMesh raw;
      raw.positions.resize(5);
      for (int i = 0; i < 5; ++i) raw.positions[ids[static_cast<std::size_t>(i)]] = corners[static_cast<std::size_t>(i)];
      raw.tets = {{ids[0], ids[1], ids[2], ids[3]}, {ids[1], ids[2], ids[3], ids[4]}};
      BuildResult built = build_mesh(raw, {.reorient_inverted = true});  // whatever the orientation
      ASSERT_TRUE(built.ok());
      const RawMesh base = built.mesh->to_raw();
      for (int mask0 = 1; mask0 < 64; ++mask0)
        for (int mask1 = 0; mask1 < 64; mask1 += 7) {
          TetMesh mesh = testing::build_or_fail(base);
          const double area = boundary_area(mesh);
          std::vector<Edge> edges = edges_of_mask(mesh, TetId{0}, mask0);
          const std::vector<Edge> more = edges_of_mask(mesh, TetId{1}, mask1);
          edges.insert(edges.end(), more.begin(), more.end());
          EdgeSplitter splitter;
          splitter.set_face_rule(rule);
          ASSERT_TRUE(splitter.split(mesh, edges, SplitMethod::kTemplates).ok());
          ASSERT_TRUE(testing::mesh_is_valid(mesh, invariants::CheckLevel::kExact)) << mask0 << " " << mask1;
          ASSERT_NEAR(boundary_area(mesh), area, 1e-12) << mask0 << " " << mask1;
        }
    }
}

TEST(EdgeSplit, UniformRefinementGivesEightTimesTheTets) {
  for (SplitMethod method : {SplitMethod::kTemplates, SplitMethod::kBisection}) {
    TetMesh mesh = testing::build_or_fail(make_box_mesh(3, 2, 2));
    const std::uint32_t tets = mesh.num_tets();
    const double volume = mesh.total_volume();
    std::vector<Edge> all;
    for (std::uint32_t t = 0; t < mesh.tet_capacity(); ++t)
      for (int e = 0; e < 6; ++e) all.push_back({mesh.vertex(TetId{t}, kEdgeVerts[e][0]), mesh.vertex(TetId{t}, kEdgeVerts[e][1])});
    EdgeSplitter splitter;
    ChangeLog log;
    mesh.begin_transaction();
    const SplitResult r = splitter.split(mesh, all, method);
    mesh.commit(&log);
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(mesh.num_tets(), 8 * tets);
    EXPECT_EQ(log.removed.size(), tets);
    EXPECT_EQ(log.created.size(), 8u * tets);
    EXPECT_EQ(log.vertices.size(), r.edges_split);
    EXPECT_TRUE(testing::mesh_is_valid(mesh, invariants::CheckLevel::kExact, volume));
  }
}

TEST(EdgeSplit, RandomEdgeSetsKeepTheMeshValidAfterEverySplit) {
  TetMesh mesh = testing::build_or_fail(make_box_mesh(3, 3, 3));
  const double volume = mesh.total_volume();
  SplitMix64 rng(2024);
  EdgeSplitter splitter;
  for (int round = 0; round < 25; ++round) {
    std::vector<Edge> edges;
    const int n = 1 + static_cast<int>(rng.below(12));
    while (static_cast<int>(edges.size()) < n) {
      const TetId t{rng.below(mesh.tet_capacity())};
      if (!mesh.is_live(t)) continue;
      const int e = static_cast<int>(rng.below(6));
      edges.push_back({mesh.vertex(t, kEdgeVerts[e][0]), mesh.vertex(t, kEdgeVerts[e][1])});
    }
    invariants::LocalChecker local(mesh.raw_view());
    ChangeLog log;
    mesh.begin_transaction();
    ASSERT_TRUE(splitter.split(mesh, edges, round % 2 ? SplitMethod::kBisection : SplitMethod::kTemplates).ok());
    mesh.commit(&log);
    std::vector<TetId> created;
    for (const CreatedTet& c : log.created) created.push_back(c.tet);
    // A raw split: its quality is reported, not judged (I7 judges Cutter transactions).
    EXPECT_TRUE(local.after_operation(mesh.raw_view(), log.removed, created,
                                      {.level = invariants::CheckLevel::kLocal, .quality_rule = invariants::QualityRule::kReportOnly}, 0.0)
                    .ok());
    ASSERT_TRUE(testing::mesh_is_valid(mesh, invariants::CheckLevel::kFull, volume)) << "round " << round;
  }
}

// A box whose interior vertices are moved by up to a tenth of a cell (seeded): its faces are
// scalene, so kLongerEdge decides them (a regular box ties everywhere and falls back to vertex
// order).
RawMesh jittered_box(std::uint32_t n, std::uint64_t seed) {
  RawMesh raw = make_box_mesh(n, n, n);
  SplitMix64 rng(seed);
  const double h = 1.0 / n;
  auto inside = [](double x) { return x > 1e-9 && x < 1 - 1e-9; };
  for (Vec3& p : raw.positions)
    if (inside(p.x) && inside(p.y) && inside(p.z)) p = p + (0.2 * h) * Vec3{rng.unit() - 0.5, rng.unit() - 0.5, rng.unit() - 0.5};
  return raw;
}

struct SplitRun {
  std::uint64_t hash = 0;
  std::uint32_t tets = 0;
};

// `rounds` splits of a few edges each, drawn around a random tet (its edges and its neighbours'),
// so that many tets get several split edges at once. After every split the local checker passes
// and the boundary keeps its area; at the end the full check passes. `shuffle`: the edges of
// each round are given in a scrambled order (the same edges).
SplitRun random_splits(const RawMesh& raw, std::uint64_t seed, int rounds, SplitMethod method, FaceRule rule, bool shuffle) {
  TetMesh mesh = testing::build_or_fail(raw);
  const double volume = mesh.total_volume();
  const double area = boundary_area(mesh);
  SplitMix64 rng(seed), order(seed + 1);
  EdgeSplitter splitter;
  splitter.set_face_rule(rule);
  for (int round = 0; round < rounds; ++round) {
    std::vector<Edge> edges;
    const TetId centre = testing::random_live_tet(mesh, rng);
    std::vector<TetId> around = {centre};
    for (int f = 0; f < 4; ++f)
      if (const FaceRef n = mesh.neighbour(centre, f); n.valid()) around.push_back(n.tet);
    const int n = 2 + static_cast<int>(rng.below(10));
    for (int k = 0; k < n; ++k) {
      const TetId t = around[rng.below(around.size())];
      const int e = static_cast<int>(rng.below(6));
      edges.push_back({mesh.vertex(t, kEdgeVerts[e][0]), mesh.vertex(t, kEdgeVerts[e][1])});
    }
    if (shuffle)
      for (std::size_t i = edges.size() - 1; i > 0; --i) {
        std::swap(edges[i], edges[order.below(i + 1)]);
        if (order.below(2)) std::swap(edges[i].a, edges[i].b);
      }
    invariants::LocalChecker local(mesh.raw_view());
    ChangeLog log;
    mesh.begin_transaction();
    const SplitResult r = splitter.split(mesh, edges, method);
    mesh.commit(&log);
    EXPECT_TRUE(r.ok()) << to_string(r.refusal);
    std::vector<TetId> created;
    for (const CreatedTet& c : log.created) created.push_back(c.tet);
    // A raw split: its quality is reported, not judged (I7 judges Cutter transactions).
    const invariants::CheckOptions raw{.level = invariants::CheckLevel::kLocal, .quality_rule = invariants::QualityRule::kReportOnly};
    EXPECT_TRUE(local.after_operation(mesh.raw_view(), log.removed, created, raw, 0.0).ok()) << "round " << round;
    EXPECT_NEAR(boundary_area(mesh), area, 1e-9 * area) << "round " << round;
  }
  EXPECT_TRUE(testing::mesh_is_valid(mesh, invariants::CheckLevel::kFull, volume));
  return {canonical_hash(mesh), mesh.num_tets()};
}

// Random multi-edge splits on a jittered box and on bundled meshes, under both face rules and
// with bisection: valid and conforming after every split (random_splits), and the same mesh bit
// for bit when run again with the edges in another order. The two rules make different meshes
// (the geometric rule was exercised); bisection has no face rule.
TEST(EdgeSplit, RandomMultiEdgeSplitsAreValidConformingAndDeterministic) {
  struct Case {
    std::string name;
    RawMesh raw;
  };
  std::vector<Case> cases = {{"jittered box", jittered_box(4, 11)}};
  for (const char* name : {"liver-coarse.msh", "cylinder.msh"}) {
    ReadResult read = read_mesh(std::string(TETCUT_CORPUS_DIR) + "/meshes/" + name);
    ASSERT_TRUE(read.mesh) << name;
    cases.push_back({name, *read.mesh});
  }
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    const SplitRun longer = random_splits(c.raw, 5, 40, SplitMethod::kTemplates, FaceRule::kLongerEdge, false);
    EXPECT_EQ(random_splits(c.raw, 5, 40, SplitMethod::kTemplates, FaceRule::kLongerEdge, true).hash, longer.hash);
    const SplitRun paper = random_splits(c.raw, 5, 40, SplitMethod::kTemplates, FaceRule::kVertexOrder, false);
    EXPECT_EQ(random_splits(c.raw, 5, 40, SplitMethod::kTemplates, FaceRule::kVertexOrder, true).hash, paper.hash);
    EXPECT_NE(longer.hash, paper.hash);
    const SplitRun bisection = random_splits(c.raw, 5, 40, SplitMethod::kBisection, FaceRule::kLongerEdge, false);
    EXPECT_EQ(random_splits(c.raw, 5, 40, SplitMethod::kBisection, FaceRule::kVertexOrder, true).hash, bisection.hash);
  }
}

TEST(EdgeSplit, ChildrenRememberTheirParentAndMidpointsTheirEdge) {
  TetMesh mesh = testing::build_or_fail(make_box_mesh(1, 1, 1));
  const Edge e{mesh.vertex(TetId{0}, 0), mesh.vertex(TetId{0}, 1)};
  std::vector<TetId> shell;
  mesh.edge_shell(TetId{0}, 0, shell);
  std::vector<TetId> parents = shell;
  std::sort(parents.begin(), parents.end());
  EdgeSplitter splitter;
  ChangeLog log;
  mesh.begin_transaction();
  ASSERT_TRUE(splitter.split(mesh, std::span<const Edge>(&e, 1), SplitMethod::kTemplates).ok());
  mesh.commit(&log);
  ASSERT_EQ(log.vertices.size(), 1u);
  const CreatedVertex& m = log.vertices[0];
  EXPECT_EQ(mesh.position(m.vertex), 0.5 * (mesh.position(e.a) + mesh.position(e.b)));
  ASSERT_TRUE(m.on_edge());
  EXPECT_EQ(std::minmax(m.from[0], m.from[1]), std::minmax(e.a, e.b));
  EXPECT_EQ(m.weight[0], 0.5);
  EXPECT_EQ(m.weight[1], 0.5);
  EXPECT_TRUE(log.removed_vertices.empty());
  EXPECT_EQ(log.created.size(), 2 * shell.size());
  std::map<std::uint32_t, int> children_per_parent;
  for (const CreatedTet& c : log.created) {
    ASSERT_EQ(c.parents_count, 1u);
    EXPECT_EQ(log.parents_of(c)[0], c.parent);
    ++children_per_parent[c.parent.value];
  }
  for (TetId p : parents) EXPECT_EQ(children_per_parent[p.value], 2);
}

TEST(EdgeSplit, RefusesANonEdgeAndADegenerateChildLeavingTheMeshUntouched) {
  TetMesh mesh = testing::build_or_fail(make_box_mesh(2, 2, 2));
  const std::uint64_t before = mesh.num_tets();
  EdgeSplitter splitter;
  const Edge not_an_edge{VertId{0}, VertId{26}};  // opposite corners of the box
  const SplitResult r = splitter.split(mesh, std::span<const Edge>(&not_an_edge, 1), SplitMethod::kTemplates);
  EXPECT_EQ(r.refusal, SplitRefusal::kNotAnEdge);
  EXPECT_EQ(mesh.num_tets(), before);

  // Nearly flat tets: the rounded midpoints of their edges can fall on or across a face plane,
  // so some splits must be refused, and a refused split must leave no trace.
  SplitMix64 rng(99);
  const Vec3 a{0.1, 0.2, 0.3}, b{1.7, 0.9, 0.35}, c{0.4, 1.3, 0.8};
  const Vec3 normal = cross(b - a, c - a);
  int refused = 0, accepted = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const double s = rng.unit(), t = rng.unit() * (1 - s);
    const Vec3 d = a + s * (b - a) + t * (c - a) + (1e-17 * (1 + rng.unit())) * normal;
    BuildResult built = build_mesh({{a, b, c, d}, {{0, 1, 2, 3}}}, {.reorient_inverted = true});
    if (!built.ok()) continue;  // flat after all
    TetMesh& thin = *built.mesh;
    const std::uint64_t hash = canonical_hash(thin);
    const int e = static_cast<int>(rng.below(6));
    const Edge edge{thin.vertex(TetId{0}, kEdgeVerts[e][0]), thin.vertex(TetId{0}, kEdgeVerts[e][1])};
    const SplitResult r = splitter.split(thin, std::span<const Edge>(&edge, 1), SplitMethod::kTemplates);
    if (r.refusal == SplitRefusal::kDegenerateChild) {
      ++refused;
      EXPECT_EQ(canonical_hash(thin), hash);
      EXPECT_EQ(thin.num_tets(), 1u);
      EXPECT_EQ(thin.vertex_capacity(), 4u) << "no midpoint was added";
    } else {
      ASSERT_TRUE(r.ok());
      ++accepted;
      EXPECT_TRUE(testing::mesh_is_valid(thin));
    }
  }
  EXPECT_GT(refused, 0);
  EXPECT_GT(accepted, 0);
}

// SplitPoint::kPositiveChildren (the removal fallback's): where the midpoints make every child
// positive it is the midpoint split bit for bit; where they do not, it moves the points along
// their edges, and the moved points are shared by every tet around their edge. Two slivers on
// either side of the face abc (d and e about a midpoint's rounding off its plane), the three
// edges of abc split: each point lies in both tets, so the full checker's conformity (I2, I3)
// judges the sharing.
TEST(EdgeSplit, MovedSplitPointsSaveSliversAndLeaveEveryOtherSplitAlone) {
  SplitMix64 rng(5);
  const Vec3 a{0.1, 0.2, 0.3}, b{1.7, 0.9, 0.35}, c{0.4, 1.3, 0.8};
  const Vec3 normal = cross(b - a, c - a);
  auto near_face = [&](double side) {
    const double s = rng.unit(), t = rng.unit() * (1 - s);
    return a + s * (b - a) + t * (c - a) + (side * 7e-17 * (1 + rng.unit())) * normal;
  };
  int same = 0, refused = 0, saved = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const Vec3 d = near_face(1.0), e = near_face(-1.0);
    BuildResult built = build_mesh({{a, b, c, d, e}, {{0, 1, 2, 3}, {0, 2, 1, 4}}});
    if (!built.ok()) continue;  // flat after all
    const std::vector<Edge> face = {{VertId{0}, VertId{1}}, {VertId{1}, VertId{2}}, {VertId{2}, VertId{0}}};
    EdgeSplitter splitter;
    TetMesh at_midpoints = *built.mesh, moved = *built.mesh;
    const SplitResult m = splitter.split(at_midpoints, face, SplitMethod::kTemplates);
    moved.begin_transaction();
    const TetMesh::Savepoint before = moved.savepoint();
    const SplitResult r = splitter.split(moved, face, SplitMethod::kTemplates, nullptr, UINT64_MAX, SplitPoint::kPositiveChildren);
    std::vector<double> ts;
    for (const TetMesh::VertexBirth& v : moved.vertices_made_since(before)) ts.push_back(v.t);
    moved.commit();
    if (m.ok()) {
      ++same;
      EXPECT_TRUE(r.ok());
      EXPECT_EQ(canonical_hash(moved), canonical_hash(at_midpoints)) << "trial " << trial;
      continue;
    }
    ASSERT_EQ(m.refusal, SplitRefusal::kDegenerateChild);
    ++refused;
    if (!r.ok()) {
      EXPECT_EQ(moved.num_tets(), 2u) << "a refused split leaves the mesh untouched";
      continue;
    }
    ++saved;
    EXPECT_EQ(ts.size(), 3u);
    for (double t : ts) EXPECT_NE(std::find(kSplitParameters.begin(), kSplitParameters.end(), t), kSplitParameters.end());
    EXPECT_TRUE(std::any_of(ts.begin(), ts.end(), [](double t) { return t != 0.5; })) << "trial " << trial;
    EXPECT_EQ(moved.num_tets(), 8u);  // 3 edges on a face: 4 children in each tet
    EXPECT_TRUE(testing::mesh_is_valid(moved)) << "trial " << trial;
  }
  std::printf("[split] slivers: midpoints fine %d, refused %d, saved by moved points %d\n", same, refused, saved);
  EXPECT_GT(same, 0);
  ASSERT_GT(refused, 0) << "no sliver made the midpoint split fail: the test tests nothing";
  EXPECT_GE(4 * saved, 3 * refused);
}

// The quality table: the worst radius ratio of the children relative to their parent's, for each
// configuration, templates against bisection, over all vertex orders of a regular tet.
TEST(EdgeSplit, QualityTableTemplatesAgainstBisection) {
  const double s = 1.0 / std::sqrt(2.0);
  const Vec3 regular[4] = {{1, 0, -s}, {-1, 0, -s}, {0, 1, s}, {0, -1, s}};
  std::map<std::string, std::pair<double, double>> worst;  // configuration -> (templates, bisection)
  for (int mask = 1; mask < 64; ++mask) {
    std::array<std::uint32_t, 4> perm = {0, 1, 2, 3};
    do {
      for (SplitMethod method : {SplitMethod::kTemplates, SplitMethod::kBisection}) {
        RawMesh raw;
        raw.positions.resize(4);
        for (int i = 0; i < 4; ++i) raw.positions[perm[i]] = regular[i];
        raw.tets.push_back(perm);
        BuildResult built = build_mesh(raw, {.reorient_inverted = true});
        ASSERT_TRUE(built.ok());
        TetMesh& mesh = *built.mesh;
        const double parent = radius_ratio(regular[0], regular[1], regular[2], regular[3]);
        EdgeSplitter splitter;
        std::vector<TetId> children;
        const SplitResult r = splitter.split(mesh, edges_of_mask(mesh, TetId{0}, mask), method, &children);
        ASSERT_TRUE(r.ok());
        ASSERT_EQ(children.size(), r.tets_created);
        auto& slot = worst.try_emplace(configuration(mask), 1.0, 1.0).first->second;
        double& w = method == SplitMethod::kTemplates ? slot.first : slot.second;
        w = std::min(w, min_radius_ratio(mesh, children) / parent);
      }
    } while (std::next_permutation(perm.begin(), perm.end()));
  }
  std::printf("%-30s %10s %10s\n", "configuration", "templates", "bisection");
  for (const auto& [name, w] : worst) {
    std::printf("%-30s %10.3f %10.3f\n", name.c_str(), w.first, w.second);
    EXPECT_GT(w.first, 0.1) << name;
  }
  // The red 1:8 split along the shortest diagonal beats repeated bisection.
  EXPECT_GT(worst["6 edges"].first, worst["6 edges"].second);
}

// The face rules on irregular tets (random, radius ratio at least 0.3): per configuration, the
// mean and the worst over the tets of their worst child's radius ratio relative to the parent's.
// A face rule can only act where a face has two split edges; elsewhere the two rules coincide.
TEST(EdgeSplit, QualityTableLongerEdgeAgainstVertexOrderOnIrregularTets) {
  struct Figures {
    double sum = 0, worst = 1;
    int n = 0;
  };
  std::map<std::string, std::array<Figures, 2>> table;  // configuration -> (vertex order, longer edge)
  SplitMix64 rng(2002);
  int tets = 0;
  while (tets < 300) {
    std::array<Vec3, 4> p;
    for (Vec3& x : p) x = {rng.unit(), rng.unit(), rng.unit()};
    if (orientation(p[0], p[1], p[2], p[3]) < 0) std::swap(p[2], p[3]);
    const double parent = radius_ratio(p[0], p[1], p[2], p[3]);
    if (parent < 0.3) continue;
    ++tets;
    std::array<std::uint32_t, 4> ids = {0, 1, 2, 3};
    for (int i = 3; i > 0; --i) std::swap(ids[static_cast<std::size_t>(i)], ids[rng.below(static_cast<std::uint64_t>(i) + 1)]);
    RawMesh raw;
    raw.positions.resize(4);
    for (int i = 0; i < 4; ++i) raw.positions[ids[static_cast<std::size_t>(i)]] = p[static_cast<std::size_t>(i)];
    raw.tets.push_back(ids);
    for (int mask = 1; mask < 64; ++mask) {
      if (two_split_faces(static_cast<std::uint8_t>(mask)) == 0) continue;
      for (int r = 0; r < 2; ++r) {
        TetMesh mesh = testing::build_or_fail(raw);
        EdgeSplitter splitter;
        splitter.set_face_rule(r == 0 ? FaceRule::kVertexOrder : FaceRule::kLongerEdge);
        std::vector<TetId> children;
        ASSERT_TRUE(splitter.split(mesh, edges_of_mask(mesh, TetId{0}, mask), SplitMethod::kTemplates, &children).ok());
        Figures& f = table[configuration(mask)][static_cast<std::size_t>(r)];
        const double q = min_radius_ratio(mesh, children) / parent;
        f.sum += q;
        f.worst = std::min(f.worst, q);
        ++f.n;
      }
    }
  }
  std::printf("%-30s %23s %23s\n", "configuration", "vertex order mean/worst", "longer edge mean/worst");
  for (const auto& [name, f] : table) {
    std::printf("%-30s %11.3f %11.3f %11.3f %11.3f\n", name.c_str(), f[0].sum / f[0].n, f[0].worst, f[1].sum / f[1].n, f[1].worst);
    EXPECT_GT(f[1].sum / f[1].n, f[0].sum / f[0].n) << name;
  }
}

}  // namespace
}  // namespace tetcut
