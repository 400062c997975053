#include <gtest/gtest.h>

#include <algorithm>

#include "core/random.hpp"
#include "test_meshes.hpp"
#include "tetcut/bounding_box.hpp"
#include "tetcut/canonical_hash.hpp"
#include "tetcut/detail/local_tables.hpp"

namespace tetcut {
namespace {

// The engine's incrementally maintained state must equal what the builder computes from
// scratch for the same tets. to_raw() numbers live tets and vertices densely in id order, so
// the fresh mesh's ids are the ranks of ours.
void expect_matches_fresh_build(const TetMesh& mesh) {
  BuildResult fresh = build_mesh(mesh.to_raw());
  ASSERT_TRUE(fresh.ok()) << (fresh.problems.empty() ? "" : fresh.problems.front().message);
  const TetMesh& ref = *fresh.mesh;
  std::vector<std::uint32_t> tet_rank(mesh.tet_capacity(), 0xFFFFFFFFu), vert_rank(mesh.vertex_capacity(), 0xFFFFFFFFu);
  std::uint32_t n = 0;
  for (std::uint32_t t = 0; t < mesh.tet_capacity(); ++t)
    if (mesh.is_live(TetId{t})) tet_rank[t] = n++;
  ASSERT_EQ(n, ref.num_tets());
  n = 0;
  for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v)
    if (mesh.is_live(VertId{v})) vert_rank[v] = n++;
  ASSERT_EQ(n, ref.num_vertices());
  ASSERT_EQ(mesh.num_vertices(), ref.num_vertices());

  for (std::uint32_t t = 0; t < mesh.tet_capacity(); ++t) {
    if (!mesh.is_live(TetId{t})) continue;
    for (int f = 0; f < 4; ++f) {
      const FaceRef ours = mesh.neighbour(TetId{t}, f);
      const FaceRef theirs = ref.neighbour(TetId{tet_rank[t]}, f);
      ASSERT_EQ(ours.valid(), theirs.valid()) << "tet " << t << " face " << f;
      if (ours.valid()) {
        EXPECT_EQ(tet_rank[ours.tet.value], theirs.tet.value);
        EXPECT_EQ(ours.face, theirs.face);
      }
    }
  }
  for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v) {
    if (!mesh.is_live(VertId{v})) continue;
    EXPECT_EQ(mesh.boundary_face_count(VertId{v}), ref.boundary_face_count(VertId{vert_rank[v]})) << v;
    const TetId seed = mesh.vertex_tet(VertId{v});
    ASSERT_TRUE(mesh.is_live(seed)) << v;
    EXPECT_GE(mesh.local_index(seed, VertId{v}), 0) << v;
  }
}

// Whether removing tet t leaves a manifold, decided by the builder on the remaining tets (the
// slow, independent oracle; the paper's O(1) test belongs to the removal issue).
bool removal_keeps_manifold(const TetMesh& mesh, TetId t) {
  RawMesh raw = mesh.to_raw();
  std::uint32_t rank = 0;
  for (std::uint32_t u = 0; u < t.value; ++u) rank += mesh.is_live(TetId{u});
  raw.tets.erase(raw.tets.begin() + rank);
  return build_mesh(raw).ok();
}

std::vector<TetId> live_tets(const TetMesh& mesh) {
  std::vector<TetId> out;
  for (std::uint32_t t = 0; t < mesh.tet_capacity(); ++t)
    if (mesh.is_live(TetId{t})) out.push_back(TetId{t});
  return out;
}

// A random tet whose removal keeps the mesh manifold, or kNoTet.
TetId pick_safe_tet(const TetMesh& mesh, SplitMix64& rng) {
  std::vector<TetId> candidates = live_tets(mesh);
  for (std::size_t i = candidates.size(); i > 1; --i)
    std::swap(candidates[i - 1], candidates[rng.below(static_cast<std::uint32_t>(i))]);
  for (TetId t : candidates)
    if (removal_keeps_manifold(mesh, t)) return t;
  return kNoTet;
}

TEST(ReplaceTets, RemovingTetsOneByOneKeepsStateEqualToAFreshBuild) {
  TetMesh mesh = testing::build_or_fail(make_box_mesh(3, 3, 2));
  SplitMix64 rng(7);
  const double volume = mesh.total_volume();
  double removed_volume = 0.0;
  int removals = 0;
  while (mesh.num_tets() > 1) {
    const TetId victim = pick_safe_tet(mesh, rng);
    if (!victim.valid()) break;
    removed_volume += mesh.volume(victim);
    const TetId only[1] = {victim};
    mesh.remove_tets(only);
    ++removals;
    EXPECT_FALSE(mesh.is_live(victim));
    expect_matches_fresh_build(mesh);
    if (::testing::Test::HasFatalFailure()) return;
  }
  EXPECT_GT(removals, 80) << "most of the 108 tets can go one at a time";
  EXPECT_NEAR(mesh.total_volume(), volume - removed_volume, 1e-12);
}

