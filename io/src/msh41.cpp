// Gmsh MSH 4.1, ASCII or binary. Nodes and elements come in entity blocks:
//   $Nodes: numBlocks numNodes minTag maxTag, then per block "dim entity parametric n", n tag
//   lines, n coordinate lines ("x y z" plus u [v [w]] when parametric).
//   $Elements: numBlocks numElements minTag maxTag, then per block "dim entity type n" and n lines
//   "tag node...".
// In a binary file the same fields are raw values (gmsh_binary.hpp).
// $Entities (physical tags live there), $PhysicalNames, $Comments and the rest are skipped.
#include <algorithm>
#include <array>
#include <string>

#include "gmsh_sections.hpp"
#include "tetcut/io.hpp"

namespace tetcut {

namespace {

using namespace io_detail;

class Msh41Reader : public GmshSectionReader {
 public:
  Msh41Reader(std::string_view text, std::string_view name) : GmshSectionReader(text, name) {}

 private:
  // The next non-blank line split into tokens_, which must not be a section marker.
  bool next_record(std::string_view where) {
    std::string_view line;
    if (!lines_.next_nonblank(line)) {
      return sink_.fail(lines_.line_number(), "unexpected end of file in " + std::string(where));
    }
    split_tokens(line, tokens_);
    if (tokens_[0][0] == '$') {
      return sink_.fail(lines_.line_number(), "section ended early: " + quote(tokens_[0]) + " in " + std::string(where));
    }
    return true;
  }

  bool expect_tokens(std::size_t n, std::string_view what) {
    if (tokens_.size() != n) {
      return sink_.fail(lines_.line_number(), "expected " + std::string(what) + ", got " +
                                                  std::to_string(tokens_.size()) + " values");
    }
    return true;
  }

  void read_format() override {
    if (!next_record("$MeshFormat") || !expect_tokens(3, "'version file-type data-size'")) return;
    if (tokens_[0] != "4.1") {
      sink_.fail(lines_.line_number(), "unsupported MSH version " + quote(tokens_[0]) + " (this reader reads 4.1)");
      return;
    }
    if (tokens_[1] == "1") {
      std::uint64_t data_size = 0;
      if (!parse_u64(tokens_[2], data_size)) {
        sink_.fail(lines_.line_number(), "data-size must be 4 or 8, got " + quote(tokens_[2]));
        return;
      }
      binary_ = true;
      if (!binary_reader_.read_check_value(data_size)) return;
    } else if (tokens_[1] != "0") {
      sink_.fail(lines_.line_number(), "file-type must be 0 (ASCII) or 1 (binary), got " + quote(tokens_[1]));
      return;
    }
    expect_gmsh_marker(lines_, sink_, "$EndMeshFormat", "the format line");
  }

  bool read_header(std::string_view section, std::uint64_t& blocks,
                   std::uint64_t& total) {
    if (!next_record(section) ||
        !expect_tokens(4, "'numEntityBlocks count minTag maxTag'")) {
      return false;
    }
    const std::uint64_t at = lines_.line_number();
    return parse_count(sink_, at, tokens_[0], lines_.remaining_bytes(), blocks) &&
           parse_count(sink_, at, tokens_[1], lines_.remaining_bytes(), total);
  }

