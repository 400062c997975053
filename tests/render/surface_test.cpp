#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "refine/refine.hpp"
#include "remove/removal.hpp"
#include "tetcut/box_mesh.hpp"
#include "tetcut/cut.hpp"
#include "tetcut/mesh_builder.hpp"
#include "tetcut/render/surface.hpp"

namespace tetcut::render {
namespace {

TetMesh build(const RawMesh& raw) {
  BuildResult r = build_mesh(raw);
  EXPECT_TRUE(r.ok());
  return std::move(*r.mesh);
}

// The unit box's surface, independently of the classifier: a point on one of its six planes.
bool on_unit_box_surface(const Vec3& p) {
  constexpr double kEps = 1e-12;
  for (double c : {p.x, p.y, p.z})
    if (std::fabs(c) < kEps || std::fabs(c - 1.0) < kEps) return true;
  return false;
}

Vec3 centroid(const SurfaceTriangle& t) { return (1.0 / 3.0) * (t.a + t.b + t.c); }

std::size_t boundary_face_count(const TetMesh& mesh) {
  std::vector<FaceRef> faces;
  mesh.boundary_faces(faces);
  return faces.size();
}

std::size_t cut_count(const std::vector<SurfaceTriangle>& surface) {
  std::size_t n = 0;
  for (const SurfaceTriangle& t : surface) n += t.cut ? 1 : 0;
  return n;
}

// On a unit box, a triangle is original surface exactly when its centroid is on the box's
// surface: the classifier must agree with that everywhere.
void expect_classified_like_the_box(const std::vector<SurfaceTriangle>& surface) {
  for (const SurfaceTriangle& t : surface) {
    const Vec3 g = centroid(t);
    EXPECT_EQ(t.cut, !on_unit_box_surface(g)) << "centroid " << g.x << ' ' << g.y << ' ' << g.z;
  }
}

TEST(ClassifySurface, AnUncutMeshHasEveryBoundaryFaceAndNoCut) {
  const TetMesh mesh = build(make_box_mesh(3, 3, 3));
  const std::vector<SurfaceTriangle> surface = classify_surface(mesh, mesh);
  EXPECT_EQ(surface.size(), boundary_face_count(mesh));
  EXPECT_EQ(surface.size(), 6u * 3 * 3 * 2) << "two triangles per cube face on the box's sides";
  EXPECT_EQ(cut_count(surface), 0u);
}

TEST(ClassifySurface, TrianglesAreOrientedOutward) {
  const TetMesh mesh = build(make_box_mesh(2, 3, 2));
  for (const SurfaceTriangle& t : boundary_surface(mesh)) {
    const Vec3 n = cross(t.b - t.a, t.c - t.a);
    EXPECT_GT(dot(n, centroid(t) - Vec3{0.5, 0.5, 0.5}), 0.0);
  }
}

TEST(ClassifySurface, TheOrderIsBoundarySurfaceOrderAndRepeatable) {
  const TetMesh mesh = build(make_box_mesh(2, 2, 2));
  const auto plain = boundary_surface(mesh);
  const auto classified = classify_surface(mesh, mesh);
  ASSERT_EQ(plain.size(), classified.size());
  for (std::size_t i = 0; i < plain.size(); ++i) {
    EXPECT_EQ(plain[i].a, classified[i].a);
    EXPECT_EQ(plain[i].b, classified[i].b);
    EXPECT_EQ(plain[i].c, classified[i].c);
  }
}

TEST(ClassifySurface, FacesExposedByRemovingABoundaryTetAreCut) {
  const TetMesh original = build(make_box_mesh(3, 3, 3));
  TetMesh mesh = original;
  // A tet with exactly one face on the surface whose removal is direct: three faces come out.
  Remover remover;
  bool removed = false;
  for (std::uint32_t i = 0; i < mesh.tet_capacity() && !removed; ++i) {
    const TetId t{i};
    if (mesh.boundary_face_count(t) != 1) continue;
    TetMesh trial = mesh;
    if (remover.remove(trial, t).outcome == RemovalOutcome::kDirect) {
      mesh = std::move(trial);
      removed = true;
    }
  }
  ASSERT_TRUE(removed);
  const std::vector<SurfaceTriangle> surface = classify_surface(mesh, original);
  EXPECT_EQ(cut_count(surface), 3u);
  EXPECT_EQ(surface.size() - cut_count(surface), boundary_face_count(original) - 1);
  expect_classified_like_the_box(surface);
}

TEST(ClassifySurface, RefinedOriginalFacesAreNotCut) {
  for (SplitMethod method : {SplitMethod::kTemplates, SplitMethod::kBisection}) {
    const TetMesh original = build(make_box_mesh(3, 3, 3));
    TetMesh mesh = original;
    // Refine around the middle of the +x side: its faces split into smaller ones in place.
    const Tool focus = Tool::ball({1.0, 0.5, 0.5}, 0.2);
    std::vector<TetId> hit;
    for (std::uint32_t i = 0; i < mesh.tet_capacity(); ++i) {
      const auto v = mesh.tet(TetId{i});
      if (intersects(focus, mesh.position(v[0]), mesh.position(v[1]), mesh.position(v[2]), mesh.position(v[3])))
        hit.push_back(TetId{i});
    }
    Refiner refiner;
    std::vector<TetId> region;
    const RefineReport r = refiner.refine(mesh, hit, {.d_ref = 0.1, .method = method, .focus = focus}, region);
    ASSERT_GT(r.edges_split, 0u);
    const std::vector<SurfaceTriangle> surface = classify_surface(mesh, original);
    EXPECT_GT(surface.size(), boundary_face_count(original)) << "refinement split surface faces";
    EXPECT_EQ(cut_count(surface), 0u);
  }
}

TEST(ClassifySurface, ACutSeparatesExposedFromOriginalSurface) {
  const TetMesh original = build(make_box_mesh(4, 4, 4));
  TetMesh mesh = original;
  Cutter cutter(mesh, CutParams{.tool_diameter = 0.2});
  for (double y : {0.3, 0.45, 0.6}) {
    const CutReport report = cutter.cut({0.5, y, 1.0});
    ASSERT_TRUE(report.ok) << report.failure;
  }
  const std::vector<SurfaceTriangle> surface = classify_surface(mesh, original);
  EXPECT_GT(cut_count(surface), 0u);
  EXPECT_LT(cut_count(surface), surface.size());
  expect_classified_like_the_box(surface);
}

TEST(ClassifySurface, WithNoOriginalEverythingIsCut) {
  const TetMesh mesh = build(make_box_mesh(1, 1, 1));
  const std::vector<SurfaceTriangle> surface = classify_surface(mesh, TetMesh{});
  EXPECT_EQ(cut_count(surface), surface.size());
}

}  // namespace
}  // namespace tetcut::render
