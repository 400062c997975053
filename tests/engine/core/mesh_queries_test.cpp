#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "test_meshes.hpp"
#include "tetcut/detail/local_tables.hpp"

namespace tetcut {
namespace {

// Queries are checked against brute force over a 3x3x3 box, where being on the surface is a
// matter of coordinates.
class BoxQueries : public ::testing::Test {
 protected:
  static constexpr int kN = 3;
  TetMesh mesh = testing::build_or_fail(make_box_mesh(kN, kN, kN, {0, 0, 0}, {kN, kN, kN}));

  static bool on_box_surface(const Vec3& p) {
    for (double c : {p.x, p.y, p.z})
      if (c == 0.0 || c == kN) return true;
    return false;
  }
  // An edge lies on the surface iff both ends lie on one common face plane of the box.
  static bool edge_on_box_surface(const Vec3& p, const Vec3& q) {
    const double a[3] = {p.x, p.y, p.z}, b[3] = {q.x, q.y, q.z};
    for (int k = 0; k < 3; ++k)
      if (a[k] == b[k] && (a[k] == 0.0 || a[k] == kN)) return true;
    return false;
  }
  std::set<std::uint32_t> brute_shell(std::initializer_list<VertId> verts) const {
    std::set<std::uint32_t> shell;
    for (std::uint32_t t = 0; t < mesh.tet_capacity(); ++t) {
      bool all = true;
      for (VertId v : verts) all = all && mesh.local_index(TetId{t}, v) >= 0;
      if (all) shell.insert(t);
    }
    return shell;
  }
};

TEST_F(BoxQueries, VertexBoundaryFlagMatchesGeometry) {
  for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v)
    EXPECT_EQ(mesh.is_boundary_vertex(VertId{v}), on_box_surface(mesh.position(VertId{v}))) << v;
}

TEST_F(BoxQueries, NeighboursAreReciprocalAndShareTheFace) {
  for (std::uint32_t t = 0; t < mesh.tet_capacity(); ++t)
    for (int f = 0; f < 4; ++f) {
      const FaceRef n = mesh.neighbour(TetId{t}, f);
      if (!n.valid()) continue;
      EXPECT_EQ(mesh.neighbour(n.tet, n.face), (FaceRef{TetId{t}, static_cast<std::uint8_t>(f)}));
      for (int k = 0; k < 3; ++k)
        EXPECT_GE(mesh.local_index(n.tet, mesh.vertex(TetId{t}, kFaceVerts[f][k])), 0);
      EXPECT_EQ(mesh.local_index(n.tet, mesh.vertex(TetId{t}, f)), -1);
    }
}

TEST_F(BoxQueries, VertexShellIsExactlyTheTetsContainingTheVertex) {
  std::vector<TetId> shell;
  for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v) {
    mesh.vertex_shell(VertId{v}, shell);
    std::set<std::uint32_t> got;
    for (TetId t : shell) got.insert(t.value);
    EXPECT_EQ(got.size(), shell.size()) << "no tet twice";
    EXPECT_EQ(got, brute_shell({VertId{v}})) << v;
  }
}

TEST_F(BoxQueries, EdgeShellIsOrderedAroundTheEdgeAndClassifiesTheBoundary) {
  std::vector<TetId> shell;
  for (std::uint32_t t = 0; t < mesh.tet_capacity(); ++t)
    for (int e = 0; e < 6; ++e) {
      const VertId a = mesh.vertex(TetId{t}, kEdgeVerts[e][0]), b = mesh.vertex(TetId{t}, kEdgeVerts[e][1]);
      const bool boundary = edge_on_box_surface(mesh.position(a), mesh.position(b));
      EXPECT_EQ(mesh.is_boundary_edge(TetId{t}, e), boundary);
      EXPECT_EQ(mesh.edge_shell(TetId{t}, e, shell), boundary);
      std::set<std::uint32_t> got;
      for (TetId s : shell) got.insert(s.value);
      ASSERT_EQ(got, brute_shell({a, b}));
      ASSERT_EQ(got.size(), shell.size());
      // Consecutive tets are face neighbours (and the ring closes for an inner edge).
      const std::size_t steps = boundary ? shell.size() - 1 : shell.size();
      for (std::size_t i = 0; i < steps; ++i) {
        const TetId x = shell[i], y = shell[(i + 1) % shell.size()];
        if (x == y) continue;  // a one-tet shell
        bool adjacent = false;
        for (int f = 0; f < 4; ++f) adjacent = adjacent || mesh.neighbour(x, f).tet == y;
        EXPECT_TRUE(adjacent) << "tets " << x.value << " and " << y.value << " around edge";
      }
      if (boundary) {
        auto has_boundary_face_on_edge = [&](TetId s) {
          for (int f = 0; f < 4; ++f) {
            if (!mesh.is_boundary_face(s, f)) continue;
            const VertId opposite = mesh.vertex(s, f);
            if (opposite != a && opposite != b) return true;
          }
          return false;
        };
        EXPECT_TRUE(has_boundary_face_on_edge(shell.front()));
        EXPECT_TRUE(has_boundary_face_on_edge(shell.back()));
      }
    }
}

TEST_F(BoxQueries, BoundaryNormalOfAFaceCentreVertexIsTheAxis) {
  // Vertex (1, 1, 0) lies inside the bottom face: normal -z. Vertex (3, 1, 2): +x.
  auto id = [](int i, int j, int k) { return VertId{static_cast<std::uint32_t>(i + 4 * (j + 4 * k))}; };
  const Vec3 bottom = mesh.boundary_normal(id(1, 1, 0));
  EXPECT_NEAR(bottom.z, -1.0, 1e-12);
  EXPECT_NEAR(bottom.x, 0.0, 1e-12);
  const Vec3 side = mesh.boundary_normal(id(3, 1, 2));
  EXPECT_NEAR(side.x, 1.0, 1e-12);
  const Vec3 corner = mesh.boundary_normal(id(0, 0, 0));
  EXPECT_LT(corner.x, 0.0);
  EXPECT_LT(corner.y, 0.0);
  EXPECT_LT(corner.z, 0.0);
  EXPECT_EQ(mesh.boundary_normal(id(1, 1, 1)), (Vec3{0, 0, 0})) << "interior vertex";
}

TEST_F(BoxQueries, BoundaryFaceCountsAgreeWithFaces) {
  std::vector<std::uint32_t> count(mesh.vertex_capacity(), 0);
  std::vector<FaceRef> faces;
  mesh.boundary_faces(faces);
  for (const FaceRef& f : faces)
    for (int k = 0; k < 3; ++k) ++count[mesh.vertex(f.tet, kFaceVerts[f.face][k]).value];
  for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v) EXPECT_EQ(mesh.boundary_face_count(VertId{v}), count[v]);
}

TEST(MeshMemory, StaysUnderSixtyFourBytesPerTet) {
  const TetMesh mesh = testing::build_or_fail(make_box_mesh(10, 10, 10));
  EXPECT_LE(static_cast<double>(mesh.memory_bytes()) / mesh.num_tets(), 64.0);
}

}  // namespace
}  // namespace tetcut
