// Fuzz target vtu: VTK XML unstructured grid reader (ascii, inline base64, appended), then a round trip.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "reader_contract.hpp"
#include "tetcut/io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // The input is the file itself (no version byte): seeds stay real files, and the dictionary's
  // keywords apply directly.
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  tetcut::fuzz::fuzz_tet_reader("read_vtu", &tetcut::read_vtu, text, &tetcut::format_vtu, &tetcut::read_vtu);
  return 0;
}
