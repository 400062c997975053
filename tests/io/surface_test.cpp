// Closed triangle surfaces for mesh generation: .off, .stl (ASCII and binary), .obj.
#include <algorithm>

#include "io_test_support.hpp"

namespace tetcut {
namespace {

// Undirected edge use counts: a closed surface uses every edge exactly twice.
bool closed(const SurfaceMesh& s) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
  for (const auto& t : s.triangles) {
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = t[k];
      const std::uint32_t b = t[(k + 1) % 3];
      edges.emplace_back(std::min(a, b), std::max(a, b));
    }
  }
  std::sort(edges.begin(), edges.end());
  for (std::size_t i = 0; i < edges.size(); i += 2) {
    if (i + 1 >= edges.size() || edges[i] != edges[i + 1]) return false;
    if (i + 2 < edges.size() && edges[i + 2] == edges[i]) return false;
  }
  return true;
}

// cube_quads.off and .obj: a unit cube of 8 corners and 6 quads, read as 12 triangles.
SurfaceReadResult read_closed_cube(const std::string& name) {
  SurfaceReadResult r = read_surface(test::corpus_file(name));
  EXPECT_TRUE(r.surface.has_value()) << (r.error ? r.error->message() : "");
  if (!r.surface) return r;
  EXPECT_EQ(r.surface->positions.size(), 8u);
  EXPECT_EQ(r.surface->triangles.size(), 12u);
  EXPECT_TRUE(closed(*r.surface));
  return r;
}

TEST(Surface, OffQuadsBecomeTriangleFans) {
  const SurfaceReadResult r = read_closed_cube("cube_quads.off");
  ASSERT_EQ(r.notices.size(), 1u);
  EXPECT_NE(r.notices[0].find("split 6 polygons"), std::string::npos);
}

TEST(Surface, ObjWithSlashedCornersRelativeIndicesAndGroups) {
  // The cube of cube_quads.off, written with v/vt/vn and v//vn corners, a relative face (the
  // last one, -8 -4 -1 -5), groups, smoothing and materials: it reads to the same triangles.
  const SurfaceReadResult obj = read_closed_cube("cube_quads.obj");
  const SurfaceReadResult off = read_surface(test::corpus_file("cube_quads.off"));
  ASSERT_TRUE(obj.surface.has_value() && off.surface.has_value());
  EXPECT_EQ(obj.surface->positions, off.surface->positions);
  EXPECT_EQ(obj.surface->triangles, off.surface->triangles);
}

TEST(Surface, StlAsciiAndBinaryWeldToTheSameTetrahedron) {
  const SurfaceReadResult ascii = read_surface(test::corpus_file("tetra.stl"));
  const SurfaceReadResult binary = read_surface(test::corpus_file("tetra_binary.stl"));
  ASSERT_TRUE(ascii.surface.has_value()) << (ascii.error ? ascii.error->message() : "");
  ASSERT_TRUE(binary.surface.has_value()) << (binary.error ? binary.error->message() : "");
  EXPECT_EQ(ascii.surface->positions.size(), 4u);
  EXPECT_EQ(ascii.surface->triangles.size(), 4u);
  EXPECT_TRUE(closed(*ascii.surface));
  EXPECT_EQ(ascii.surface->positions, binary.surface->positions);
  EXPECT_EQ(ascii.surface->triangles, binary.surface->triangles);
}

TEST(Surface, MalformedSurfacesNameTheLine) {
  const auto err = [](const SurfaceReadResult& r) { return r.error.value_or(ParseError{"", 999, "accepted"}); };
  EXPECT_EQ(err(read_off("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 5\n", "a.off")).line, 6u);
  EXPECT_NE(err(read_off("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 5\n", "a.off")).reason.find("vertex id 5 not defined"),
            std::string::npos);
  EXPECT_EQ(err(read_off("OFF\n3 1 0\n0 0 0\n1 nan 0\n", "a.off")).line, 4u);
  EXPECT_NE(err(read_off("OFF\n99999999999 1 0\n", "a.off")).reason.find("exceeds file size"), std::string::npos);
  EXPECT_EQ(err(read_off("", "a.off")).reason, "empty file");
  EXPECT_EQ(err(read_obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n", "a.obj")).line, 4u);
  EXPECT_EQ(err(read_obj("v 0 0 0\nv 1 0 0\nf 1 2\n", "a.obj")).line, 3u);
  EXPECT_EQ(err(read_obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n", "a.obj")).line, 4u);
  EXPECT_EQ(err(read_stl("solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0\n", "a.stl")).line, 5u);
  EXPECT_NE(err(read_stl(std::string(84, '\0') + "x", "a.stl")).reason.find("binary STL header"), std::string::npos);
  const SurfaceReadResult unknown = read_surface("shape.ply");
  ASSERT_TRUE(unknown.error.has_value());
  EXPECT_NE(unknown.error->reason.find("unknown extension"), std::string::npos);
}

}  // namespace
}  // namespace tetcut
