// Per-tet labels (RawMesh::labels): every writer that carries them writes what every reader reads
// back, tet by tet; a file without labels reads unlabelled; bad label data is refused with the
// file, the line and the reason.
#include <array>
#include <string>
#include <vector>

#include "io_test_support.hpp"

namespace tetcut {
namespace {

RawMesh labelled_two_tets() {
  RawMesh m = test::two_tets();
  m.labels = {7, 1000};
  return m;
}

struct Writer {
  const char* what;
  std::string (*format)(const RawMesh&);
  ReadResult (*read)(std::string_view, std::string_view);
};

std::string vtu_zlib(const RawMesh& m) { return format_vtu_binary(m, Compression::kZlib); }
std::string vtu_raw(const RawMesh& m) { return format_vtu_binary(m, Compression::kNone); }

const Writer kWriters[] = {
    {"msh 2.2 ascii", format_msh22, read_msh},   {"msh 2.2 binary", format_msh22_binary, read_msh},
    {"msh 4.1 ascii", format_msh41, read_msh},   {"msh 4.1 binary", format_msh41_binary, read_msh},
    {"medit", format_medit, read_medit},         {"vtk ascii", format_vtk, read_vtk},
    {"vtk binary", format_vtk_binary, read_vtk}, {"vtu ascii", format_vtu, read_vtu},
    {"vtu appended", vtu_raw, read_vtu},         {"vtu zlib", vtu_zlib, read_vtu},
};

TEST(Labels, EveryLabelledFormatRoundTripsTheLabelsTetByTet) {
  const RawMesh m = labelled_two_tets();
  for (const Writer& w : kWriters) {
    SCOPED_TRACE(w.what);
    const ReadResult r = w.read(w.format(m), "m");
    ASSERT_TRUE(r.mesh.has_value()) << r.error->message();
    EXPECT_EQ(r.mesh->tets, m.tets);
    EXPECT_EQ(r.mesh->labels, m.labels);
  }
}

TEST(Labels, Msh41KeepsTheTetOrderWhenLabelsInterleave) {
  // Labels 5, 2, 5, 0 in that order: two volumes for three distinct labels' worth of runs; the
  // tets come back in their order with their labels, and one volume per label is written.
  RawMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}, {2, 0, 0}, {0, 2, 0}};
  m.tets = {{0, 1, 2, 3}, {1, 2, 3, 4}, {1, 5, 2, 3}, {2, 6, 1, 3}};
  m.labels = {5, 2, 5, 0};
  for (auto format : {format_msh41, format_msh41_binary}) {
    const std::string text = format(m);
    const ReadResult r = read_msh(text, "m.msh");
    ASSERT_TRUE(r.mesh.has_value()) << r.error->message();
    EXPECT_EQ(r.mesh->tets, m.tets);
    EXPECT_EQ(r.mesh->labels, m.labels);
  }
  const std::string ascii = format_msh41(m);
  // Volumes 1, 2, 3 carry labels 0, 2, 5; the four tets make four element blocks.
  EXPECT_NE(ascii.find("$Entities\n0 0 0 3\n1 0 0 0 1 2 1 1 0 0\n2 "), std::string::npos) << ascii;
  EXPECT_NE(ascii.find(" 1 5 0\n$EndEntities"), std::string::npos) << ascii;
  EXPECT_NE(ascii.find("$Elements\n4 4 1 4\n3 3 4 1\n1 1 2 3 4\n3 2 4 1\n"), std::string::npos) << ascii;
}

TEST(Labels, Msh41VolumesWithoutPhysicalTagsReadAsLabelZeroOrUnlabelled) {
  const std::string head =
      "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Entities\n1 0 0 2\n7 0 0 0 1 9\n"
      "1 0 0 0 1 1 1 0 0\n2 0 0 0 1 1 1 ";
  const std::string tail =
      " 0\n$EndEntities\n$Nodes\n1 5 1 5\n3 1 0 5\n1\n2\n3\n4\n5\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n1 1 1\n"
      "$EndNodes\n$Elements\n3 3 1 3\n0 7 15 1\n3 1\n3 1 4 1\n1 1 2 3 4\n3 2 4 1\n2 2 3 4 5\n$EndElements\n";
  // Volume 2 in physical group 8 (and 9, not the first), volume 1 in none: labels 0 and 8; the
  // point's physical tag 9 is no tet's.
  const ReadResult r = read_msh(head + "2 8 9" + tail, "m.msh");
  ASSERT_TRUE(r.mesh.has_value()) << r.error->message();
  EXPECT_EQ(r.mesh->labels, (std::vector<std::uint32_t>{0, 8}));
  const ReadResult u = read_msh(head + "0" + tail, "m.msh");
  ASSERT_TRUE(u.mesh.has_value()) << u.error->message();
  EXPECT_FALSE(u.mesh->labelled());
  // The unlabelled writer's single volume has no physical tag: it reads back unlabelled.
  EXPECT_FALSE(read_msh(format_msh41(test::two_tets()), "m").mesh->labelled());
  EXPECT_FALSE(read_msh(format_msh41_binary(test::two_tets()), "m").mesh->labelled());
}

