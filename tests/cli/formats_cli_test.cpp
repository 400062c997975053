// The command line on the files users bring: binary and compressed output that reads
// back, a file without tets refused saying what it held, a mesh in the opposite orientation named
// with the command that turns it, formats told by content, VTK surfaces tetrahedralized, and bad
// binary input refused on one line.
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "cli_fixture.hpp"
#include "tetcut/canonical_hash.hpp"

namespace tetcut::test {
namespace {

std::string corpus(const std::string& name) { return std::string(TETCUT_CORPUS_DIR) + "/test-files/" + name; }

// The run exited 2 and its last line of stderr is "tetcut: FILE: LAST_LINE".
testing::AssertionResult refused_ending_with(const ProcessResult& r, const std::string& file, const std::string& last_line) {
  if (!r.exited) return testing::AssertionFailure() << "killed by signal " << r.signal;
  if (r.exit_code != 2) return testing::AssertionFailure() << "exit " << r.exit_code << ", expected 2\n" << r.out << r.err;
  if (r.err.empty() || r.err.back() != '\n') return testing::AssertionFailure() << "stderr does not end a line: " << r.err;
  const std::size_t start = r.err.rfind('\n', r.err.size() - 2);
  const std::string last = r.err.substr(start == std::string::npos ? 0 : start + 1);
  const std::string expected = "tetcut: " + file + ": " + last_line + "\n";
  if (last != expected) return testing::AssertionFailure() << "last line " << last << "expected   " << expected << r.err;
  return testing::AssertionSuccess();
}

TEST_F(Cli, AFileWithoutTetsIsRefusedSayingWhatItHeld) {
  std::string hexes = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n8\n";
  for (int i = 0; i < 8; ++i) hexes += std::to_string(i + 1) + " " + std::to_string(i % 2) + " " + std::to_string(i / 2 % 2) + " " + std::to_string(i / 4) + "\n";
  hexes += "$EndNodes\n$Elements\n27\n";
  for (int e = 0; e < 27; ++e) hexes += std::to_string(e + 1) + " 5 2 1 1 1 2 4 3 5 6 8 7\n";
  hexes += "$EndElements\n";
  const std::string hex = write("hex.msh", hexes);
  EXPECT_TRUE(refused_ending_with(tetcut({"check", hex}), hex, "27 hexahedra, no tetrahedra"));
  EXPECT_TRUE(refused_ending_with(tetcut({"info", hex, "--json"}), hex, "27 hexahedra, no tetrahedra"));
  const std::string point = write("point.msh", "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n1\n1 0 0 0\n$EndNodes\n"
                                               "$Elements\n0\n$EndElements\n");
  EXPECT_TRUE(refused_ending_with(tetcut({"info", point}), point, "1 point and no cells, no tetrahedra"));
}

TEST_F(Cli, AMeshWhoseTetsAreAllInvertedIsNamedWithTheCommandThatReorientsIt) {
  RawMesh box = make_box_mesh(2, 2, 2);
  const std::string hash = hash_to_hex(canonical_hash(box));
  for (auto& t : box.tets) std::swap(t[2], t[3]);
  const std::string inverted = path("inverted.vtu");
  ASSERT_TRUE(write_mesh(inverted, box).ok);
  const ProcessResult check = tetcut({"check", inverted});
  EXPECT_EQ(check.exit_code, 1);
  EXPECT_NE(check.err.find("note: all " + std::to_string(box.tets.size()) + " tets are negatively oriented"),
            std::string::npos) << check.err;
  EXPECT_NE(check.err.find("`tetcut convert " + inverted + " OUT --reorient`"), std::string::npos) << check.err;

  const std::string fixed = path("fixed.msh");
  const ProcessResult convert = tetcut({"convert", inverted, fixed, "--reorient"});
  ASSERT_EQ(convert.exit_code, 0) << convert.err;
  EXPECT_TRUE(convert.err.empty()) << convert.err;  // no note about what it is fixing
  EXPECT_NE(convert.out.find("reoriented 48 of 48 tets"), std::string::npos) << convert.out;
  EXPECT_EQ(tetcut({"check", fixed}).exit_code, 0);
  EXPECT_EQ(tetcut_json({"info", fixed, "--json"}, 0).at("hash").get<std::string>(), hash);

  // One inverted tet among positive ones is the checker's business (I4), not a convention.
  std::swap(box.tets[1][2], box.tets[1][3]);
  std::swap(box.tets[0][2], box.tets[0][3]);
  ASSERT_TRUE(write_mesh(inverted, box).ok);
  const ProcessResult mixed = tetcut({"check", inverted});
  EXPECT_EQ(mixed.err.find("negatively oriented"), std::string::npos) << mixed.err;
}

TEST_F(Cli, BinaryAndCompressedOutputsReadBackWithTheSameHash) {
  const std::string box = write_box("box.msh", 2, 2, 3);
  const std::string hash = hash_to_hex(canonical_hash(make_box_mesh(2, 2, 3)));
  const std::vector<std::vector<std::string>> outputs = {
      {"b22.msh", "--binary"}, {"b41.msh", "--format", "msh41", "--binary"}, {"b.vtk", "--binary"},
      {"b.vtu", "--binary"},   {"z.vtu", "--compress", "zlib"},              {"x.vtu", "--compress", "lzma"}};
  for (const auto& output : outputs) {
    SCOPED_TRACE(output[0]);
    const ProcessResult r = convert(box, output);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find(hash), std::string::npos) << r.out;
    EXPECT_EQ(tetcut_json({"info", path(output[0]), "--json"}, 0).at("hash").get<std::string>(), hash);
  }
  const ProcessResult gmsh = tetcut({"convert", box, path("c.msh"), "--compress", "zlib"});
  EXPECT_EQ(gmsh.exit_code, 2);
  EXPECT_NE(gmsh.err.find("only VTU"), std::string::npos) << gmsh.err;
  EXPECT_FALSE(fs::exists(path("c.msh")));
  EXPECT_EQ(tetcut({"convert", box, path("m.mesh"), "--binary"}).exit_code, 2);
  EXPECT_EQ(tetcut({"convert", box, path("y.vtu"), "--compress", "bzip2"}).exit_code, 2);
}

TEST_F(Cli, BadBinaryFilesAreRefusedOnOneLine) {
  const RawMesh mesh = make_box_mesh(2, 2, 2);
  const std::vector<std::pair<std::string, std::string>> files = {
      {"cut.vtu", format_vtu_binary(mesh, Compression::kZlib)},
      {"cut.vtk", format_vtk_binary(mesh)},
      {"cut22.msh", format_msh22_binary(mesh)},
      {"cut41.msh", format_msh41_binary(mesh)},
  };
  for (const auto& [name, bytes] : files) {
    for (const std::size_t keep : {bytes.size() / 3, bytes.size() / 2, bytes.size() * 9 / 10}) {
      SCOPED_TRACE(name + " cut to " + std::to_string(keep) + " bytes");
      const std::string file = write(name, bytes.substr(0, keep));
      const ProcessResult r = tetcut({"info", file});
      EXPECT_EQ(r.exit_code, 2);
      EXPECT_TRUE(r.err.starts_with("tetcut: " + file + ":")) << r.err;
      EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "not one line: " << r.err;
    }
  }
}

TEST_F(Cli, TheContentDecidesTheFormatWhateverTheExtension) {
  const std::string vtk = write("really_xml.vtk", format_vtu_binary(make_box_mesh(1, 1, 1), Compression::kLzma));
  const ProcessResult r = tetcut({"info", vtk});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("the content is VTK XML UnstructuredGrid: read as VTK XML"), std::string::npos) << r.err;
  const std::string unknown = write("mesh.data", "solid x\n facet normal 0 0 1\n");
  const ProcessResult stl = tetcut({"info", unknown});
  EXPECT_EQ(stl.exit_code, 2);
  EXPECT_NE(stl.err.find("an ASCII STL surface"), std::string::npos) << stl.err;
  EXPECT_NE(stl.err.find("tetcut gen surface"), std::string::npos) << stl.err;
}

TEST_F(Cli, GenSurfaceTetrahedralizesVtkPolydataSurfaces) {
  for (const char* name : {"tetra_surface_binary.vtk", "tetra_surface_ascii.vtk", "tetra_surface.vtp"}) {
    SCOPED_TRACE(name);
    const std::string out = path(std::string(name) + ".msh");
    const ProcessResult r = tetcut({"gen", "surface", corpus(std::string("binary/") + name), "-o", out});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(tetcut({"check", out}).exit_code, 0);
  }
}

}  // namespace
}  // namespace tetcut::test
