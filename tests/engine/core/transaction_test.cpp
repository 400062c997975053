#include <gtest/gtest.h>

#include <algorithm>
#include <optional>

#include "change_log_check.hpp"
#include "core/random.hpp"
#include "refine/edge_split.hpp"
#include "test_meshes.hpp"
#include "tetcut/detail/local_tables.hpp"

namespace tetcut {
namespace {

// Every observable piece of state, compared element by element.
void expect_identical(const TetMesh& a, const TetMesh& b) {
  ASSERT_EQ(a.tet_capacity(), b.tet_capacity());
  ASSERT_EQ(a.vertex_capacity(), b.vertex_capacity());
  EXPECT_EQ(a.num_tets(), b.num_tets());
  EXPECT_EQ(a.num_vertices(), b.num_vertices());
  for (std::uint32_t t = 0; t < a.tet_capacity(); ++t) {
    ASSERT_EQ(a.raw_tets()[t], b.raw_tets()[t]) << "tet " << t;
    if (!a.is_live(TetId{t})) continue;
    for (int f = 0; f < 4; ++f) ASSERT_EQ(a.neighbour(TetId{t}, f), b.neighbour(TetId{t}, f));
  }
  for (std::uint32_t v = 0; v < a.vertex_capacity(); ++v) {
    ASSERT_EQ(a.position(VertId{v}), b.position(VertId{v}));
    ASSERT_EQ(a.vertex_tet(VertId{v}), b.vertex_tet(VertId{v}));
    ASSERT_EQ(a.boundary_face_count(VertId{v}), b.boundary_face_count(VertId{v}));
  }
  ASSERT_EQ(a.attributes().channel_count(), b.attributes().channel_count());
  for (std::uint32_t c = 0; c < a.attributes().channel_count(); ++c)
    EXPECT_EQ(a.attributes().channel(c).values, b.attributes().channel(c).values);
}

void random_operation(TetMesh& mesh, SplitMix64& rng, EdgeSplitter& splitter) {
  std::vector<Edge> edges;
  for (int i = 0; i < 3; ++i) {
    const TetId t = testing::random_live_tet(mesh, rng);
    const int e = static_cast<int>(rng.below(6));
    edges.push_back({mesh.vertex(t, kEdgeVerts[e][0]), mesh.vertex(t, kEdgeVerts[e][1])});
  }
  ASSERT_TRUE(splitter.split(mesh, edges, SplitMethod::kTemplates).ok());
  // And a removal of a tet with three boundary faces, if any (always keeps a manifold).
  for (std::uint32_t t = 0; t < mesh.tet_capacity(); ++t)
    if (mesh.is_live(TetId{t}) && mesh.boundary_face_count(TetId{t}) >= 3) {
      const TetId only[1] = {TetId{t}};
      mesh.remove_tets(only);
      break;
    }
}

// A 3x3x3 box with a vertex channel (so attributes are restored too) and some history first, so
// that its free lists are not empty.
TetMesh box_with_history(SplitMix64& rng, EdgeSplitter& splitter) {
  TetMesh mesh = testing::build_or_fail(make_box_mesh(3, 3, 3));
  const auto tag = *mesh.attributes().add_channel("tag", 1);
  for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v) mesh.attributes().value(tag, VertId{v})[0] = v;
  for (int i = 0; i < 5; ++i) random_operation(mesh, rng, splitter);
  return mesh;
}

TEST(Transaction, RollbackRestoresTheMeshBitForBit) {
  SplitMix64 rng(17);
  EdgeSplitter splitter;
  TetMesh mesh = box_with_history(rng, splitter);
  for (int round = 0; round < 20; ++round) {
    const TetMesh before = mesh;
    mesh.begin_transaction();
    for (int i = 0; i < 1 + round % 4; ++i) random_operation(mesh, rng, splitter);
    mesh.rollback();
    EXPECT_FALSE(mesh.in_transaction());
    expect_identical(mesh, before);
    if (::testing::Test::HasFatalFailure()) return;
    // Same future: the free lists were restored too.
    TetMesh twin = before;
    SplitMix64 rng_a(round), rng_b(round);
    EdgeSplitter s2;
    random_operation(mesh, rng_a, splitter);
    random_operation(twin, rng_b, s2);
    expect_identical(mesh, twin);
  }
}

TEST(Transaction, CommitKeepsTheChanges) {
  TetMesh mesh = testing::build_or_fail(make_box_mesh(2, 2, 2));
  SplitMix64 rng(1);
  EdgeSplitter splitter;
  const std::uint32_t before = mesh.num_tets();
  mesh.begin_transaction();
  random_operation(mesh, rng, splitter);
  mesh.commit();
  EXPECT_NE(mesh.num_tets(), before);
  EXPECT_FALSE(mesh.in_transaction());
}

TEST(Transaction, SavepointsRollBackBitForBitAndNest) {
  SplitMix64 rng(23);
  EdgeSplitter splitter;
  TetMesh mesh = box_with_history(rng, splitter);
  const TetMesh start = mesh;
  mesh.begin_transaction();
  random_operation(mesh, rng, splitter);
  const TetMesh::Savepoint first = mesh.savepoint();
  const TetMesh at_first = mesh;
  random_operation(mesh, rng, splitter);
  const TetMesh::Savepoint second = mesh.savepoint();
  const TetMesh at_second = mesh;
  random_operation(mesh, rng, splitter);
  random_operation(mesh, rng, splitter);
  mesh.rollback_to(second);
  expect_identical(mesh, at_second);
  EXPECT_TRUE(mesh.in_transaction());
  // Work again after coming back, then further back still.
  random_operation(mesh, rng, splitter);
  mesh.rollback_to(first);
  expect_identical(mesh, at_first);
  random_operation(mesh, rng, splitter);
  mesh.rollback();
  expect_identical(mesh, start);
}

// The live tets' vertices by id at one moment (nullopt: dead): what changes_since() is compared
// with, read from the mesh without the journal.
std::vector<std::optional<TetMesh::TetVerts>> live_tets(const TetMesh& mesh) {
  std::vector<std::optional<TetMesh::TetVerts>> out(mesh.tet_capacity());
  for (std::uint32_t t = 0; t < mesh.tet_capacity(); ++t)
    if (mesh.is_live(TetId{t})) out[t] = mesh.tet(TetId{t});
  return out;
}

// changes_since(p) is the difference of two snapshots: removed, the ids live at p and not live
// now with the same vertices; created, the ids live now and not live at p with them; both sorted.
void expect_net_change(TetMesh& mesh, const TetMesh::Savepoint& p, const std::vector<std::optional<TetMesh::TetVerts>>& at_p) {
  std::vector<TetId> removed, created, want_removed, want_created;
  mesh.changes_since(p, removed, created);
  const auto now = live_tets(mesh);
  for (std::uint32_t t = 0; t < std::max(now.size(), at_p.size()); ++t) {
    const std::optional<TetMesh::TetVerts> then = t < at_p.size() ? at_p[t] : std::nullopt;
    const std::optional<TetMesh::TetVerts> current = t < now.size() ? now[t] : std::nullopt;
    if (then == current) continue;
    if (then) want_removed.push_back(TetId{t});
    if (current) want_created.push_back(TetId{t});
  }
  EXPECT_EQ(removed, want_removed);
  EXPECT_EQ(created, want_created);
}

TEST(Transaction, ChangesSinceASavepointAreTheDifferenceOfTwoSnapshotsThroughRollbacks) {
  SplitMix64 rng(41);
  EdgeSplitter splitter;
  // Some history first: ids are made from the free list as well as appended.
  TetMesh mesh = box_with_history(rng, splitter);
  mesh.begin_transaction();
  const TetMesh::Savepoint start = mesh.savepoint();
  const auto at_start = live_tets(mesh);
  random_operation(mesh, rng, splitter);
  random_operation(mesh, rng, splitter);
  const TetMesh::Savepoint first = mesh.savepoint();
  const auto at_first = live_tets(mesh);
  random_operation(mesh, rng, splitter);
  const TetMesh::Savepoint second = mesh.savepoint();
  const auto at_second = live_tets(mesh);
  random_operation(mesh, rng, splitter);
  random_operation(mesh, rng, splitter);
  expect_net_change(mesh, start, at_start);
  expect_net_change(mesh, first, at_first);
  expect_net_change(mesh, second, at_second);
  // Undone work leaves births and freed ids behind in the scratch state: none may show.
  mesh.rollback_to(second);
  random_operation(mesh, rng, splitter);
  expect_net_change(mesh, start, at_start);
  expect_net_change(mesh, first, at_first);
  expect_net_change(mesh, second, at_second);
  mesh.rollback_to(first);
  random_operation(mesh, rng, splitter);
  expect_net_change(mesh, start, at_start);
  expect_net_change(mesh, first, at_first);
  std::vector<TetId> removed, created;
  mesh.changes_since(start, removed, created);
  EXPECT_FALSE(removed.empty());
  EXPECT_FALSE(created.empty());
  mesh.commit();
}

TEST(Transaction, NoIdIsReusedInsideATransactionAndChangesAreNet) {
  TetMesh mesh = testing::build_or_fail(make_box_mesh(3, 3, 3));
  SplitMix64 rng(5);
  EdgeSplitter splitter;
  mesh.begin_transaction();
  const TetMesh::Savepoint start = mesh.savepoint();
  std::vector<std::uint8_t> was_live(mesh.tet_capacity());
  for (std::uint32_t t = 0; t < mesh.tet_capacity(); ++t) was_live[t] = mesh.is_live(TetId{t});
  std::vector<TetId> created;
  for (int i = 0; i < 6; ++i) {
    std::vector<Edge> edges;
    TetId t;
    do t = TetId{rng.below(mesh.tet_capacity())};
    while (!mesh.is_live(t));
    edges.push_back({mesh.vertex(t, 0), mesh.vertex(t, 1)});
    std::vector<TetId> made;
    ASSERT_TRUE(splitter.split(mesh, edges, SplitMethod::kTemplates, &made).ok());
    for (TetId c : made) {
      // Never an id that was live at the start or made earlier in the transaction.
      EXPECT_FALSE(c.value < was_live.size() && was_live[c.value]) << c.value;
      EXPECT_EQ(std::count(created.begin(), created.end(), c), 0) << c.value;
    }
    created.insert(created.end(), made.begin(), made.end());
  }
  std::vector<TetId> removed, net_created;
  mesh.changes_since(start, removed, net_created);
  for (TetId r : removed) EXPECT_TRUE(was_live[r.value] && !mesh.is_live(r));
  for (TetId c : net_created) EXPECT_TRUE(mesh.is_live(c) && !(c.value < was_live.size() && was_live[c.value]));
  std::uint32_t live_made = 0;
  for (TetId c : created) live_made += mesh.is_live(c) ? 1u : 0u;
  EXPECT_EQ(net_created.size(), live_made);
  EXPECT_EQ(mesh.num_tets() + removed.size(), 162u + net_created.size());
  // After commit the ids freed by the transaction are reused.
  mesh.commit();
  std::vector<Edge> edges;
  TetId t{0};
  while (!mesh.is_live(t)) t = TetId{t.value + 1};
  edges.push_back({mesh.vertex(t, 0), mesh.vertex(t, 1)});
  std::vector<TetId> made;
  const std::uint32_t capacity = mesh.tet_capacity();
  ASSERT_TRUE(splitter.split(mesh, edges, SplitMethod::kTemplates, &made).ok());
  EXPECT_EQ(mesh.tet_capacity(), capacity);
}

TEST(RecordOfChange, ChildrenSplitAgainNameTheTetsThereBeforeAndMidpointsTheirOldVertices) {
  TetMesh mesh = testing::build_or_fail(make_box_mesh(2, 2, 2));
  const auto tag = *mesh.attributes().add_channel("tag", 1);
  for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v) mesh.attributes().value(tag, VertId{v})[0] = 3.0 * v;
  const TetMesh before = mesh;
  EdgeSplitter splitter;
  SplitMix64 rng(11);
  mesh.begin_transaction();
  // Three rounds, each splitting edges of tets the previous round made: grandchildren whose
  // midpoints lie on edges between midpoints.
  std::vector<TetId> made;
  const Edge first{mesh.vertex(TetId{0}, 0), mesh.vertex(TetId{0}, 1)};
  ASSERT_TRUE(splitter.split(mesh, std::span<const Edge>(&first, 1), SplitMethod::kTemplates, &made).ok());
  for (int round = 0; round < 2; ++round) {
    std::vector<Edge> edges;
    for (TetId t : made)
      if (mesh.is_live(t)) edges.push_back({mesh.vertex(t, rng.below(2) ? 2 : 0), mesh.vertex(t, 3), t});
    made.clear();
    ASSERT_TRUE(splitter.split(mesh, edges, SplitMethod::kTemplates, &made).ok());
  }
  // An attempt undone: its births go with it.
  const TetMesh::Savepoint point = mesh.savepoint();
  const std::size_t births = mesh.tets_made_since(point).size();
  const Edge undone{mesh.vertex(made[0], 1), mesh.vertex(made[0], 2)};
  ASSERT_TRUE(splitter.split(mesh, std::span<const Edge>(&undone, 1), SplitMethod::kTemplates).ok());
  EXPECT_GT(mesh.tets_made_since(point).size(), births);
  mesh.rollback_to(point);
  EXPECT_EQ(mesh.tets_made_since(point).size(), 0u);
  EXPECT_EQ(mesh.vertices_made_since(point).size(), 0u);
  ChangeLog log;
  mesh.commit(&log);
  EXPECT_FALSE(log.created.empty());
  EXPECT_GT(testing::expect_log_describes(before, mesh, log), 0) << "some midpoints lie inside old faces or tets";
  EXPECT_TRUE(log.removed_vertices.empty());
}