TEST(Labels, UnlabelledMeshesWriteWhatTheyWroteBefore) {
  // Gmsh and medit always carried a region (1); VTK files gain no cell data.
  const RawMesh m = test::two_tets();
  EXPECT_NE(format_msh22(m).find("1 4 2 1 1 1 2 3 4\n"), std::string::npos);
  EXPECT_EQ(format_vtk(m).find("CELL_DATA"), std::string::npos);
  EXPECT_EQ(format_vtu(m).find("CellData"), std::string::npos);
  EXPECT_EQ(read_vtk(format_vtk(m), "m").mesh->labels.size(), 0u);
  EXPECT_EQ(read_vtu(format_vtu(m), "m").mesh->labels.size(), 0u);
  // Gmsh's single volume reads back as region 1.
  EXPECT_EQ(read_msh(format_msh22(m), "m").mesh->labels, (std::vector<std::uint32_t>{1, 1}));
}

TEST(Labels, FilesWithoutTagsReadUnlabelled) {
  const std::string msh =
      "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n$EndNodes\n"
      "$Elements\n1\n1 4 0 1 2 3 4\n$EndElements\n";
  const ReadResult r = read_msh(msh, "m.msh");
  ASSERT_TRUE(r.mesh.has_value());
  EXPECT_FALSE(r.mesh->labelled());
  const std::string medit =
      "MeshVersionFormatted 2\nDimension 3\nVertices\n4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n"
      "Tetrahedra\n1\n1 2 3 4\nEnd\n";
  const ReadResult m = read_medit(medit, "m.mesh");
  ASSERT_TRUE(m.mesh.has_value());
  EXPECT_FALSE(m.mesh->labelled());
}

TEST(Labels, CellDataOfOtherCellsIsSkippedAndTheBestNamedArrayWins) {
  // A triangle before the tet: its cell data value must not become the tet's label; "label"
  // wins over "gmsh:physical" whatever the order.
  const std::string vtk =
      "# vtk DataFile Version 3.0\nt\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 4 double\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n"
      "CELLS 2 9\n3 0 1 2\n4 0 1 2 3\nCELL_TYPES 2\n5\n10\nPOINT_DATA 4\nSCALARS p float 1\nLOOKUP_TABLE default\n"
      "0.5 1.5 2.5 3.5\nCELL_DATA 2\nFIELD f 2\ngmsh:physical 1 2 int\n4 5\nlabel 1 2 int\n8 9\n";
  const ReadResult r = read_vtk(vtk, "m.vtk");
  ASSERT_TRUE(r.mesh.has_value()) << r.error->message();
  EXPECT_EQ(r.mesh->labels, (std::vector<std::uint32_t>{9}));
}

void expect_refused(const ReadResult& r, const char* name, std::uint64_t line, const std::string& reason) {
  ASSERT_TRUE(r.error.has_value()) << "accepted";
  EXPECT_FALSE(r.mesh.has_value());
  EXPECT_EQ(r.error->file, name);
  EXPECT_EQ(r.error->line, line) << r.error->message();
  EXPECT_NE(r.error->reason.find(reason), std::string::npos) << r.error->message();
}

