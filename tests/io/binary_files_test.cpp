// Binary and compressed files as other tools write them (corpus/test-files/binary, written by
// make_binary_files.py with Python's struct, zlib and lzma, independently of our writers): each
// holds the two tets ABCD / BCDE (plus a triangle to ignore) and must read as exactly that mesh;
// the surfaces are a tetrahedron's four faces. Also: formats told by content, and what a file
// without tets is said to hold.
#include <algorithm>

#include "io_test_support.hpp"

namespace tetcut {
namespace {

using test::identical;

bool has_notice(const ReadResult& r, const std::string& text) {
  return std::any_of(r.notices.begin(), r.notices.end(),
                     [&](const std::string& n) { return n.find(text) != std::string::npos; });
}

std::string binary_file(const std::string& name) { return test::corpus_file("binary/" + name); }

TEST(BinaryFiles, EveryVtuEncodingReadsTheSameTwoTetsBitForBit) {
  int files = 0;
  for (const char* order : {"le", "be"}) {
    for (const char* header : {"u32", "u64"}) {
      for (const char* layout : {"inline", "raw", "b64"}) {
        for (const char* compressor : {"none", "zlib", "lzma"}) {
          const std::string name = std::string("vtu_") + order + "_" + header + "_" + layout + "_" + compressor + ".vtu";
          SCOPED_TRACE(name);
          const ReadResult r = read_mesh(binary_file(name));
          ASSERT_TRUE(r.mesh.has_value()) << test::describe(r);
          EXPECT_TRUE(identical(*r.mesh, test::two_tets()));
          EXPECT_TRUE(has_notice(r, "ignored 1 cells of VTK type 5 (triangle)"));
          ++files;
        }
      }
    }
  }
  EXPECT_EQ(files, 36);
}

TEST(BinaryFiles, LegacyVtkBinaryIsBigEndianWithFieldDataFloatPointsAndVersion51Arrays) {
  for (const char* name : {"two_tets_binary_v3.vtk", "two_tets_binary_v51.vtk"}) {
    SCOPED_TRACE(name);
    const ReadResult r = read_mesh(binary_file(name));
    ASSERT_TRUE(r.mesh.has_value()) << test::describe(r);
    EXPECT_TRUE(identical(*r.mesh, test::two_tets()));
    EXPECT_TRUE(has_notice(r, "ignored 1 cells of VTK type 5 (triangle)"));
  }
}

TEST(BinaryFiles, GmshBinaryInBothByteOrdersWithEntitiesParametricNodesAndSmallSizeT) {
  for (const char* name : {"two_tets_msh22_binary_le.msh", "two_tets_msh22_binary_be.msh",
                           "two_tets_msh41_binary_le.msh", "two_tets_msh41_binary_be.msh",
                           "two_tets_msh41_binary_size4.msh"}) {
    SCOPED_TRACE(name);
    const ReadResult r = read_mesh(binary_file(name));
    ASSERT_TRUE(r.mesh.has_value()) << test::describe(r);
    EXPECT_TRUE(identical(*r.mesh, test::two_tets()));
    EXPECT_TRUE(has_notice(r, "ignored 1 elements of type 2 (triangle)"));
  }
}

// The four faces of the tetrahedron A B C D, each as a sorted triple.
std::vector<std::array<std::uint32_t, 3>> sorted_faces(const SurfaceMesh& s) {
  std::vector<std::array<std::uint32_t, 3>> faces;
  for (auto t : s.triangles) {
    std::sort(t.begin(), t.end());
    faces.push_back(t);
  }
  std::sort(faces.begin(), faces.end());
  return faces;
}

TEST(BinaryFiles, VtkPolydataSurfacesLegacyAsciiBinaryStripsAndXml) {
  const std::vector<std::array<std::uint32_t, 3>> expected = {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}};
  for (const char* name : {"tetra_surface_ascii.vtk", "tetra_surface_binary.vtk", "tetra_surface_strips_binary.vtk",
                           "tetra_surface.vtp"}) {
    SCOPED_TRACE(name);
    const SurfaceReadResult r = read_surface(binary_file(name));
    ASSERT_TRUE(r.surface.has_value()) << (r.error ? r.error->message() : "");
    ASSERT_EQ(r.surface->positions.size(), 4u);
    EXPECT_EQ(r.surface->positions[3].z, 1.0);
    EXPECT_EQ(sorted_faces(*r.surface), expected);
    // Every face turned the same way round: each directed edge is used once.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
    for (const auto& t : r.surface->triangles) {
      for (int k = 0; k < 3; ++k) edges.emplace_back(t[k], t[(k + 1) % 3]);
    }
    std::sort(edges.begin(), edges.end());
    EXPECT_EQ(std::adjacent_find(edges.begin(), edges.end()), edges.end()) << "inconsistent orientation";
  }
}

TEST(BinaryFiles, TheContentDecidesOverTheExtension) {
  test::ScratchDir dir;
  std::string text;
  ASSERT_FALSE(read_file(binary_file("vtu_le_u32_inline_zlib.vtu"), text).has_value());
  ASSERT_TRUE(write_file_atomically(dir.file("really_xml.vtk"), text).ok);
  const ReadResult xml = read_mesh(dir.file("really_xml.vtk"));
  ASSERT_TRUE(xml.mesh.has_value()) << test::describe(xml);
  EXPECT_TRUE(identical(*xml.mesh, test::two_tets()));
  EXPECT_TRUE(has_notice(xml, "the content is VTK XML UnstructuredGrid")) << xml.notices.front();

  ASSERT_FALSE(read_file(binary_file("two_tets_msh41_binary_be.msh"), text).has_value());
  ASSERT_TRUE(write_file_atomically(dir.file("mesh.dat"), text).ok);
  const ReadResult gmsh = read_mesh(dir.file("mesh.dat"));
  ASSERT_TRUE(gmsh.mesh.has_value()) << test::describe(gmsh);
  EXPECT_TRUE(has_notice(gmsh, "unknown extension '.dat': the content is Gmsh MSH"));

  ASSERT_FALSE(read_file(binary_file("tetra_surface_binary.vtk"), text).has_value());
  ASSERT_TRUE(write_file_atomically(dir.file("surface.vtk"), text).ok);
  const ReadResult surface = read_mesh(dir.file("surface.vtk"));
  ASSERT_TRUE(surface.error.has_value());
  EXPECT_NE(surface.error->reason.find("legacy VTK POLYDATA, a surface"), std::string::npos) << surface.error->reason;
  EXPECT_NE(surface.error->reason.find("tetcut gen surface"), std::string::npos);

  ASSERT_TRUE(write_file_atomically(dir.file("noise.xyz"), std::string("\x01\x02\x03 binary", 10)).ok);
  const ReadResult noise = read_mesh(dir.file("noise.xyz"));
  ASSERT_TRUE(noise.error.has_value());
  EXPECT_NE(noise.error->reason.find("unknown extension '.xyz'"), std::string::npos);
  EXPECT_NE(noise.error->reason.find("binary data"), std::string::npos) << noise.error->reason;
}

TEST(BinaryFiles, AFileWithoutTetsSaysWhatItHeld) {
  // 27 hexahedra of a 3x3x3 grid (node ids only need to exist).
  std::string hexes = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n64\n";
  for (int i = 0; i < 64; ++i) hexes += std::to_string(i + 1) + " " + std::to_string(i % 4) + " " + std::to_string(i / 4 % 4) + " " + std::to_string(i / 16) + "\n";
  hexes += "$EndNodes\n$Elements\n28\n";
  for (int e = 0; e < 27; ++e) hexes += std::to_string(e + 1) + " 5 0 1 2 3 4 5 6 7 8\n";
  hexes += "28 1 0 1 2\n$EndElements\n";
  const ReadResult r = read_msh(hexes, "hex.msh");
  ASSERT_TRUE(r.mesh.has_value()) << test::describe(r);
  EXPECT_TRUE(r.mesh->tets.empty());
  EXPECT_EQ(no_tetrahedra_reason(r), "1 line and 27 hexahedra, no tetrahedra");

  const ReadResult points = read_msh("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n1\n1 0 0 0\n$EndNodes\n"
                                     "$Elements\n0\n$EndElements\n",
                                     "p.msh");
  ASSERT_TRUE(points.mesh.has_value());
  EXPECT_EQ(no_tetrahedra_reason(points), "1 point and no cells, no tetrahedra");

  const ReadResult vtk = read_vtk("# vtk DataFile Version 3.0\nt\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 3 double\n"
                                  "0 0 0 1 0 0 0 1 0\nCELLS 3 10\n3 0 1 2\n3 0 2 1\n1 0\nCELL_TYPES 3\n5\n5\n99\n",
                                  "t.vtk");
  ASSERT_TRUE(vtk.mesh.has_value()) << test::describe(vtk);
  EXPECT_EQ(no_tetrahedra_reason(vtk), "2 triangles and 1 cell of VTK type 99, no tetrahedra");
}

}  // namespace
}  // namespace tetcut