TEST(RecordOfChange, AMovedVertexIsLocatedInTheOldTetItMovedInto) {
  TetMesh mesh = testing::build_or_fail(make_box_mesh(2, 2, 2));
  const auto tag = *mesh.attributes().add_channel("tag", 1);
  for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v) mesh.attributes().value(tag, VertId{v})[0] = 1.0 + v * v;
  const TetMesh before = mesh;
  // An interior edge: its midpoint can move a little in any direction.
  Edge edge{};
  for (std::uint32_t t = 0; t < mesh.tet_capacity() && !edge.a.valid(); ++t)
    for (int e = 0; e < 6 && !edge.a.valid(); ++e)
      if (!mesh.is_boundary_edge(TetId{t}, e)) edge = {mesh.vertex(TetId{t}, kEdgeVerts[e][0]), mesh.vertex(TetId{t}, kEdgeVerts[e][1])};
  ASSERT_TRUE(edge.a.valid());
  EdgeSplitter splitter;
  mesh.begin_transaction();
  const TetMesh::Savepoint point = mesh.savepoint();
  ASSERT_TRUE(splitter.split(mesh, std::span<const Edge>(&edge, 1), SplitMethod::kTemplates).ok());
  ASSERT_EQ(mesh.vertices_made_since(point).size(), 1u);
  const VertId m = mesh.vertices_made_since(point)[0].vertex;
  ASSERT_TRUE(mesh.made_in_transaction(m));
  mesh.move_vertex(m, mesh.position(m) + Vec3{0.011, 0.007, -0.013});
  ChangeLog log;
  mesh.commit(&log);
  ASSERT_EQ(log.vertices.size(), 1u);
  EXPECT_GE(log.vertices[0].count, 3u) << "off its edge";
  testing::expect_log_describes(before, mesh, log);
}

