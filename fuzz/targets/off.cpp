// Fuzz target off: the .off surface reader (input of mesh generation) never crashes and returns
// triangles over existing, finite vertices.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "support/reader_contract.hpp"
#include "tetcut/io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // The input is the file itself (no version byte): seeds stay real files.
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  tetcut::fuzz::check_surface_result("read_off", tetcut::read_off(bytes, "input.off"));
  return 0;
}