TEST(Labels, BadLabelDataIsRefusedWithFileLineAndReason) {
  const std::string msh_head =
      "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n$EndNodes\n$Elements\n1\n";
  expect_refused(read_msh(msh_head + "1 4 2 -3 1 1 2 3 4\n$EndElements\n", "m.msh"), "m.msh", 13,
                 "physical tag -3 is not a label");
  expect_refused(read_msh(msh_head + "1 4 2 3000000000 1 1 2 3 4\n$EndElements\n", "m.msh"), "m.msh", 13,
                 "physical tag 3000000000 is not a label");
  const std::string medit_head =
      "MeshVersionFormatted 2\nDimension 3\nVertices\n4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\nTetrahedra\n1\n";
  expect_refused(read_medit(medit_head + "1 2 3 4 x\nEnd\n", "m.mesh"), "m.mesh", 11,
                 "tetrahedron reference 'x' is not a label");
  const std::string vtk_head =
      "# vtk DataFile Version 3.0\nt\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 4 double\n0 0 0\n1 0 0\n0 1 0\n"
      "0 0 1\nCELLS 1 5\n4 0 1 2 3\nCELL_TYPES 1\n10\n";
  expect_refused(read_vtk(vtk_head + "CELL_DATA 1\nSCALARS label int 1\nLOOKUP_TABLE default\n2.5\n", "m.vtk"),
                 "m.vtk", 17, "expected cell data 'label' values");
  expect_refused(read_vtk(vtk_head + "CELL_DATA 1\nSCALARS label int 1\nLOOKUP_TABLE default\n-1\n", "m.vtk"),
                 "m.vtk", 15, "cell data 'label' of cell 0: -1 is not a label");
  expect_refused(read_vtk(vtk_head + "CELL_DATA 2\nSCALARS label int 1\n", "m.vtk"), "m.vtk", 14,
                 "CELL_DATA declares 2 values for 1 cells");
  expect_refused(read_vtk(vtk_head + "CELL_DATA 1\nSCALARS label int 2\nLOOKUP_TABLE default\n1 2\n", "m.vtk"),
                 "m.vtk", 15, "has 2 components, a label has 1");
  // .vtu: a label array of the wrong length, and one of reals.
  std::string vtu = format_vtu(labelled_two_tets());
  const std::size_t at = vtu.find("          1000\n");
  ASSERT_NE(at, std::string::npos);
  std::string short_array = vtu;
  short_array.erase(at, std::string("          1000\n").size());
  const ReadResult r = read_vtu(short_array, "m.vtu");
  ASSERT_TRUE(r.error.has_value());
  EXPECT_NE(r.error->reason.find("cell data 'label'"), std::string::npos) << r.error->message();
  EXPECT_GT(r.error->line, 0u);
  std::string reals = vtu;
  reals.replace(reals.find("type=\"Int32\" Name=\"label\""), 26, "type=\"Float64\" Name=\"label\"");
  const ReadResult f = read_vtu(reals, "m.vtu");
  ASSERT_TRUE(f.error.has_value());
  EXPECT_NE(f.error->reason.find("label"), std::string::npos) << f.error->message();
}