// Bisects edge (a, b) of every tet around it, as the refinement templates will.
void split_edge(TetMesh& mesh, TetId t, int local_edge, std::vector<TetId>& created) {
  std::vector<TetId> shell;
  mesh.edge_shell(t, local_edge, shell);
  const VertId a = mesh.vertex(t, kEdgeVerts[local_edge][0]), b = mesh.vertex(t, kEdgeVerts[local_edge][1]);
  const VertId m = mesh.add_vertex_on_edge(a, b, 0.5);
  std::vector<TetMesh::TetVerts> children;
  for (TetId s : shell) {
    TetMesh::TetVerts with_a = mesh.tet(s), with_b = mesh.tet(s);
    for (int i = 0; i < 4; ++i) {
      if (with_a[i] == b) with_a[i] = m;  // keeps a, replaces b: same orientation
      if (with_b[i] == a) with_b[i] = m;
    }
    children.push_back(with_a);
    children.push_back(with_b);
  }
  mesh.replace_tets(shell, children, &created);
}

TEST(ReplaceTets, SplittingInnerAndBoundaryEdgesGluesChildrenAndKeepsVolume) {
  TetMesh mesh = testing::build_or_fail(make_box_mesh(3, 3, 3));
  const double volume = mesh.total_volume();
  SplitMix64 rng(11);
  std::vector<TetId> created;
  for (int step = 0; step < 60; ++step) {
    const TetId t = testing::random_live_tet(mesh, rng);
    const int e = static_cast<int>(rng.below(6));
    std::vector<TetId> shell;
    mesh.edge_shell(t, e, shell);
    const std::uint32_t before = mesh.num_tets();
    created.clear();
    split_edge(mesh, t, e, created);
    EXPECT_EQ(created.size(), 2 * shell.size());
    EXPECT_EQ(mesh.num_tets(), before + shell.size());
    for (TetId c : created) EXPECT_GT(mesh.volume(c), 0.0);
    expect_matches_fresh_build(mesh);
    if (::testing::Test::HasFatalFailure()) return;
  }
  EXPECT_NEAR(mesh.total_volume(), volume, 1e-12 * volume);
}

TEST(ReplaceTets, ReusesFreedIdsSoCapacityStopsGrowing) {
  TetMesh mesh = testing::build_or_fail(make_box_mesh(2, 2, 2));
  std::vector<TetId> created;
  split_edge(mesh, TetId{0}, 0, created);
  const std::uint32_t tets = mesh.tet_capacity(), verts = mesh.vertex_capacity();
  // Undo-and-redo cycles: the same number of tets and vertices come and go.
  for (int cycle = 0; cycle < 5; ++cycle) {
    std::vector<TetId> shell;
    const TetId t = created.front();
    created.clear();
    split_edge(mesh, t, 0, created);
    mesh.compact();
    (void)shell;
  }
  EXPECT_GT(mesh.tet_capacity(), tets) << "splits add tets";
  const std::uint32_t settled = mesh.tet_capacity();
  std::vector<TetId> all;
  for (std::uint32_t t = 0; t < mesh.tet_capacity(); ++t) all.push_back(TetId{t});
  // Remove 10 tets and put the same ten back: no new slots.
  std::vector<TetId> ten(all.begin(), all.begin() + 10);
  std::vector<TetMesh::TetVerts> back;
  for (TetId t : ten) back.push_back(mesh.tet(t));
  mesh.replace_tets(ten, back, &created);
  EXPECT_EQ(mesh.tet_capacity(), settled);
  EXPECT_GE(mesh.vertex_capacity(), verts);
  expect_matches_fresh_build(mesh);
}

TEST(ReplaceTets, CompactKeepsTheMeshAndReportsTheRenumbering) {
  TetMesh mesh = testing::build_or_fail(make_box_mesh(3, 2, 2));
  std::vector<TetId> victims;
  SplitMix64 rng(3);
  for (int i = 0; i < 5; ++i) {
    victims.push_back(pick_safe_tet(mesh, rng));
    ASSERT_TRUE(victims.back().valid());
    mesh.remove_tets(std::span<const TetId>(&victims.back(), 1));
  }
  const std::uint64_t hash = canonical_hash(mesh);
  const std::uint32_t tets = mesh.num_tets();
  std::vector<TetMesh::TetVerts> before(mesh.tet_capacity());
  for (std::uint32_t t = 0; t < mesh.tet_capacity(); ++t)
    if (mesh.is_live(TetId{t})) before[t] = mesh.tet(TetId{t});
  std::vector<Vec3> positions_before(mesh.vertex_capacity());
  for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v)
    if (mesh.is_live(VertId{v})) positions_before[v] = mesh.position(VertId{v});
  for (const IdOrder order : {IdOrder::kKept, IdOrder::kAlongCurve}) {
    SCOPED_TRACE(order == IdOrder::kKept ? "kept" : "along the curve");
    TetMesh compacted = mesh;
    const Renumbering map = compacted.compact(order);
    EXPECT_EQ(compacted.tet_capacity(), tets);
    EXPECT_EQ(canonical_hash(compacted), hash);
    for (TetId v : victims) EXPECT_FALSE(map.tet_old_to_new[v.value].valid());
    for (std::uint32_t t = 0; t < map.tet_old_to_new.size(); ++t) {
      const TetId now = map.tet_old_to_new[t];
      if (!now.valid()) continue;
      for (int i = 0; i < 4; ++i) EXPECT_EQ(compacted.vertex(now, i), map.vert_old_to_new[before[t][i].value]);
    }
    for (std::uint32_t v = 0; v < map.vert_old_to_new.size(); ++v)
      if (map.vert_old_to_new[v].valid()) {
        EXPECT_EQ(compacted.position(map.vert_old_to_new[v]), positions_before[v]);
      }
    expect_matches_fresh_build(compacted);
  }
}

