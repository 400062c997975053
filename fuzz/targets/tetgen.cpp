// Fuzz target tetgen: the TetGen .node + .ele reader, then a round trip through our writers.
// One input holds both files: the .node text, a separator line, the .ele text. Without the
// separator the whole input is the .node file and the .ele file is empty.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "support/fuzz_failure.hpp"
#include "support/reader_contract.hpp"
#include "tetcut/io.hpp"

namespace {

// Also in tetgen.dict, so that libFuzzer can split an input it grew from a single file.
constexpr std::string_view kSeparator = "\n=== ele ===\n";

tetcut::ReadResult read_pair(std::string_view node, std::string_view ele) {
  return tetcut::read_tetgen(node, "input.node", ele, "input.ele");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const std::size_t cut = text.find(kSeparator);
  const std::string_view node = text.substr(0, cut);
  const std::string_view ele = cut == std::string_view::npos ? std::string_view() : text.substr(cut + kSeparator.size());
  const tetcut::ReadResult result = read_pair(node, ele);
  const tetcut::RawMesh* mesh = tetcut::fuzz::check_read_result("read_tetgen", result);
  if (mesh == nullptr) return 0;

  const std::string node_out = tetcut::format_tetgen_node(*mesh);
  const std::string ele_out = tetcut::format_tetgen_ele(*mesh);
  const tetcut::ReadResult again = read_pair(node_out, ele_out);
  if (!again.mesh)
    tetcut::fuzz::fail("round-trip", 1, "read_tetgen round trip",
                       "rereading our own output failed: " + (again.error ? again.error->message() : std::string()));
  if (again.mesh->positions != mesh->positions || again.mesh->tets != mesh->tets || again.mesh->labels != mesh->labels)
    tetcut::fuzz::fail("round-trip", 1, "read_tetgen round trip", "the mesh read back differs");
  return 0;
}