  void read_nodes() override {
    if (binary_) {
      if (binary_reader_.msh41_nodes(lines_.line_number())) {
        expect_gmsh_marker(lines_, sink_, "$EndNodes", "the last node block");
      }
      return;
    }
    std::uint64_t blocks = 0;
    std::uint64_t total = 0;
    if (!read_header("$Nodes", blocks, total)) return;
    mesh_.positions.reserve(total);
    for (std::uint64_t b = 0; b < blocks; ++b) {
      if (!next_record("$Nodes block header") ||
          !expect_tokens(4, "'entityDim entityTag parametric numNodesInBlock'")) {
        return;
      }
      std::uint64_t n = 0;
      std::int64_t parametric = 0;
      if (!parse_i64(tokens_[2], parametric) || (parametric != 0 && parametric != 1)) {
        sink_.fail(lines_.line_number(), "parametric must be 0 or 1, got " + quote(tokens_[2]));
        return;
      }
      if (!parse_count(sink_, lines_.line_number(), tokens_[3], lines_.remaining_bytes(), n)) return;
      if (!check_block_fits(sink_, lines_.line_number(), "node", mesh_.positions.size(), n, total)) return;
      for (std::uint64_t i = 0; i < n; ++i) {
        if (!next_record("$Nodes (node tags)") || !expect_tokens(1, "one node tag")) return;
        std::int64_t id = 0;
        if (!parse_id(sink_, lines_.line_number(), tokens_[0], id)) return;
        if (!ids_.insert(id, static_cast<std::uint32_t>(mesh_.positions.size() + i))) {
          sink_.fail(lines_.line_number(), "duplicate node id " + std::to_string(id));
          return;
        }
      }
      for (std::uint64_t i = 0; i < n; ++i) {
        if (!next_record("$Nodes (coordinates)")) return;
        const std::size_t expected = parametric == 0 ? 3 : 0;
        if ((expected == 3 && tokens_.size() != 3) || tokens_.size() < 3 || tokens_.size() > 6) {
          sink_.fail(lines_.line_number(), "expected 3 coordinates, got " + std::to_string(tokens_.size()) + " values");
          return;
        }
        Vec3 p;
        if (!parse_point(sink_, lines_.line_number(), tokens_.data(), p)) return;
        mesh_.positions.push_back(p);
      }
    }
    if (check_blocks_add_up(sink_, lines_.line_number(), "node", mesh_.positions.size(), total)) {
      expect_gmsh_marker(lines_, sink_, "$EndNodes", "the last node block");
    }
  }

