// Fuzz target vtu: VTK XML unstructured grid reader (ascii, inline base64, appended raw or base64,
// UInt32/UInt64 headers, either byte order, zlib or xz compressed), then round trips through our
// ascii writer and our binary writer (appended raw, zlib).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "support/reader_contract.hpp"
#include "tetcut/io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // The input is the file itself (no version byte): seeds stay real files, and the dictionary's
  // keywords apply directly.
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  tetcut::fuzz::fuzz_tet_reader("read_vtu", &tetcut::read_vtu, text, &tetcut::format_vtu, &tetcut::read_vtu,
                                [](const tetcut::RawMesh& m) { return tetcut::format_vtu_binary(m, tetcut::Compression::kZlib); });
  // The same bytes also go to the XML PolyData surface reader (gen surface's .vtp input), which
  // shares the XML scanner and the DataArray decoding.
  tetcut::fuzz::check_surface_result("read_vtp", tetcut::read_vtp(text, "input"));
  return 0;
}
