// The binary sections of Gmsh MSH 2.2 and 4.1 (file-type 1). Section markers and counts stay
// text lines; the data between them is raw: ints are 4 bytes, MSH 4.1's size_t fields take the
// format line's data-size (8 from every Gmsh), coordinates are 8-byte doubles. The byte order is
// the writer's, told by the int 1 Gmsh writes after the format line. An error inside binary data
// is reported at its section's header line. Internal to the engine (not installed).
#pragma once

#include <cstdint>
#include <string_view>

#include "byte_order.hpp"
#include "gmsh_common.hpp"

namespace tetcut::io_detail {

class GmshBinaryReader {
 public:
  GmshBinaryReader(LineReader& lines, ErrorSink& sink, RawMesh& mesh, NodeIdMap& ids, GmshElementSink& elements)
      : lines_(lines), sink_(sink), mesh_(mesh), ids_(ids), elements_(elements) {}

  // After the format line "version 1 data-size": reads the check value (an int 1) and with it
  // the byte order. `size_bytes` is the data-size (MSH 4.1: bytes of a size_t; 2.2: must be 8).
  bool read_check_value(std::uint64_t size_bytes);

  // MSH 2.2: `count` nodes "int id, 3 doubles" after the count line.
  bool msh22_nodes(std::uint64_t count, std::uint64_t line);
  // MSH 2.2: `count` elements in blocks "int type, int n, int tags" then n "int id, tags, nodes".
  bool msh22_elements(std::uint64_t count, std::uint64_t line);
  // MSH 4.1: everything after the $Nodes line, up to $EndNodes.
  bool msh41_nodes(std::uint64_t line);
  // MSH 4.1: everything after the $Entities line, up to $EndEntities: the volumes' labels
  // (points, curves and surfaces skipped field by field).
  bool msh41_entities(std::uint64_t line, GmshVolumeLabels& volumes);
  // MSH 4.1: everything after the $Elements line, up to $EndElements; tets labelled by `volumes`.
  bool msh41_elements(std::uint64_t line, const GmshVolumeLabels& volumes);

 private:
  // The next `n` bytes (n counted in 64 bits: a product of file values), or an error naming
  // `what` at `line`.
  bool take(std::uint64_t n, std::string_view what, std::uint64_t line, std::string_view& bytes);
  bool check_count(std::uint64_t count, std::uint64_t record_bytes, std::string_view what, std::uint64_t line);
  // MSH 4.1's section header "numEntityBlocks total minTag maxTag" (sizes), each count checked
  // against the bytes left (a block header takes 12 + size bytes, an entry `entry_bytes`).
  bool msh41_section_header(std::string_view section, std::string_view noun, std::uint64_t entry_bytes,
                            std::uint64_t line, std::uint64_t& blocks, std::uint64_t& total);
  [[nodiscard]] std::uint64_t size_at(const unsigned char* p) const { return load_uint(p, size_bytes_, order_); }
  [[nodiscard]] std::int64_t int_at(const unsigned char* p) const { return load_int(p, 4, order_); }

  LineReader& lines_;
  ErrorSink& sink_;
  RawMesh& mesh_;
  NodeIdMap& ids_;
  GmshElementSink& elements_;
  ByteOrder order_ = ByteOrder::kLittle;
  std::size_t size_bytes_ = 8;
};

}  // namespace tetcut::io_detail
