// The fallback with a proof (docs/removal-proof.md), tested exhaustively on small meshes: for
// every tet T of each mesh, on a copy, the normal-surface construction removes T and leaves a
// mesh the independent checker accepts, touching nothing outside the stars of T's vertices.
// And the gap in the paper's claim for 3.4: its set is sometimes not removable as it stands.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>

#include "checked.hpp"
#include "core/random.hpp"
#include "removal_test_support.hpp"
#include "remove/neighbour_search.hpp"
#include "remove/normal_surface_fallback.hpp"
#include "remove/refinement_strategies.hpp"
#include "tetcut/canonical_hash.hpp"
#include "tetcut/io.hpp"
#include "tetcut/predicates.hpp"

namespace tetcut::testing {
namespace {

// One request context over `mesh` inside an open transaction.
struct Request {
  SetRemovalWorkspace ws;
  EdgeSplitter splitter;
  ChangeLog log;
  std::vector<TetId> exposed;
  detail::TissueRemoval tissue;
  detail::RemovalContext context(TetMesh& mesh) {
    detail::RemovalContext c{mesh, ws, splitter, exposed, mesh.savepoint(), 0xFFFFFFFFu};
    c.tissue = &tissue;
    return c;
  }
};

// The vertices of the stars of t's corners: what the construction may touch.
std::vector<VertId> star_vertices(const TetMesh& mesh, TetId t) {
  std::vector<VertId> out;
  std::vector<TetId> shell;
  for (VertId a : mesh.tet(t)) {
    mesh.vertex_shell(a, shell);
    for (TetId u : shell)
      for (VertId w : mesh.tet(u)) out.push_back(w);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

::testing::AssertionResult fallback_works_on_every_tet(const TetMesh& original) {
  int checked = 0;
  detail::NormalSurfaceFallback fallback;
  Request request;
  for (std::uint32_t i = 0; i < original.tet_capacity(); ++i) {
    const TetId t{i};
    if (!original.is_live(t)) continue;
    TetMesh mesh = original;
    const std::vector<VertId> star = star_vertices(mesh, t);
    const Vec3 c = centroid(mesh, t);
    mesh.begin_transaction();
    request.log.clear();
    detail::RemovalContext ctx = request.context(mesh);
    const std::uint32_t n = fallback.remove(ctx, t);
    mesh.commit(&request.log);
    if (n == 0) return ::testing::AssertionFailure() << "tet " << i << ": the fallback refused";
    if (mesh.is_live(t)) return ::testing::AssertionFailure() << "tet " << i << ": still there";
    if (tet_containing(mesh, c).valid()) return ::testing::AssertionFailure() << "tet " << i << ": its centroid is covered";
    const auto report = invariants::check_mesh(mesh.raw_view());
    if (!report.ok()) return ::testing::AssertionFailure() << "tet " << i << ": " << describe(report);
    // Local: every edge split has an end among T's corners, so every tet removed or made has
    // its original vertices in the stars.
    for (const CreatedVertex& v : request.log.vertices)
      for (int k = 0; k < v.count; ++k)
        if (!std::binary_search(star.begin(), star.end(), v.from[k]))
          return ::testing::AssertionFailure() << "tet " << i << ": split outside the stars";
    ++checked;
  }
  if (checked == 0) return ::testing::AssertionFailure() << "no tet";
  return ::testing::AssertionSuccess() << checked << " tets";
}

TEST(NormalSurfaceFallback, RemovesEveryTetOfSmallBoxes) {
  for (auto [nx, ny, nz] : {std::array<std::uint32_t, 3>{1, 1, 1}, {2, 2, 2}, {3, 3, 2}, {4, 2, 1}}) {
    SCOPED_TRACE(std::to_string(nx) + "x" + std::to_string(ny) + "x" + std::to_string(nz));
    EXPECT_TRUE(fallback_works_on_every_tet(box(nx, ny, nz)));
  }
}

TEST(NormalSurfaceFallback, RemovesEveryTetOfACone) {
  // Every tet shares the apex, a boundary vertex whose star is the whole mesh.
  EXPECT_TRUE(fallback_works_on_every_tet(build_or_fail(cone_over_grid(5))));
}

TEST(NormalSurfaceFallback, RemovesEveryTetOfBoxesAlreadyCut) {
  // Meshes with cavities, thin walls and tunnels: a box hollowed part-way by random requests.
  for (std::uint64_t seed : {4ull, 5ull}) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    TetMesh mesh = box(3, 3, 3);
    Remover remover({.strategy = RemovalStrategy::kWide});
    BoundaryTetPicker picker(mesh, seed);
    for (int k = 0; k < 40; ++k) {
      const TetId t = picker.pick(mesh);
      if (!t.valid()) break;
      remover.remove(mesh, t);
      picker.add(remover.last_exposed());
    }
    ASSERT_TRUE(mesh_is_valid(mesh));
    EXPECT_TRUE(fallback_works_on_every_tet(mesh));
  }
}

TEST(NormalSurfaceFallback, RemovesEveryTetOfTheFuzzMeshes) {
  for (const char* name : {"cylinder-small.msh", "sheet-small.msh", "liver-small.msh"}) {
    SCOPED_TRACE(name);
    ReadResult read = read_mesh(std::string(TETCUT_CORPUS_DIR) + "/fuzz/meshes/" + name);
    ASSERT_TRUE(read.mesh.has_value());
    EXPECT_TRUE(fallback_works_on_every_tet(build_or_fail(*read.mesh)));
  }
}

// Paper 3.4 says its set "can always be removed"; on the fuzz meshes it sometimes cannot (the
// configuration of docs/removal-proof.md), and the construction then removes T all the same.
TEST(NormalSurfaceFallback, TakesOverWherePaper34sSetIsNotRemovable) {
  int refused = 0, tried = 0;
  for (const char* name : {"cylinder-small.msh", "sheet-small.msh", "liver-small.msh"}) {
    ReadResult read = read_mesh(std::string(TETCUT_CORPUS_DIR) + "/fuzz/meshes/" + name);
    ASSERT_TRUE(read.mesh.has_value());
    const TetMesh original = build_or_fail(*read.mesh);
    for (std::uint32_t i = 0; i < original.tet_capacity(); ++i) {
      const TetId t{i};
      const Removability first = removability(original, t);
      if (first.removable()) continue;
      ++tried;
      TetMesh mesh = original;
      const std::uint64_t before = canonical_hash(mesh);
      Request request;
      detail::RefinementStrategies paper;
      mesh.begin_transaction();
      detail::RemovalContext ctx = request.context(mesh);
      const std::uint32_t n = paper.basic(ctx, t);
      if (n > 0) {
        mesh.commit();
        continue;
      }
      ++refused;
      // Rolled back bit for bit; then the fallback removes T.
      EXPECT_EQ(canonical_hash(mesh), before);
      EXPECT_TRUE(mesh.is_live(t));
      detail::NormalSurfaceFallback fallback;
      EXPECT_GT(fallback.remove(ctx, t), 0u) << name << " tet " << i;
      mesh.commit();
      EXPECT_FALSE(mesh.is_live(t));
      EXPECT_TRUE(mesh_is_valid(mesh)) << name << " tet " << i;
    }
  }
  EXPECT_GT(tried, 50);
  EXPECT_GT(refused, 0) << "3.4's set was removable on all " << tried << " singular tets";
  std::printf("[fallback] paper 3.4's set not removable for %d of %d singular tets\n", refused, tried);
}

// docs/removal-proof.md's counter-example to 3.4, as 3.4 now runs (it also takes the corners at a
// of the tets around av): T has exactly one boundary face F, the vertex v opposite F is on the
// surface, a vertex a of F has av on the surface, and on both sides of T around av some tet has
// its face opposite v inside the mesh (the tissue is more than one tet deep at a). There the
// set's part of a's link is the whole fan around v, which touches the border at v and along T's
// edge bc, so what stays at a falls in two: 3.4's set is never removable.
TEST(NormalSurfaceFallback, Paper34sSetFailsWhereTheTissueIsDeepOnBothSidesOfTAroundAv) {
  // The fuzz meshes, each hollowed part-way by random boundary requests (a cut's cavity is where
  // a tet gets exactly one boundary face with its fourth vertex on the surface).
  std::vector<TetMesh> meshes;
  for (const char* name : {"cylinder-small.msh", "sheet-small.msh", "liver-small.msh"}) {
    ReadResult read = read_mesh(std::string(TETCUT_CORPUS_DIR) + "/fuzz/meshes/" + name);
    ASSERT_TRUE(read.mesh.has_value());
    for (std::uint64_t seed : {4ull, 5ull, 6ull}) {
      TetMesh mesh = build_or_fail(*read.mesh);
      Remover remover;
      BoundaryTetPicker picker(mesh, seed);
      for (int k = 0; k < 60; ++k) {
        const TetId t = picker.pick(mesh);
        if (!t.valid()) break;
        remover.remove(mesh, t);
        picker.add(remover.last_exposed());
      }
      meshes.push_back(std::move(mesh));
    }
  }
  int configurations = 0;
  for (std::size_t mesh_index = 0; mesh_index < meshes.size(); ++mesh_index) {
    const TetMesh& original = meshes[mesh_index];
    const std::string name = "mesh " + std::to_string(mesh_index);
    SetRemovalWorkspace ws;
    std::vector<TetId> sides;
    std::vector<std::uint32_t> sizes;
    for (std::uint32_t i = 0; i < original.tet_capacity(); ++i) {
      const TetId t{i};
      if (!original.is_live(t) || original.boundary_face_count(t) != 1) continue;
      int f = 0;
      while (!original.is_boundary_face(t, f)) ++f;
      const VertId v = original.tet(t)[static_cast<std::size_t>(f)];
      if (!original.is_boundary_vertex(v)) continue;
      bool deep_at_some_a = false;
      for (int la = 0; la < 4 && !deep_at_some_a; ++la) {
        if (la == f) continue;
        const VertId a = original.tet(t)[static_cast<std::size_t>(la)];
        if (!original.is_boundary_edge(t, original.local_edge(t, a, v))) continue;
        detail::sides_of_edge(original, ws, t, a, v, sides, sizes);
        if (sizes.size() != 2) continue;
        bool deep[2] = {false, false};
        std::size_t k = 0;
        for (int side = 0; side < 2; ++side)
          for (std::uint32_t j = 0; j < sizes[static_cast<std::size_t>(side)]; ++j, ++k) {
            const TetId u = sides[k];
            deep[side] = deep[side] || !original.is_boundary_face(u, original.local_index(u, v));
          }
        deep_at_some_a = deep[0] && deep[1];
      }
      if (!deep_at_some_a) continue;
      ++configurations;
      TetMesh mesh = original;
      Request request;
      detail::RefinementStrategies paper;
      mesh.begin_transaction();
      detail::RemovalContext ctx = request.context(mesh);
      EXPECT_EQ(paper.basic(ctx, t), 0u) << name << " tet " << i << ": 3.4's set passed where a's link falls in two";
      mesh.commit();
    }
  }
  EXPECT_GT(configurations, 0) << "no tet of the fuzz meshes is in the counter-example's configuration";
  std::printf("[3.4] %d tets in the counter-example's configuration, 3.4's set refused for each\n", configurations);
}

// The proof does not need midpoints (docs/removal-proof.md, "Any split point"). T with a sliver U
// on its face abc: U's apex e lies about a midpoint's rounding (1e-16) away from the plane of abc,
// so the rounded midpoints of ea, eb, ec can fall on or across a face plane and a child of U be
// flat or inverted. There the midpoint split is refused, and the fallback moves the points and
// removes T all the same: nearly always at this height (closer to the plane, where a child's sign
// is the rounding's alone, about half the time: the search tries 7 points per edge, not all).
TEST(NormalSurfaceFallback, MovesTheSplitPointsWhereASliversMidpointChildIsNotPositive) {
  SplitMix64 rng(7);
  const Vec3 a{0.1, 0.2, 0.3}, b{1.7, 0.9, 0.35}, c{0.4, 1.3, 0.8};
  const Vec3 normal = cross(b - a, c - a);
  const Vec3 d = (1.0 / 3.0) * (a + b + c) + 0.8 * normal;  // T = abcd, a fine tet
  int refused_at_midpoints = 0, removed = 0, trials = 0;
  for (; trials < 2000 && refused_at_midpoints < 20; ++trials) {
    const double s = rng.unit(), t = rng.unit() * (1 - s);
    const Vec3 e = a + s * (b - a) + t * (c - a) - (7e-17 * (1 + rng.unit())) * normal;
    BuildResult built = build_mesh({{a, b, c, d, e}, {{0, 1, 2, 3}, {0, 2, 1, 4}}});
    if (!built.ok()) continue;  // U flat after all
    const TetMesh original = std::move(*built.mesh);
    const TetId tet_t{0};
    const std::vector<Edge> to_e = {{VertId{0}, VertId{4}}, {VertId{1}, VertId{4}}, {VertId{2}, VertId{4}}};

    // The precondition: the midpoints make a child of U that is not positive.
    TetMesh at_midpoints = original;
    EdgeSplitter splitter;
    if (splitter.split(at_midpoints, to_e, SplitMethod::kTemplates).refusal != SplitRefusal::kDegenerateChild) continue;
    ++refused_at_midpoints;

    TetMesh mesh = original;
    Request request;
    detail::NormalSurfaceFallback fallback;
    mesh.begin_transaction();
    detail::RemovalContext ctx = request.context(mesh);
    const TetMesh::Savepoint before = mesh.savepoint();
    const std::uint32_t n = fallback.remove(ctx, tet_t);
    if (n == 0) {  // refused: the mesh as it was
      mesh.commit();
      EXPECT_EQ(canonical_hash(mesh), canonical_hash(original)) << "trial " << trials;
      continue;
    }
    ++removed;
    // The points moved off the midpoint where needed; every child positive (exact predicate).
    bool moved = false;
    for (const TetMesh::VertexBirth& v : mesh.vertices_made_since(before)) moved |= v.t != 0.5;
    EXPECT_TRUE(moved) << "trial " << trials << ": the midpoints were refused, yet every point is one";
    for (const TetMesh::TetBirth& child : mesh.tets_made_since(before))
      if (mesh.is_live(child.tet)) {
        const TetMesh::TetVerts v = mesh.tet(child.tet);
        EXPECT_GT(orientation(mesh.position(v[0]), mesh.position(v[1]), mesh.position(v[2]), mesh.position(v[3])), 0)
            << "trial " << trials;
      }
    mesh.commit();
    EXPECT_FALSE(mesh.is_live(tet_t));
    EXPECT_TRUE(mesh_is_valid(mesh)) << "trial " << trials;
  }
  std::printf("[fallback] midpoints refused for %d slivers of %d; the moved points removed T for %d\n",
              refused_at_midpoints, trials, removed);
  ASSERT_GT(refused_at_midpoints, 0) << "no sliver made the midpoint split fail: the test tests nothing";
  EXPECT_GE(4 * removed, 3 * refused_at_midpoints) << "the moved points should save most of them";
}

}  // namespace
}  // namespace tetcut::testing
