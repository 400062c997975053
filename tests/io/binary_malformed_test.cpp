// Bad binary files: every one is refused with the file name and a reason (no crash, no mesh, no
// allocation beyond what the file holds: the ASan build would abort on one), whether it is cut
// short anywhere, declares a wrong header size, holds a corrupt compressed stream, or a count
// that overflows or exceeds the file.
#include <cstring>

#include "io_test_support.hpp"

namespace tetcut {
namespace {

std::string binary_text(const std::string& name) {
  std::string text;
  EXPECT_FALSE(read_file(test::corpus_file("binary/" + name), text).has_value()) << name;
  return text;
}

using Reader = ReadResult (*)(std::string_view, std::string_view);

Reader reader_for(const std::string& name) {
  if (name.ends_with(".vtu")) return &read_vtu;
  if (name.ends_with(".vtk")) return &read_vtk;
  return &read_msh;
}

// Cut short at every length, a file either reads as the whole mesh (only its trailing markers
// were lost) or is refused: never a crash, never another mesh.
TEST(BinaryMalformed, EveryTruncationIsAnErrorOrTheWholeMesh) {
  for (const char* name : {"vtu_le_u32_inline_zlib.vtu", "vtu_be_u64_raw_lzma.vtu", "vtu_le_u64_b64_zlib.vtu",
                           "vtu_be_u32_raw_none.vtu", "two_tets_binary_v3.vtk", "two_tets_binary_v51.vtk",
                           "two_tets_msh22_binary_be.msh", "two_tets_msh41_binary_le.msh"}) {
    SCOPED_TRACE(name);
    const std::string full = binary_text(name);
    const Reader read = reader_for(name);
    std::size_t refused = 0;
    for (std::size_t n = 0; n < full.size(); ++n) {
      const ReadResult r = read(std::string_view(full).substr(0, n), "cut");
      if (r.mesh) {
        ASSERT_TRUE(test::identical(*r.mesh, test::two_tets())) << "prefix of " << n << " bytes read as another mesh";
      } else {
        ASSERT_TRUE(r.error.has_value());
        ASSERT_EQ(r.error->file, "cut");
        ASSERT_FALSE(r.error->reason.empty());
        ++refused;
      }
    }
    // Only cuts in trailing data the readers do not need (CELL_DATA, closing tags) may read.
    EXPECT_GT(refused, full.size() / 2);
  }
}

void put_le(std::string& s, std::size_t at, std::uint64_t v, int bytes) {
  for (int i = 0; i < bytes; ++i) s[at + static_cast<std::size_t>(i)] = static_cast<char>((v >> (8 * i)) & 0xFF);
}

void put_be(std::string& s, std::size_t at, std::uint64_t v, int bytes) {
  for (int i = 0; i < bytes; ++i) s[at + static_cast<std::size_t>(bytes - 1 - i)] = static_cast<char>((v >> (8 * i)) & 0xFF);
}

std::string replaced(std::string s, const std::string& from, const std::string& to) {
  const std::size_t at = s.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) s.replace(at, from.size(), to);
  return s;
}

struct Case {
  const char* what;
  std::string bytes;
  const char* reason;  // a substring of the reason
};

// Every case refused with one line naming the file and containing its reason; every failing
// case is named in the result.
::testing::AssertionResult refused(Reader read, const std::vector<Case>& cases) {
  std::string failures;
  for (const Case& c : cases) {
    const ReadResult r = read(c.bytes, "bad");
    if (!r.error) {
      failures += std::string("\n") + c.what + ": accepted";
      continue;
    }
    const std::string message = r.error->message();
    if (r.mesh) failures += std::string("\n") + c.what + ": a mesh came back with the error";
    if (r.error->file != "bad") failures += std::string("\n") + c.what + ": names file '" + r.error->file + "'";
    if (r.error->reason.find(c.reason) == std::string::npos)
      failures += std::string("\n") + c.what + ": reason lacks '" + c.reason + "': " + message;
    if (message.find('\n') != std::string::npos) failures += std::string("\n") + c.what + ": more than one line: " + message;
  }
  if (failures.empty()) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << failures;
}

TEST(BinaryMalformed, CompressedVtu) {
  const std::string zlib = binary_text("vtu_le_u32_raw_zlib.vtu");
  const std::size_t data = zlib.find('_', zlib.find("<AppendedData")) + 1;  // the Points array's header
  std::string corrupt = zlib, blocks = zlib, csize = zlib, last = zlib, small = zlib;
  corrupt[data + 4 * 7 + 3] ^= 0x5A;          // inside the first compressed block (after 3 + 4 sizes)
  put_le(blocks, data, 0xFFFFFFFFu, 4);       // number of blocks
  put_le(csize, data + 12, 0x7FFFFFFFu, 4);   // compressed size of block 1
  put_le(last, data + 8, 1000, 4);            // last block larger than the block size
  put_le(small, data + 4, 16, 4);             // blocks of 16 bytes declared, 32 inside
  put_le(small, data + 8, 8, 4);
  const std::string lzma = binary_text("vtu_le_u32_raw_lzma.vtu");
  std::string bad_xz = lzma;
  bad_xz[lzma.find('_', lzma.find("<AppendedData")) + 1 + 4 * 7 + 20] ^= 0x5A;
  EXPECT_TRUE(refused(&read_vtu, {
      {"corrupt zlib stream", corrupt, "block 1 of 4: "},
      {"corrupt xz stream", bad_xz, "block 1 of 4: "},
      {"block count past the file", blocks, "blocks, more than the file holds"},
      {"compressed size past the file", csize, "add up to more than the file holds"},
      {"last block larger than a block", last, "larger than the block size"},
      {"block yields more than declared", small, "yields more than the 16 bytes"},
      {"wrong header size", replaced(zlib, "header_type=\"UInt32\"", "header_type=\"UInt64\""), ""},
      {"unknown header type", replaced(zlib, "header_type=\"UInt32\"", "header_type=\"UInt16\""), "header_type must be"},
      {"unsupported compressor", replaced(zlib, "vtkZLibDataCompressor", "vtkLZ4DataCompressor"), "is not supported"},
      {"compressor on uncompressed data", replaced(binary_text("vtu_le_u32_raw_none.vtu"), "header_type", "compressor=\"vtkZLibDataCompressor\" header_type"), ""},
  }));
}

TEST(BinaryMalformed, UncompressedVtu) {
  const std::string raw = binary_text("vtu_be_u64_raw_none.vtu");
  const std::size_t data = raw.find('_', raw.find("<AppendedData")) + 1;
  std::string huge = raw, odd = raw;
  put_be(huge, data, std::uint64_t{1} << 63, 8);  // the Points array's byte count
  put_be(odd, data, 119, 8);
  const std::string inline_text = binary_text("vtu_le_u32_inline_none.vtu");
  EXPECT_TRUE(refused(&read_vtu, {
      {"byte count past the file", huge, "exceeds file size"},
      {"byte count not a multiple of the type", odd, "not a multiple of its Float64 values"},
      {"count that overflows 3 coordinates", replaced(raw, "NumberOfPoints=\"5\"", "NumberOfPoints=\"6148914691236517206\""), "exceeds file size"},
      {"offset past the file", replaced(raw, "offset=\"0\"", "offset=\"99999999\""), "exceeds file size"},
      {"bad base64", replaced(inline_text, "AAAA", "A*AA"), "invalid base64"},
  }));
}

TEST(BinaryMalformed, LegacyVtkBinary) {
  const std::string v51 = binary_text("two_tets_binary_v51.vtk");
  const std::string v3 = binary_text("two_tets_binary_v3.vtk");
  std::string overrun = v3;
  put_be(overrun, v3.find("CELLS 3 14\n") + 11, 0x7FFFFFFF, 4);  // the first cell's point count
  EXPECT_TRUE(refused(&read_vtk, {
      {"points past the file", replaced(v51, "POINTS 5 double", "POINTS 50 double"), "binary POINTS: 150 double values need 1200 bytes"},
      {"connectivity past the file", replaced(v51, "CELLS 4 11", "CELLS 4 20"), "binary CONNECTIVITY: 20 vtktypeint64 values need 160 bytes"},
      {"absurd count", replaced(v51, "CELLS 4 11", "CELLS 4 99999999999999"), "exceeds file size"},
      {"unknown data type", replaced(v51, "POINTS 5 double", "POINTS 5 quad"), "unknown data type 'quad'"},
      {"cell overruns the list", overrun, "overruns the declared cell list size"},
      {"cell types and cells disagree", replaced(v3, "CELL_TYPES 3", "CELL_TYPES 4"), "CELL_TYPES declares 4 cells, CELLS 3"},
      {"field data past the file", replaced(v3, "TIME 1 1 double", "TIME 1 100 double"), "binary FIELD data"},
  }));
}

TEST(BinaryMalformed, GmshBinary) {
  const std::string m22 = binary_text("two_tets_msh22_binary_le.msh");
  const std::size_t elements = m22.find("$Elements\n3\n") + 12;
  std::string check = m22, block = m22, type = m22, tags = m22;
  put_le(check, m22.find("8\n") + 2, 7, 4);
  put_le(block, elements + 4, 0x7FFFFFFF, 4);
  put_le(type, elements, 99, 4);
  put_le(tags, elements + 8, 0x7FFFFFFF, 4);
  EXPECT_TRUE(refused(&read_msh, {
      {"check value", check, "is not the int 1 in either byte order"},
      {"node count past the file", replaced(m22, "$Nodes\n5\n", "$Nodes\n50\n"), "count 50 of nodes exceeds file size"},
      {"absurd node count", replaced(m22, "$Nodes\n5\n", "$Nodes\n99999999999999\n"), "exceeds file size"},
      {"element block past the count", block, "element block of 2147483647 elements after 0 of the 3 declared"},
      {"unknown element type", type, "unknown element type 99"},
      {"absurd number of tags", tags, "bad number of tags"},
      {"data-size 4 in 2.2", replaced(m22, "2.2 1 8", "2.2 1 4"), "data-size must be 8"},
      {"missing end marker", m22.substr(0, m22.size() - 13), "missing $EndElements"},
  }));
  const std::string m41 = binary_text("two_tets_msh41_binary_le.msh");
  const std::size_t nodes = m41.find("$Nodes\n") + 7;
  const std::size_t elements41 = m41.find("$Elements\n") + 10;
  std::string total = m41, blocks = m41, type41 = m41, count41 = m41;
  put_le(total, nodes + 8, std::uint64_t{1} << 60, 8);
  put_le(blocks, nodes, std::uint64_t{1} << 62, 8);
  put_le(type41, elements41 + 32 + 8, 99, 4);
  put_le(count41, elements41 + 32 + 12, 1000, 8);
  EXPECT_TRUE(refused(&read_msh, {
      {"absurd node total", total, "exceeds file size"},
      {"absurd block count", blocks, "exceeds file size"},
      {"unknown element type", type41, "unknown element type 99"},
      {"block past the element total", count41, "element blocks hold more than the 3 elements declared"},
      {"data-size 2", replaced(m41, "4.1 1 8", "4.1 1 2"), "data-size must be 4 or 8"},
  }));
}

}  // namespace
}  // namespace tetcut