TEST(Labels, BadMsh41EntitiesAreRefusedWithFileLineAndReason) {
  const std::string format = "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";
  const std::string nodes =
      "$Nodes\n1 4 1 4\n3 1 0 4\n1\n2\n3\n4\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n$EndNodes\n";
  const auto with = [&](const std::string& entities, const std::string& block) {
    return format + "$Entities\n" + entities + "$EndEntities\n" + nodes + "$Elements\n1 1 1 1\n" + block +
           "\n1 1 2 3 4\n$EndElements\n";
  };
  expect_refused(read_msh(with("0 0 0 1\n1 0 0 0 1 1 1 1 3000000000 0\n", "3 1 4 1"), "m.msh"), "m.msh", 6,
                 "physical tag 3000000000 is not a label");
  expect_refused(read_msh(with("0 0 0 1\n1 0 0 0 1 1 1 1 -2 0\n", "3 1 4 1"), "m.msh"), "m.msh", 6,
                 "physical tag -2 is not a label");
  expect_refused(read_msh(with("0 0 0 1\n1 0 0 0 1 1 1 1 4 0\n", "3 2 4 1"), "m.msh"), "m.msh", 22,
                 "names volume entity 2, which $Entities does not list");
  expect_refused(read_msh(with("0 0 0 1\n1 0 0 0 1 1 1 1 4 0\n", "2 1 4 1"), "m.msh"), "m.msh", 22,
                 "entity dimension 2");
  // A volume whose bounding-surface count runs past its line, a field missing, a section cut short.
  expect_refused(read_msh(with("0 0 0 1\n1 0 0 0 1 1 1 1 4 3 1\n", "3 1 4 1"), "m.msh"), "m.msh", 6,
                 "expected a volume entity");
  expect_refused(read_msh(with("0 1 0 0\n1 0 0 0 1 1 1 0\n", "3 1 4 1"), "m.msh"), "m.msh", 6,
                 "expected a curve entity");
  expect_refused(read_msh(with("0 0 0 2\n1 0 0 0 1 1 1 1 4 0\n", "3 1 4 1"), "m.msh"), "m.msh", 7,
                 "section ended early");
  expect_refused(read_msh(with("0 0 0 2\n1 0 0 0 1 1 1 1 4 0\n1 0 0 0 1 1 1 0 0\n", "3 1 4 1"), "m.msh"), "m.msh",
                 7, "volume entity 1 listed twice");
  expect_refused(read_msh(format + "$Entities\n0 0 0 1\n1 0 0 0 1 1 1 1 4 0\n", "m.msh"), "m.msh", 6,
                 "missing $EndEntities");

  // Binary: the writer's own file, its $Entities cut short or its physical tag out of range.
  RawMesh m = labelled_two_tets();
  const std::string binary = format_msh41_binary(m);
  const std::size_t entities = binary.find("$Entities\n") + 10;
  const std::size_t end = binary.find("\n$EndEntities");
  expect_refused(read_msh(binary.substr(0, end - 3), "b.msh"), "b.msh", 5, "truncated file?");
  expect_refused(read_msh(binary.substr(0, entities + 40), "b.msh"), "b.msh", 5,
                 "count 2 of $Entities volumes exceeds file size");
  std::string out_of_range = binary;
  // Volume 2's physical tag (label 1000) is the int before its 8-byte bounding count.
  const std::size_t tag_at = end - 8 - 4;
  ASSERT_EQ(static_cast<unsigned char>(out_of_range[tag_at]), 1000 & 0xFF);
  out_of_range[tag_at + 3] = static_cast<char>(0x80);
  expect_refused(read_msh(out_of_range, "b.msh"), "b.msh", 5, "is not a label");
  std::string unknown = binary;
  // The first element block names volume 1 (label 7); make it volume 9.
  const std::size_t block = binary.find("$Elements\n") + 10 + 32;
  ASSERT_EQ(unknown[block + 4], 1);
  unknown[block + 4] = 9;
  expect_refused(read_msh(unknown, "b.msh"), "b.msh", 11, "names volume entity 9");
}

// TetGen: the .ele's attribute column (-A's region attribute, "an integer in the last column").
TEST(Labels, TetgenRegionAttributeRoundTripsTheLabelsTetByTet) {
  const RawMesh m = labelled_two_tets();
  const std::string ele = format_tetgen_ele(m);
  EXPECT_EQ(ele, "2 4 1\n1 1 2 3 4 7\n2 2 3 4 5 1000\n# written by tetcut\n");
  const ReadResult r = read_tetgen(format_tetgen_node(m), "m.node", ele, "m.ele");
  ASSERT_TRUE(r.mesh.has_value()) << r.error->message();
  EXPECT_EQ(r.mesh->tets, m.tets);
  EXPECT_EQ(r.mesh->labels, m.labels);
  EXPECT_TRUE(r.notices.empty());
  // And as files: write_mesh writes the pair, read_mesh reads it by either name.
  test::ScratchDir dir;
  ASSERT_TRUE(write_mesh((dir.path() / "a.ele").string(), m).ok);
  const ReadResult f = read_mesh((dir.path() / "a.node").string());
  ASSERT_TRUE(f.mesh.has_value()) << f.error->message();
  EXPECT_EQ(f.mesh->labels, m.labels);
}

TEST(Labels, TetgenUnlabelledFilesReadAndWriteWithoutAttributes) {
  const RawMesh m = test::two_tets();
  EXPECT_EQ(format_tetgen_ele(m), "2 4 0\n1 1 2 3 4\n2 2 3 4 5\n# written by tetcut\n");
  const ReadResult r = read_tetgen(format_tetgen_node(m), "m.node", format_tetgen_ele(m), "m.ele");
  ASSERT_TRUE(r.mesh.has_value()) << r.error->message();
  EXPECT_FALSE(r.mesh->labelled());
  // The header's attribute count may be left out, as TetGen's own reader allows.
  const ReadResult short_header = read_tetgen(format_tetgen_node(m), "m.node", "2 4\n1 1 2 3 4\n2 2 3 4 5\n", "m.ele");
  ASSERT_TRUE(short_header.mesh.has_value()) << short_header.error->message();
  EXPECT_FALSE(short_header.mesh->labelled());
}

