// Fuzz target msh41: Gmsh MSH 4.1 reader (ASCII and binary, either byte order, 4- or 8-byte
// size_t), then round trips through our ASCII and binary writers.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "support/reader_contract.hpp"
#include "tetcut/io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // The input is the file itself (no version byte): seeds stay real files, and the dictionary's
  // keywords apply directly.
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  tetcut::fuzz::fuzz_tet_reader("read_msh41", &tetcut::read_msh41, text, &tetcut::format_msh41, &tetcut::read_msh41,
                                &tetcut::format_msh41_binary);
  return 0;
}
