// Every malformed input is refused with the file name, the 1-based line of the problem and a
// reason that says what is wrong. A file that ends too early is reported at its last line that
// holds something (0 for a file with nothing in it).
#include <functional>
#include <sstream>
#include <vector>

#include "io_test_support.hpp"

namespace tetcut {
namespace {

std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::string join(const std::vector<std::string>& lines) {
  std::string out;
  for (const std::string& l : lines) out += l + "\n";
  return out;
}

// Line n (1-based) replaced by `text`.
std::string with_line(const std::string& base, std::size_t n, const std::string& text) {
  auto lines = split_lines(base);
  lines.at(n - 1) = text;
  return join(lines);
}
// Only the first n lines.
std::string first_lines(const std::string& base, std::size_t n) {
  auto lines = split_lines(base);
  lines.resize(n);
  return join(lines);
}
std::string without_line(const std::string& base, std::size_t n) {
  auto lines = split_lines(base);
  lines.erase(lines.begin() + static_cast<std::ptrdiff_t>(n - 1));
  return join(lines);
}

using Reader = std::function<ReadResult(const std::string&)>;

struct Case {
  const char* what;
  std::string text;
  std::uint64_t line;
  const char* reason;  // a substring of the reason
};

void check_cases(const Reader& read, const char* name, const std::vector<Case>& cases) {
  for (const Case& c : cases) {
    SCOPED_TRACE(c.what);
    const ReadResult r = read(c.text);
    ASSERT_TRUE(r.error.has_value()) << "accepted";
    EXPECT_FALSE(r.mesh.has_value());
    EXPECT_EQ(r.error->file, name);
    EXPECT_EQ(r.error->line, c.line) << r.error->message();
    EXPECT_NE(r.error->reason.find(c.reason), std::string::npos) << r.error->message();
  }
}

// Lines: 1 $MeshFormat, 2 version, 3 $EndMeshFormat, 4 $Nodes, 5 count, 6-10 nodes,
// 11 $EndNodes, 12 $Elements, 13 count, 14-15 tets, 16 $EndElements.
const std::string kMsh22 =
    "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n5\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n"
    "5 1 1 1\n$EndNodes\n$Elements\n2\n1 4 2 1 1 1 2 3 4\n2 4 2 1 1 2 3 4 5\n$EndElements\n";

TEST(Malformed, ValidBasesAreAccepted) {
  EXPECT_TRUE(read_msh(kMsh22, "m.msh").mesh.has_value());
}

TEST(Malformed, Msh22) {
  ASSERT_NO_FATAL_FAILURE(check_cases([](const std::string& t) { return read_msh(t, "m.msh"); }, "m.msh",
              {
                  {"empty file", "", 1, "empty file"},
                  {"blank file", "\n\n  \n", 1, "empty file"},
                  {"garbage", "hello world\n\x01\x02", 1, "expected $MeshFormat"},
                  {"truncated in header", "$MeshFormat\n", 1, "end of file in $MeshFormat"},
                  {"truncated in nodes", first_lines(kMsh22, 8), 8, "end of file in $Nodes"},
                  {"truncated in elements", first_lines(kMsh22, 14), 14, "end of file in $Elements"},
                  {"truncated before elements", first_lines(kMsh22, 11), 11, "missing $Elements"},
                  {"missing $EndNodes", without_line(kMsh22, 11), 11, "expected $EndNodes"},
                  {"missing $EndElements", first_lines(kMsh22, 15), 15, "missing $EndElements"},
                  {"missing $EndMeshFormat", without_line(kMsh22, 3), 3, "expected $EndMeshFormat"},
                  {"section without end", kMsh22 + "$Comments\nabc\n", 17, "has no $EndComments"},
                  {"NaN coordinate", with_line(kMsh22, 7, "2 nan 0 0"), 7, "NaN coordinate"},
                  {"inf coordinate", with_line(kMsh22, 7, "2 1 -inf 0"), 7, "infinite coordinate"},
                  {"overflowing coordinate", with_line(kMsh22, 7, "2 1 1e999 0"), 7, "infinite coordinate"},
                  {"garbage coordinate", with_line(kMsh22, 7, "2 1 0x 0"), 7, "expected a coordinate, got '0x'"},
                  {"short node line", with_line(kMsh22, 7, "2 1 0"), 7, "expected a node id and 3 coordinates"},
                  {"undefined node", with_line(kMsh22, 15, "2 4 2 1 1 2 3 4 17"), 15, "node id 17 not defined"},
                  {"tet with 3 nodes", with_line(kMsh22, 14, "1 4 2 1 1 1 2 3"), 14,
                   "expected 4 node ids for a tetrahedron, got 3"},
                  {"tet with 5 nodes", with_line(kMsh22, 14, "1 4 2 1 1 1 2 3 4 5"), 14,
                   "expected 4 node ids for a tetrahedron, got 5"},
                  {"tags past the line", with_line(kMsh22, 14, "1 4 9 1 1 1 2 3 4"), 14, "bad number of tags"},
                  {"absurd node count", with_line(kMsh22, 5, "99999999999"), 5, "count 99999999999 exceeds file size"},
                  {"absurd element count", with_line(kMsh22, 13, "4000000000"), 13, "exceeds file size"},
                  {"negative count", with_line(kMsh22, 5, "-5"), 5, "negative count -5"},
                  {"count too large for the section", with_line(kMsh22, 5, "6"), 11, "section ended after 5 of 6 nodes"},
                  {"duplicate node id", with_line(kMsh22, 8, "2 0 1 0"), 8, "duplicate node id 2"},
                  {"ASCII data in a binary file", with_line(kMsh22, 2, "2.2 1 8"), 3, "binary check value '$End' is not the int 1"},
                  {"version 3", with_line(kMsh22, 2, "3.0 0 8"), 2, "unsupported MSH version"},
                  {"version 4.0", with_line(kMsh22, 2, "4 0 8"), 2, "MSH 4.0 is not supported"},
                  {"second $Nodes", kMsh22 + "$Nodes\n0\n$EndNodes\n", 17, "second $Nodes"},
                  {"stray end marker", with_line(kMsh22, 12, "$EndFoo"), 12, "unexpected '$EndFoo'"},
                  {"element type garbage", with_line(kMsh22, 14, "1 tet 2 1 1 1 2 3 4"), 14, "expected an element type"},
              }));
}

// 1 $MeshFormat 2 4.1 3 $End 4 $Nodes 5 header 6 block 7-11 tags 12-16 coords 17 $EndNodes
// 18 $Elements 19 header 20 block 21-22 tets 23 $EndElements
const std::string kMsh41 =
    "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 5 1 5\n3 1 0 5\n1\n2\n3\n4\n5\n0 0 0\n1 0 0\n"
    "0 1 0\n0 0 1\n1 1 1\n$EndNodes\n$Elements\n1 2 1 2\n3 1 4 2\n1 1 2 3 4\n2 2 3 4 5\n$EndElements\n";

TEST(Malformed, Msh41) {
  ASSERT_TRUE(read_msh(kMsh41, "m.msh").mesh.has_value()) << test::describe(read_msh(kMsh41, "m.msh"));
  ASSERT_NO_FATAL_FAILURE(check_cases([](const std::string& t) { return read_msh(t, "m.msh"); }, "m.msh",
              {
                  // 5 nodes take at least 10 lines: 3 lines left cannot hold them.
                  {"truncated in tags", first_lines(kMsh41, 9), 6, "count 5 exceeds file size"},
                  {"truncated in tags, count fits", first_lines(kMsh41, 9) + "\n\n\n\n\n", 9,
                   "unexpected end of file in $Nodes (node tags)"},
                  {"truncated in coordinates", first_lines(kMsh41, 14), 14, "unexpected end of file in $Nodes (coordinates)"},
                  {"truncated in elements", first_lines(kMsh41, 21), 21, "unexpected end of file in $Elements"},
                  {"missing $EndElements", first_lines(kMsh41, 22), 22, "missing $EndElements"},
                  {"NaN coordinate", with_line(kMsh41, 13, "nan 0 0"), 13, "NaN coordinate"},
                  {"duplicate tag", with_line(kMsh41, 9, "2"), 9, "duplicate node id 2"},
                  {"tet with 5 nodes", with_line(kMsh41, 22, "2 2 3 4 5 1"), 22, "expected 4 node ids for a tetrahedron, got 5"},
                  {"tet with 3 nodes", with_line(kMsh41, 21, "1 1 2 3"), 21, "expected 4 node ids for a tetrahedron, got 3"},
                  {"undefined node", with_line(kMsh41, 22, "2 2 3 4 99"), 22, "node id 99 not defined"},
                  {"absurd block count", with_line(kMsh41, 19, "99999999999 2 1 2"), 19, "exceeds file size"},
                  {"negative block size", with_line(kMsh41, 6, "3 1 0 -1"), 6, "negative count -1"},
                  {"blocks short of the total", with_line(kMsh41, 5, "1 6 1 6"), 16, "node blocks hold 5 nodes, the header declares 6"},
                  {"bad parametric flag", with_line(kMsh41, 6, "3 1 7 5"), 6, "parametric must be 0 or 1"},
                  {"ASCII data in a binary file", with_line(kMsh41, 2, "4.1 1 8"), 3, "binary check value '$End' is not the int 1"},
              }));
}

TEST(Malformed, Msh10) {
  const std::string base =
      "$NOD\n5\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n5 1 1 1\n$ENDNOD\n$ELM\n2\n1 4 1 1 4 1 2 3 4\n"
      "2 4 1 1 4 2 3 4 5\n$ENDELM\n";
  ASSERT_TRUE(read_msh(base, "m.msh").mesh.has_value());
  ASSERT_NO_FATAL_FAILURE(check_cases([](const std::string& t) { return read_msh(t, "m.msh"); }, "m.msh",
              {
                  {"count mismatch", with_line(base, 11, "1 4 1 1 3 1 2 3 4"), 11, "declares '3' nodes but lists 4"},
                  {"tet with 3 nodes", with_line(base, 11, "1 4 1 1 3 1 2 3"), 11, "expected 4 node ids for a tetrahedron, got 3"},
                  {"undefined node", with_line(base, 12, "2 4 1 1 4 2 3 4 0"), 12, "node id 0 not defined"},
                  {"missing $ENDELM", first_lines(base, 12), 12, "missing $ENDELM"},
                  {"truncated nodes", first_lines(base, 4), 4, "unexpected end of file in $NOD"},
              }));
}

// 1-3 header, 4 DATASET, 5 POINTS, 6-8 coords, 9 CELLS, 10-11 cells, 12 CELL_TYPES, 13-14 types
const std::string kVtk =
    "# vtk DataFile Version 3.0\nt\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 5 double\n0 0 0 1 0 0\n"
    "0 1 0 0 0 1\n1 1 1\nCELLS 2 10\n4 0 1 2 3\n4 1 2 3 4\nCELL_TYPES 2\n10\n10\n";

TEST(Malformed, LegacyVtk) {
  ASSERT_TRUE(read_vtk(kVtk, "m.vtk").mesh.has_value());
  ASSERT_NO_FATAL_FAILURE(check_cases([](const std::string& t) { return read_vtk(t, "m.vtk"); }, "m.vtk",
              {
                  {"empty file", "", 1, "empty file"},
                  {"garbage", "garbage\n", 1, "not a legacy VTK file"},
                  {"ASCII data in a binary file", with_line(kVtk, 3, "BINARY"), 5, "binary POINTS: 15 double values need 120 bytes"},
                  {"polydata", with_line(kVtk, 4, "DATASET POLYDATA"), 4, "not an UNSTRUCTURED_GRID"},
                  {"NaN coordinate", with_line(kVtk, 7, "0 1 0 0 NaN 1"), 7, "NaN coordinate"},
                  {"truncated points", first_lines(kVtk, 7), 7, "unexpected end of file: expected point coordinates"},
                  {"absurd point count", with_line(kVtk, 5, "POINTS 99999999999 double"), 5, "exceeds file size"},
                  {"negative cell count", with_line(kVtk, 9, "CELLS -2 10"), 9, "negative count -2"},
                  {"out of range point", with_line(kVtk, 11, "4 1 2 3 5"), 11, "point id 5 not defined"},
                  {"negative point id", with_line(kVtk, 11, "4 1 2 3 -1"), 11, "point id -1 not defined"},
                  {"tet with 3 points", with_line(with_line(kVtk, 9, "CELLS 2 9"), 11, "3 1 2 3"), 11,
                   "expected 4 point ids for a tetrahedron (cell 1), got 3"},
                  {"cell list size mismatch", with_line(kVtk, 9, "CELLS 2 11"), 9, "does not match"},
                  {"cell overruns size", with_line(kVtk, 9, "CELLS 2 6"), 11, "overruns"},
                  {"missing CELL_TYPES", first_lines(kVtk, 11), 11, "missing CELL_TYPES"},
                  {"type count mismatch", with_line(kVtk, 12, "CELL_TYPES 3"), 12, "CELL_TYPES declares 3 cells"},
                  {"unknown keyword", with_line(kVtk, 12, "CELL_TYPO 2"), 12, "unexpected keyword 'CELL_TYPO'"},
              }));
}

const std::string kVtu = format_vtu(test::two_tets());

TEST(Malformed, Vtu) {
  ASSERT_TRUE(read_vtu(kVtu, "m.vtu").mesh.has_value());
  // Lines: 6 Points DataArray, 7-11 points, 15 connectivity DataArray, 16-17 connectivity,
  // 19 offsets, 23 types DataArray, 30 </VTKFile>.
  ASSERT_NO_FATAL_FAILURE(check_cases([](const std::string& t) { return read_vtu(t, "m.vtu"); }, "m.vtu",
              {
                  {"empty file", "", 1, "empty file"},
                  {"garbage", "garbage", 1, "no <VTKFile>"},
                  {"NaN coordinate", with_line(kVtu, 8, "nan 0 0"), 8, "NaN coordinate"},
                  {"out of range point", with_line(kVtu, 17, "1 2 3 7"), 23, "point id 7 not defined"},
                  {"tet with 3 points", with_line(with_line(kVtu, 17, "1 2 3"), 21, "7"), 23,
                   "expected 4 point ids for a tetrahedron (cell 1), got 3"},
                  {"truncated", first_lines(kVtu, 20), 20, "missing </DataArray>"},
                  {"missing root end", first_lines(kVtu, 29), 29, "missing </VTKFile>"},
                  {"mismatched end tag", with_line(kVtu, 13, "</Cells>"), 13, "expected </Points>"},
                  {"too few points", with_line(kVtu, 11, ""), 6, "expected 15 coordinate values, got 12"},
                  {"absurd point count", with_line(kVtu, 4, "<Piece NumberOfPoints=\"99999999999\" NumberOfCells=\"2\">"), 4,
                   "exceeds file size"},
                  {"negative cell count", with_line(kVtu, 4, "<Piece NumberOfPoints=\"5\" NumberOfCells=\"-2\">"), 4,
                   "NumberOfCells must be a non-negative integer"},
                  {"offsets decreasing", with_line(kVtu, 21, "3"), 19, "offsets not increasing"},
                  {"unknown type", with_line(kVtu, 6, "<DataArray type=\"Float128\" NumberOfComponents=\"3\" format=\"ascii\">"), 6,
                   "unsupported DataArray type"},
                  {"bad base64", with_line(with_line(kVtu, 19, "<DataArray type=\"Int64\" Name=\"offsets\" format=\"binary\">"), 20, "AAAA*AAA"), 20,
                   "invalid base64"},
                  {"appended without data", with_line(kVtu, 19, "<DataArray type=\"Int64\" Name=\"offsets\" format=\"appended\" offset=\"0\">"), 19,
                   "no <AppendedData>"},
                  {"unterminated comment", "<?xml version=\"1.0\"?>\n<!-- never closed\n", 2, "unterminated comment"},
              }));
}

// 1 MeshVersionFormatted, 3 Dimension, 5 Vertices, 6 count, 7-11 vertices, 13 Tetrahedra,
// 14 count, 15-16 tets, 18 End
const std::string kMedit = format_medit(test::two_tets());

TEST(Malformed, Medit) {
  ASSERT_TRUE(read_medit(kMedit, "m.mesh").mesh.has_value());
  ASSERT_NO_FATAL_FAILURE(check_cases([](const std::string& t) { return read_medit(t, "m.mesh"); }, "m.mesh",
              {
                  {"empty file", "", 0, "empty file"},
                  {"garbage", "garbage\n", 1, "expected MeshVersionFormatted"},
                  {"2D", with_line(kMedit, 3, "Dimension 2"), 3, "only 3D meshes"},
                  {"NaN coordinate", with_line(kMedit, 8, "nan 0 0 0"), 8, "NaN coordinate"},
                  {"truncated vertices", first_lines(kMedit, 9), 9, "unexpected end of file in Vertices"},
                  {"absurd count", with_line(kMedit, 6, "99999999999"), 6, "exceeds file size"},
                  {"negative count", with_line(kMedit, 14, "-1"), 14, "negative count -1"},
                  {"vertex id past the end", with_line(kMedit, 16, "2 3 4 6 1"), 16, "vertex id 6 not defined"},
                  {"vertex id 0", with_line(kMedit, 16, "0 3 4 5 1"), 16, "vertex id 0 not defined"},
                  {"tet with 3 vertices", with_line(kMedit, 16, "2 3 4"), 16, "expected 4 vertex ids and a reference for a tetrahedron, got 3"},
                  {"missing End", first_lines(kMedit, 17), 16, "missing End"},
                  {"missing tets", first_lines(kMedit, 12), 11, "missing Tetrahedra"},
                  {"unknown keyword", with_line(kMedit, 12, "Bogus"), 13, "unknown keyword 'Bogus'"},
              }));
}

TEST(Malformed, Tetgen) {
  const std::string node = "5 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n5 1 1 1\n";
  const std::string ele = "2 4 0\n1 1 2 3 4\n2 2 3 4 5\n";
  ASSERT_TRUE(read_tetgen(node, "m.node", ele, "m.ele").mesh.has_value());
  ASSERT_NO_FATAL_FAILURE(check_cases([&](const std::string& t) { return read_tetgen(t, "m.node", ele, "m.ele"); }, "m.node",
              {
                  {"empty node file", "", 0, "empty file"},
                  {"duplicate id", with_line(node, 3, "1 1 0 0"), 3, "duplicate point id 1"},
                  {"NaN", with_line(node, 4, "3 0 nan 0"), 4, "NaN coordinate"},
                  {"truncated", first_lines(node, 3), 3, "expected 5 points, got 2"},
                  {"absurd count", with_line(node, 1, "99999999999 3 0 0"), 1, "exceeds file size"},
                  {"2D", with_line(node, 1, "5 2 0 0"), 1, "only 3D points"},
                  {"missing attribute", with_line(node, 1, "5 3 1 0"), 2, "expected 5 values for a point"},
              }));
  ASSERT_NO_FATAL_FAILURE(check_cases([&](const std::string& t) { return read_tetgen(node, "m.node", t, "m.ele"); }, "m.ele",
              {
                  {"undefined node", with_line(ele, 3, "2 2 3 4 6"), 3, "node id 6 not defined"},
                  {"tet with 3 nodes", with_line(ele, 3, "2 2 3 4"), 3, "expected 4 node ids for a tetrahedron"},
                  {"negative count", with_line(ele, 1, "-2 4 0"), 1, "negative count -2"},
                  {"bad nodes per tet", with_line(ele, 1, "2 5 0"), 1, "must be 4 or 10"},
                  {"truncated", first_lines(ele, 2), 2, "expected 2 tetrahedra, got 1"},
              }));
}

}  // namespace
}  // namespace tetcut
