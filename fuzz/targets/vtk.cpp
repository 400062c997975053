// Fuzz target vtk: legacy VTK unstructured grid reader (ASCII and big-endian BINARY), then round
// trips through our ASCII and BINARY writers.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "support/reader_contract.hpp"
#include "tetcut/io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // The input is the file itself (no version byte): seeds stay real files, and the dictionary's
  // keywords apply directly.
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  tetcut::fuzz::fuzz_tet_reader("read_vtk", &tetcut::read_vtk, text, &tetcut::format_vtk, &tetcut::read_vtk,
                                &tetcut::format_vtk_binary);
  // The same bytes also go to the legacy POLYDATA surface reader (gen surface's .vtk input).
  tetcut::fuzz::check_surface_result("read_vtk_polydata", tetcut::read_vtk_polydata(text, "input"));
  return 0;
}
