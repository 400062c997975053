// Files as other tools write them (corpus/test-files): each holds the two tets ABCD / BCDE with
// the quirks of its format, and each must read as exactly that mesh.
#include <algorithm>
#include <utility>
#include <vector>

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

// A file with the quirks of its format, and the notices reading it must give.
struct QuirkyFile {
  const char* test_name;
  const char* file;
  std::vector<const char*> notices;
};

const QuirkyFile kQuirkyFiles[] = {
    {"Msh22SparseUnorderedIdsTagsCommentsAndMixedElements", "two_tets_msh22_quirks.msh",
     {"ignored 3 elements of type 2 (triangle)", "ignored 1 elements of type 1 (line)",
      "ignored 1 elements of type 15 (point)"}},
    {"Msh41EntityBlocksParametricNodesAndPhysicalTags", "two_tets_msh41_quirks.msh",
     {"ignored 1 elements of type 2 (triangle)"}},
    {"Msh10NodAndElmSections", "two_tets_msh10.msh", {"ignored 1 elements of type 2 (triangle)"}},
    {"LegacyVtk3WithFieldDataMixedCellsAndFreeFormatPoints", "two_tets_v3.vtk",
     {"ignored 1 cells of VTK type 5 (triangle)", "ignored 1 cells of VTK type 1 (vertex)"}},
    {"LegacyVtk51OffsetsConnectivityAndMetadata", "two_tets_v51.vtk", {"ignored 1 cells of VTK type 5 (triangle)"}},
    {"VtuAsciiWithPointAndCellData", "two_tets_ascii.vtu", {"ignored 1 cells of VTK type 5 (triangle)"}},
    {"VtuInlineBinaryWithUInt32Headers", "two_tets_binary_uint32.vtu", {}},
    {"VtuInlineBinaryWithUInt64Headers", "two_tets_binary_uint64.vtu", {}},
    {"VtuAppendedRaw", "two_tets_appended_raw.vtu", {}},
    {"VtuAppendedBase64", "two_tets_appended_base64.vtu", {}},
    {"MeditCommentsSplitKeywordAndExtraSections", "two_tets_quirks.mesh",
     {"ignored 2 entries of Triangles", "ignored 2 entries of Corners"}},
    {"TetgenZeroBasedWithAttributesMarkersAndComments", "two_tets_zero_based.node", {}},
    {"TetgenOneBased", "two_tets_one_based.ele", {}},
};

class QuirkyTestFile : public ::testing::TestWithParam<QuirkyFile> {};

TEST_P(QuirkyTestFile, ReadsAsTheTwoTetsWithItsNotices) {
  const ReadResult r = read_test_file(GetParam().file);
  expect_two_tets(r);
  for (const char* notice : GetParam().notices) EXPECT_TRUE(has_notice(r, notice)) << notice;
}

INSTANTIATE_TEST_SUITE_P(CorpusTestFiles, QuirkyTestFile, ::testing::ValuesIn(kQuirkyFiles),
                         [](const auto& info) { return std::string(info.param.test_name); });

TEST(TestFiles, CrlfLineEndsAndTetgenNumberingReadTheSame) {
  const std::pair<const char*, const char*> alike[] = {{"two_tets_msh22_quirks.msh", "two_tets_msh22_crlf.msh"},
                                                       {"two_tets_quirks.mesh", "two_tets_crlf.mesh"},
                                                       {"two_tets_zero_based.node", "two_tets_one_based.ele"}};
  for (const auto& [first, second] : alike) {
    SCOPED_TRACE(second);
    const ReadResult a = read_test_file(first);
    const ReadResult b = read_test_file(second);
    ASSERT_TRUE(a.mesh && b.mesh);
    EXPECT_TRUE(test::identical(*a.mesh, *b.mesh));
  }
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
