// Files as other tools write them (corpus/test-files): each holds the two tets ABCD / BCDE with
// the quirks of its format, and each must read as exactly that mesh.
#include <algorithm>

#include "io_test_support.hpp"
#include "tetcut/canonical_hash.hpp"

namespace tetcut {
namespace {

bool has_notice(const ReadResult& r, const std::string& text) {
  return std::any_of(r.notices.begin(), r.notices.end(),
                     [&](const std::string& n) { return n.find(text) != std::string::npos; });
}

ReadResult read_test_file(const std::string& name) {
  const ReadResult r = read_mesh(test::corpus_file(name));
  EXPECT_TRUE(r.mesh.has_value()) << name << ": " << test::describe(r);
  return r;
}

void expect_two_tets(const ReadResult& r) {
  ASSERT_TRUE(r.mesh.has_value());
  EXPECT_EQ(r.mesh->positions.size(), 5u);
  EXPECT_EQ(r.mesh->tets.size(), 2u);
  EXPECT_EQ(canonical_hash(*r.mesh), canonical_hash(test::two_tets()));
}

TEST(TestFiles, Msh22SparseUnorderedIdsTagsCommentsAndMixedElements) {
  const ReadResult r = read_test_file("two_tets_msh22_quirks.msh");
  expect_two_tets(r);
  EXPECT_TRUE(has_notice(r, "ignored 3 elements of type 2 (triangle)"));
  EXPECT_TRUE(has_notice(r, "ignored 1 elements of type 1 (line)"));
  EXPECT_TRUE(has_notice(r, "ignored 1 elements of type 15 (point)"));
}

TEST(TestFiles, Msh22WithCrlfLineEndsReadsTheSame) {
  const ReadResult lf = read_test_file("two_tets_msh22_quirks.msh");
  const ReadResult crlf = read_test_file("two_tets_msh22_crlf.msh");
  ASSERT_TRUE(lf.mesh && crlf.mesh);
  EXPECT_TRUE(test::identical(*lf.mesh, *crlf.mesh));
}

TEST(TestFiles, Msh41EntityBlocksParametricNodesAndPhysicalTags) {
  const ReadResult r = read_test_file("two_tets_msh41_quirks.msh");
  expect_two_tets(r);
  EXPECT_TRUE(has_notice(r, "ignored 1 elements of type 2 (triangle)"));
}

TEST(TestFiles, Msh10NodAndElmSections) {
  const ReadResult r = read_test_file("two_tets_msh10.msh");
  expect_two_tets(r);
  EXPECT_TRUE(has_notice(r, "ignored 1 elements of type 2 (triangle)"));
}

TEST(TestFiles, LegacyVtk3WithFieldDataMixedCellsAndFreeFormatPoints) {
  const ReadResult r = read_test_file("two_tets_v3.vtk");
  expect_two_tets(r);
  EXPECT_TRUE(has_notice(r, "ignored 1 cells of VTK type 5 (triangle)"));
  EXPECT_TRUE(has_notice(r, "ignored 1 cells of VTK type 1 (vertex)"));
}

TEST(TestFiles, LegacyVtk51OffsetsConnectivityAndMetadata) {
  const ReadResult r = read_test_file("two_tets_v51.vtk");
  expect_two_tets(r);
  EXPECT_TRUE(has_notice(r, "ignored 1 cells of VTK type 5 (triangle)"));
}

TEST(TestFiles, VtuAsciiWithPointAndCellData) {
  const ReadResult r = read_test_file("two_tets_ascii.vtu");
  expect_two_tets(r);
  EXPECT_TRUE(has_notice(r, "ignored 1 cells of VTK type 5 (triangle)"));
}

TEST(TestFiles, VtuInlineBinaryWithUInt32AndUInt64Headers) {
  for (const char* name : {"two_tets_binary_uint32.vtu", "two_tets_binary_uint64.vtu"}) {
    SCOPED_TRACE(name);
    ASSERT_NO_FATAL_FAILURE(expect_two_tets(read_test_file(name)));
  }
}

TEST(TestFiles, VtuAppendedRawAndBase64) {
  for (const char* name : {"two_tets_appended_raw.vtu", "two_tets_appended_base64.vtu"}) {
    SCOPED_TRACE(name);
    ASSERT_NO_FATAL_FAILURE(expect_two_tets(read_test_file(name)));
  }
}

TEST(TestFiles, MeditCommentsSplitKeywordAndExtraSections) {
  const ReadResult r = read_test_file("two_tets_quirks.mesh");
  expect_two_tets(r);
  EXPECT_TRUE(has_notice(r, "ignored 2 entries of Triangles"));
  EXPECT_TRUE(has_notice(r, "ignored 2 entries of Corners"));
  const ReadResult crlf = read_test_file("two_tets_crlf.mesh");
  ASSERT_TRUE(crlf.mesh && r.mesh);
  EXPECT_TRUE(test::identical(*r.mesh, *crlf.mesh));
}

TEST(TestFiles, TetgenZeroAndOneBasedWithAttributesMarkersAndComments) {
  const ReadResult zero = read_test_file("two_tets_zero_based.node");
  const ReadResult one = read_test_file("two_tets_one_based.ele");
  expect_two_tets(zero);
  expect_two_tets(one);
  ASSERT_TRUE(zero.mesh && one.mesh);
  EXPECT_TRUE(test::identical(*zero.mesh, *one.mesh));
}

TEST(TestFiles, SecondOrderTetsAreReadAsTheirCorners) {
  const std::string msh =
      "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n5\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n5 1 1 1\n"
      "$EndNodes\n$Elements\n1\n1 11 2 1 1 1 2 3 4 5 5 5 5 5 5\n$EndElements\n";
  const ReadResult r = read_msh(msh, "p2.msh");
  ASSERT_TRUE(r.mesh.has_value()) << test::describe(r);
  ASSERT_EQ(r.mesh->tets.size(), 1u);
  EXPECT_EQ(r.mesh->tets[0], (std::array<std::uint32_t, 4>{0, 1, 2, 3}));
  EXPECT_TRUE(has_notice(r, "second-order"));
}

}  // namespace
}  // namespace tetcut