// A vertex there before moves (the pass smooths within a cut's reach): the log lists it as moved
// with its old position, its origin over old positions, and its channels interpolated from the
// values at the start; so is a midpoint made on an edge to it after it moved, whose origin goes
// through the moved vertex's; a rollback undoes the move bit for bit.
TEST(RecordOfChange, AVertexThereBeforeMovesAsTheLogSaysAndRollsBack) {
  TetMesh mesh = testing::build_or_fail(make_box_mesh(2, 2, 2));
  const auto tag = *mesh.attributes().add_channel("tag", 1);
  for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v) mesh.attributes().value(tag, VertId{v})[0] = 1.0 + v * v;
  const TetMesh before = mesh;
  VertId inner = kNoVert;  // the box's one interior vertex
  for (std::uint32_t v = 0; v < mesh.vertex_capacity() && !inner.valid(); ++v)
    if (mesh.is_live(VertId{v}) && !mesh.is_boundary_vertex(VertId{v})) inner = VertId{v};
  ASSERT_TRUE(inner.valid());
  const Vec3 start = mesh.position(inner);

  mesh.begin_transaction();
  mesh.move_vertex(inner, start + Vec3{0.011, 0.007, -0.013});
  mesh.rollback();
  expect_identical(mesh, before);

  mesh.begin_transaction();
  mesh.move_vertex(inner, start + Vec3{0.011, 0.007, -0.013});
  EXPECT_TRUE(mesh.moved_in_transaction(inner));
  EXPECT_EQ(mesh.position_at_start(inner), start);
  EXPECT_EQ(mesh.attributes().value(tag, inner)[0], before.attributes().value(tag, inner)[0]) << "kept until commit";
  // A midpoint on an edge from the moved vertex, then a second move of it.
  std::vector<TetId> shell;
  mesh.vertex_shell(inner, shell);
  const TetId t = shell.front();
  const Edge edge{inner, mesh.vertex(t, (mesh.local_index(t, inner) + 1) % 4)};
  EdgeSplitter splitter;
  ASSERT_TRUE(splitter.split(mesh, std::span<const Edge>(&edge, 1), SplitMethod::kTemplates).ok());
  mesh.move_vertex(inner, start + Vec3{-0.02, 0.004, 0.009});
  ChangeLog log;
  mesh.commit(&log);
  ASSERT_EQ(log.moved.size(), 1u);
  EXPECT_EQ(log.moved[0].vertex, inner);
  EXPECT_EQ(log.moved[0].before, start);
  EXPECT_FALSE(mesh.moved_in_transaction(inner)) << "no transaction open";
  ASSERT_EQ(log.vertices.size(), 1u);
  EXPECT_GE(log.vertices[0].count, 3u) << "the midpoint's origin goes through where the moved vertex was then";
  EXPECT_NE(mesh.attributes().value(tag, inner)[0], before.attributes().value(tag, inner)[0]);
  testing::expect_log_describes(before, mesh, log);
}

TEST(RecordOfChange, RemovedTetsAndVerticesAreNetAndTheLogOfAnEmptyTransactionIsEmpty) {
  TetMesh mesh = testing::build_or_fail(make_box_mesh(1, 1, 1));
  const TetMesh before = mesh;
  ChangeLog log;
  mesh.begin_transaction();
  mesh.commit(&log);
  EXPECT_TRUE(log.removed.empty() && log.created.empty() && log.vertices.empty() && log.removed_vertices.empty());
  // A corner tet of the cube: removing it frees no vertex; removing all frees all eight.
  std::vector<TetId> all;
  for (std::uint32_t t = 0; t < mesh.tet_capacity(); ++t) all.push_back(TetId{t});
  mesh.begin_transaction();
  mesh.remove_tets(all);
  mesh.commit(&log);
  EXPECT_EQ(log.removed.size(), all.size());
  EXPECT_EQ(log.removed_vertices.size(), 8u);
  testing::expect_log_describes(before, mesh, log);
}

}  // namespace
}  // namespace tetcut