// The key of a point by the definition (bit i of a coordinate's cell at bit 3i + axis), written
// here without the engine's bit tricks.
std::uint64_t morton_key_by_definition(const Vec3& p, const Vec3& lo, double extent) {
  std::uint64_t key = 0;
  const double c[3] = {p.x - lo.x, p.y - lo.y, p.z - lo.z};
  for (int axis = 0; axis < 3; ++axis) {
    const auto cell = static_cast<std::uint64_t>(std::clamp(c[axis] / extent * 2097151.0, 0.0, 2097151.0));
    for (int bit = 0; bit < 21; ++bit) key |= ((cell >> bit) & 1u) << (3 * bit + axis);
  }
  return key;
}

// Kept: the live ids in their old order. Along the curve: keys never decrease with the new id,
// and equal keys keep the old order, for tets (by centroid) and vertices alike.
TEST(ReplaceTets, CompactOrdersIdsAsAsked) {
  TetMesh mesh = testing::build_or_fail(make_box_mesh(5, 4, 3));
  SplitMix64 rng(11);
  for (int i = 0; i < 12; ++i) {
    const TetId victim = pick_safe_tet(mesh, rng);
    ASSERT_TRUE(victim.valid());
    mesh.remove_tets(std::span<const TetId>(&victim, 1));
  }
  std::vector<TetId> created;
  for (int i = 0; i < 20; ++i) {  // splits put new tets at the end of the ids, far from their place
    const TetId t = pick_safe_tet(mesh, rng);
    created.clear();
    split_edge(mesh, t, i % 6, created);
  }
  {
    TetMesh kept = mesh;
    const Renumbering map = kept.compact(IdOrder::kKept);
    std::uint32_t next = 0;
    for (TetId now : map.tet_old_to_new)
      if (now.valid()) {
        EXPECT_EQ(now.value, next++);
      }
    next = 0;
    for (VertId now : map.vert_old_to_new)
      if (now.valid()) {
        EXPECT_EQ(now.value, next++);
      }
  }
  const Renumbering map = mesh.compact();  // along the curve by default
  BoundingBox box;
  for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v) box.add(mesh.position(VertId{v}));
  const Vec3 size = box.size();
  const double extent = std::max({size.x, size.y, size.z});
  std::vector<std::uint32_t> tet_old(mesh.tet_capacity()), vert_old(mesh.vertex_capacity());
  for (std::uint32_t t = 0; t < map.tet_old_to_new.size(); ++t)
    if (map.tet_old_to_new[t].valid()) tet_old[map.tet_old_to_new[t].value] = t;
  for (std::uint32_t v = 0; v < map.vert_old_to_new.size(); ++v)
    if (map.vert_old_to_new[v].valid()) vert_old[map.vert_old_to_new[v].value] = v;
  const auto expect_along_curve = [](const std::vector<std::uint64_t>& keys, const std::vector<std::uint32_t>& old) {
    for (std::size_t n = 1; n < keys.size(); ++n) {
      EXPECT_LE(keys[n - 1], keys[n]) << "id " << n;
      if (keys[n - 1] == keys[n]) {
        EXPECT_LT(old[n - 1], old[n]) << "id " << n;
      }
    }
  };
  std::vector<std::uint64_t> keys;
  for (std::uint32_t t = 0; t < mesh.tet_capacity(); ++t) {
    const TetMesh::TetVerts v = mesh.tet(TetId{t});
    const Vec3 centroid = 0.25 * (mesh.position(v[0]) + mesh.position(v[1]) + mesh.position(v[2]) + mesh.position(v[3]));
    keys.push_back(morton_key_by_definition(centroid, box.lo, extent));
  }
  expect_along_curve(keys, tet_old);
  bool moved = false;
  for (std::uint32_t n = 1; n < tet_old.size(); ++n) moved = moved || tet_old[n] < tet_old[n - 1];
  EXPECT_TRUE(moved) << "the split children should have moved towards their place";
  keys.clear();
  for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v)
    keys.push_back(morton_key_by_definition(mesh.position(VertId{v}), box.lo, extent));
  expect_along_curve(keys, vert_old);
  expect_matches_fresh_build(mesh);
}

}  // namespace
}  // namespace tetcut