  void read_elements() override {
    if (binary_) {
      if (binary_reader_.msh41_elements(lines_.line_number())) {
        expect_gmsh_marker(lines_, sink_, "$EndElements", "the last element block");
      }
      return;
    }
    std::uint64_t blocks = 0;
    std::uint64_t total = 0;
    if (!read_header("$Elements", blocks, total)) return;
    mesh_.tets.reserve(total);
    std::uint64_t seen = 0;
    for (std::uint64_t b = 0; b < blocks; ++b) {
      if (!next_record("$Elements block header") ||
          !expect_tokens(4, "'entityDim entityTag elementType numElementsInBlock'")) {
        return;
      }
      std::int64_t type = 0;
      std::uint64_t n = 0;
      if (!parse_gmsh_type(sink_, lines_.line_number(), tokens_[2], type)) return;
      if (!parse_count(sink_, lines_.line_number(), tokens_[3], lines_.remaining_bytes(), n)) return;
      if (!check_block_fits(sink_, lines_.line_number(), "element", seen, n, total)) return;
      for (std::uint64_t i = 0; i < n; ++i) {
        if (!next_record("$Elements")) return;
        std::int64_t id = 0;
        if (!parse_id(sink_, lines_.line_number(), tokens_[0], id)) return;
        if (!elements_.add(sink_, lines_.line_number(), type, tokens_.data() + 1, tokens_.size() - 1)) return;
      }
      seen += n;
    }
    if (check_blocks_add_up(sink_, lines_.line_number(), "element", seen, total)) {
      expect_gmsh_marker(lines_, sink_, "$EndElements", "the last element block");
    }
  }
};

// The bounding box of every position ({0,0,0}, {0,0,0} for none), for the volume entity.
std::array<double, 6> bounding_box(const RawMesh& mesh) {
  Vec3 lo{0, 0, 0};
  Vec3 hi{0, 0, 0};
  if (!mesh.positions.empty()) {
    lo = hi = mesh.positions[0];
    for (const Vec3& p : mesh.positions) {
      lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
      hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
    }
  }
  return {lo.x, lo.y, lo.z, hi.x, hi.y, hi.z};
}

// The writers put all `n` nodes (or elements) of a section in one block of the volume entity,
// tagged 1 to n: the section header "numEntityBlocks n minTag maxTag" and, when n > 0, the
// block header "entityDim(3) entityTag(1) <kind> n", kind = parametric flag (0) or element type.
void append_single_block_headers(std::string& out, std::uint64_t n, std::uint64_t kind) {
  const std::uint64_t blocks = n > 0 ? 1 : 0;
  for (std::uint64_t v : {blocks, n, blocks}) {
    append_uint(out, v);
    out += ' ';
  }
  append_uint(out, n);
  out += '\n';
  if (n == 0) return;
  out += "3 1 ";
  append_uint(out, kind);
  out += ' ';
  append_uint(out, n);
  out += '\n';
}

// The same headers in a binary file: sizes are 8 bytes, dimension, tag and kind 4-byte ints.
constexpr auto kBinaryOrder = ByteOrder::kLittle;
void put_int(std::string& out, std::uint64_t v) { store_uint(out, v, 4, kBinaryOrder); }
void put_size(std::string& out, std::uint64_t v) { store_uint(out, v, 8, kBinaryOrder); }

void store_single_block_headers(std::string& out, std::uint64_t n, std::uint64_t kind) {
  const std::uint64_t blocks = n > 0 ? 1 : 0;
  for (std::uint64_t v : {blocks, n, blocks, n}) put_size(out, v);
  if (n == 0) return;
  for (std::uint64_t v : {std::uint64_t{3}, std::uint64_t{1}, kind}) put_int(out, v);
  put_size(out, n);
}

}  // namespace

ReadResult read_msh41(std::string_view text, std::string_view name) {
  return Msh41Reader(text, name).read();
}

std::string format_msh41(const RawMesh& mesh) {
  std::string out;
  out.reserve(256 + mesh.positions.size() * 64 + mesh.tets.size() * 40);
  out += "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";
  // One volume entity (tag 1) holding everything, with its bounding box, as Gmsh expects.
  out += "$Entities\n0 0 0 1\n1 ";
  for (double c : bounding_box(mesh)) {
    append_double(out, c);
    out += ' ';
  }
  out += "0 0\n$EndEntities\n$Nodes\n";
  append_single_block_headers(out, mesh.positions.size(), 0);
  for (std::uint64_t i = 0; i < mesh.positions.size(); ++i) {
    append_uint(out, i + 1);
    out += '\n';
  }
  append_point_lines(out, mesh.positions);
  out += "$EndNodes\n$Elements\n";
  append_single_block_headers(out, mesh.tets.size(), kGmshTet4);
  append_numbered_tets(out, mesh.tets);
  out += "$EndElements\n";
  return out;
}

std::string format_msh41_binary(const RawMesh& mesh) {
  std::string out;
  out.reserve(256 + mesh.positions.size() * 32 + mesh.tets.size() * 40);
  out += "$MeshFormat\n4.1 1 8\n";
  put_int(out, 1);  // the check value that tells readers the byte order
  out += "\n$EndMeshFormat\n$Entities\n";
  // No points, curves or surfaces; one volume (tag 1) with its bounding box, no physical tags
  // and no bounding surfaces.
  for (std::uint64_t n : {0, 0, 0, 1}) put_size(out, n);
  put_int(out, 1);
  for (double c : bounding_box(mesh)) store_f64(out, c, kBinaryOrder);
  put_size(out, 0);
  put_size(out, 0);
  out += "\n$EndEntities\n$Nodes\n";
  store_single_block_headers(out, mesh.positions.size(), 0);
  for (std::uint64_t i = 0; i < mesh.positions.size(); ++i) put_size(out, i + 1);
  for (const Vec3& p : mesh.positions) {
    for (double c : {p.x, p.y, p.z}) store_f64(out, c, kBinaryOrder);
  }
  out += "\n$EndNodes\n$Elements\n";
  store_single_block_headers(out, mesh.tets.size(), kGmshTet4);
  for (std::uint64_t t = 0; t < mesh.tets.size(); ++t) {
    put_size(out, t + 1);
    for (std::uint32_t v : mesh.tets[t]) put_size(out, std::uint64_t{v} + 1);
  }
  out += "\n$EndElements\n";
  return out;
}

}  // namespace tetcut