TEST(Labels, TetgenFilesAsTetgenWritesThemGiveTheirRegionAttributes) {
  // The layout of TetGen's .ele example (0-based here, comments, aligned columns), with -A's
  // region attribute last; attributes are REALs in tetgenio, so "-2e1" or "3.0" may be written.
  const std::string node = "# a .node file\n5  3  0  0\n   0  0 0 0\n   1  1 0 0\n   2  0 1 0\n   3  0 0 1\n   4  1 1 1\n";
  const std::string ele =
      "# tetrahedra, nodes per tet, region attribute\n"
      "  2  4  1\n"
      "    0       0     1     2     3    11\n"
      "    1       1     2     3     4    3.0  # a comment after a record\n";
  const ReadResult r = read_tetgen(node, "p.node", ele, "p.ele");
  ASSERT_TRUE(r.mesh.has_value()) << r.error->message();
  EXPECT_EQ(r.mesh->labels, (std::vector<std::uint32_t>{11, 3}));
  // Several attributes (user attributes carried by -r, then -A's): the last is the label, with a
  // notice; 10-node tets keep their corners and their attribute.
  const std::string ele10 =
      "2 10 2\n0 0 1 2 3 0 0 0 0 0 0 0.25 20\n1 1 2 3 4 1 1 1 1 1 1 -2e1 5e0\n";
  const ReadResult q = read_tetgen(node, "p.node", ele10, "p.ele");
  ASSERT_TRUE(q.mesh.has_value()) << q.error->message();
  EXPECT_EQ(q.mesh->labels, (std::vector<std::uint32_t>{20, 5}));
  EXPECT_EQ(q.mesh->tets, (std::vector<std::array<std::uint32_t, 4>>{{0, 1, 2, 3}, {1, 2, 3, 4}}));
  ASSERT_EQ(q.notices.size(), 2u);
  EXPECT_NE(q.notices[1].find("the last of the 2 attributes"), std::string::npos) << q.notices[1];
}

TEST(Labels, TetgenBadRegionAttributesAreRefusedWithFileLineAndReason) {
  const std::string node = format_tetgen_node(test::two_tets());
  const auto ele = [](const std::string& second) { return "2 4 1\n1 1 2 3 4 1\n2 2 3 4 5 " + second + "\n"; };
  const std::pair<std::string, std::string> cases[] = {
      {ele("2.5"), "region attribute '2.5' is not a label"},
      {ele("-1"), "region attribute -1 is not a label"},
      {ele("-1.0"), "region attribute '-1.0' is not a label"},
      {ele("3000000000"), "region attribute 3000000000 is not a label"},
      {ele("3e9"), "region attribute '3e9' is not a label"},
      {ele("nan"), "region attribute 'nan' is not a label"},
      {ele("inf"), "region attribute 'inf' is not a label"},
      {ele("x"), "region attribute 'x' is not a label"},
      // A record without its attribute is one value short.
      {"2 4 1\n1 1 2 3 4 1\n2 2 3 4 5\n", "with 1 attributes"},
  };
  for (const auto& [text, reason] : cases) {
    SCOPED_TRACE(text);
    const ReadResult r = read_tetgen(node, "m.node", text, "m.ele");
    ASSERT_TRUE(r.error.has_value()) << "accepted";
    EXPECT_FALSE(r.mesh.has_value());
    expect_refused(r, "m.ele", 3, reason);
  }
}

TEST(Labels, WritersRefuseLabelsThatDoNotFitTheFormats) {
  test::ScratchDir dir;
  RawMesh m = labelled_two_tets();
  m.labels.pop_back();
  EXPECT_FALSE(write_mesh((dir.path() / "a.vtu").string(), m).ok);
  m.labels = {1, kMaxTetLabel + 1};
  const WriteResult w = write_mesh((dir.path() / "a.msh").string(), m);
  EXPECT_FALSE(w.ok);
  EXPECT_NE(w.error.find("label"), std::string::npos);
}

}  // namespace
}  // namespace tetcut
