// Fuzz target medit: medit / Mmg .mesh reader, then a round trip through our writer.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "support/reader_contract.hpp"
#include "tetcut/io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // The input is the file itself (no version byte): seeds stay real files, and the dictionary's
  // keywords apply directly.
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  tetcut::fuzz::fuzz_tet_reader("read_medit", &tetcut::read_medit, text, &tetcut::format_medit, &tetcut::read_medit);
  return 0;
}
