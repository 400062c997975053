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

#include "gmsh_binary.hpp"
#include "gmsh_common.hpp"
#include "tetcut/io.hpp"

namespace tetcut {

namespace {

using namespace io_detail;


class Msh41Reader {
 public:
  Msh41Reader(std::string_view text, std::string_view name) : lines_(text), sink_(name) {}

  ReadResult read() {
    std::string_view line;
    bool have_format = false;
    bool have_nodes = false;
    bool have_elements = false;
    while (!sink_.failed() && lines_.next_nonblank(line)) {
      const std::string_view header = trim(line);
      if (header[0] != '$') {
        sink_.fail(lines_.line_number(), "expected a section header such as $Nodes, got " + quote(header));
        break;
      }
      const std::string_view section = header.substr(1);
      if (!have_format && section != "MeshFormat" && section != "Comments") {
        sink_.fail(lines_.line_number(), "expected $MeshFormat first, got " + quote(header));
      } else if (section == "MeshFormat") {
        read_format();
        have_format = true;
      } else if (section == "Nodes") {
        if (have_nodes) sink_.fail(lines_.line_number(), "second $Nodes section");
        else read_nodes();
        have_nodes = true;
      } else if (section == "Elements") {
        if (have_elements) sink_.fail(lines_.line_number(), "second $Elements section");
        else if (!have_nodes) sink_.fail(lines_.line_number(), "$Elements before $Nodes");
        else read_elements();
        have_elements = true;
      } else if (section.substr(0, 3) == "End") {
        sink_.fail(lines_.line_number(), "unexpected " + quote(header) + " outside its section");
      } else {
        skip_gmsh_section(lines_, sink_, section);
      }
    }
    if (!sink_.failed()) {
      if (!have_format) sink_.fail(std::max<std::uint64_t>(1, lines_.line_number()), "empty file: no $MeshFormat section");
      else if (!have_nodes) sink_.fail(lines_.line_number(), "missing $Nodes section");
      else if (!have_elements) sink_.fail(lines_.line_number(), "missing $Elements section");
    }
    std::vector<std::string> notices;
    elements_.emit_notices(notices);
    return make_result(sink_, std::move(mesh_), std::move(notices), &elements_.ignored);
  }

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

  void read_format() {
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

  void read_nodes() {
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
    std::vector<std::int64_t> block_ids;
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
      if (mesh_.positions.size() + n > total) {
        sink_.fail(lines_.line_number(), "node blocks hold more than the " + std::to_string(total) + " nodes declared");
        return;
      }
      block_ids.clear();
      block_ids.reserve(n);
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
        const std::uint64_t at = lines_.line_number();
        if (!parse_coordinate(sink_, at, tokens_[0], p.x) || !parse_coordinate(sink_, at, tokens_[1], p.y) ||
            !parse_coordinate(sink_, at, tokens_[2], p.z)) {
          return;
        }
        mesh_.positions.push_back(p);
      }
    }
    if (mesh_.positions.size() != total) {
      sink_.fail(lines_.line_number(), "node blocks hold " + std::to_string(mesh_.positions.size()) +
                                           " nodes, the header declares " + std::to_string(total));
      return;
    }
    expect_gmsh_marker(lines_, sink_, "$EndNodes", "the last node block");
  }

  void read_elements() {
    elements_.nodes = &ids_;
    elements_.tets = &mesh_.tets;
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
      if (!parse_i64(tokens_[2], type)) {
        sink_.fail(lines_.line_number(), "expected an element type, got " + quote(tokens_[2]));
        return;
      }
      if (!parse_count(sink_, lines_.line_number(), tokens_[3], lines_.remaining_bytes(), n)) return;
      if (seen + n > total) {
        sink_.fail(lines_.line_number(), "element blocks hold more than the " + std::to_string(total) + " elements declared");
        return;
      }
      for (std::uint64_t i = 0; i < n; ++i) {
        if (!next_record("$Elements")) return;
        std::int64_t id = 0;
        if (!parse_id(sink_, lines_.line_number(), tokens_[0], id)) return;
        if (!elements_.add(sink_, lines_.line_number(), type, tokens_.data() + 1, tokens_.size() - 1)) return;
      }
      seen += n;
    }
    if (seen != total) {
      sink_.fail(lines_.line_number(), "element blocks hold " + std::to_string(seen) +
                                           " elements, the header declares " + std::to_string(total));
      return;
    }
    expect_gmsh_marker(lines_, sink_, "$EndElements", "the last element block");
  }

  LineReader lines_;
  ErrorSink sink_;
  RawMesh mesh_;
  NodeIdMap ids_;
  GmshElementSink elements_;
  std::vector<std::string_view> tokens_;
  GmshBinaryReader binary_reader_{lines_, sink_, mesh_, ids_, elements_};
  bool binary_ = false;
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
  const std::uint64_t nv = mesh.positions.size();
  out += nv > 0 ? "1 " : "0 ";
  append_uint(out, nv);
  out += nv > 0 ? " 1 " : " 0 ";
  append_uint(out, nv);
  out += '\n';
  if (nv > 0) {
    out += "3 1 0 ";
    append_uint(out, nv);
    out += '\n';
    for (std::uint64_t i = 0; i < nv; ++i) {
      append_uint(out, i + 1);
      out += '\n';
    }
    for (const Vec3& p : mesh.positions) {
      append_point(out, p);
      out += '\n';
    }
  }
  out += "$EndNodes\n$Elements\n";
  const std::uint64_t nt = mesh.tets.size();
  out += nt > 0 ? "1 " : "0 ";
  append_uint(out, nt);
  out += nt > 0 ? " 1 " : " 0 ";
  append_uint(out, nt);
  out += '\n';
  if (nt > 0) {
    out += "3 1 4 ";
    append_uint(out, nt);
    out += '\n';
    for (std::uint64_t t = 0; t < nt; ++t) {
      append_uint(out, t + 1);
      for (std::uint32_t v : mesh.tets[t]) {
        out += ' ';
        append_uint(out, static_cast<std::uint64_t>(v) + 1);
      }
      out += '\n';
    }
  }
  out += "$EndElements\n";
  return out;
}

std::string format_msh41_binary(const RawMesh& mesh) {
  constexpr auto kOrder = ByteOrder::kLittle;
  const auto put_int = [](std::string& out, std::uint64_t v) { store_uint(out, v, 4, kOrder); };
  const auto put_size = [](std::string& out, std::uint64_t v) { store_uint(out, v, 8, kOrder); };
  std::string out;
  out.reserve(256 + mesh.positions.size() * 32 + mesh.tets.size() * 40);
  out += "$MeshFormat\n4.1 1 8\n";
  put_int(out, 1);  // the check value that tells readers the byte order
  out += "\n$EndMeshFormat\n$Entities\n";
  // No points, curves or surfaces; one volume (tag 1) with its bounding box, no physical tags
  // and no bounding surfaces.
  for (std::uint64_t n : {0, 0, 0, 1}) put_size(out, n);
  put_int(out, 1);
  for (double c : bounding_box(mesh)) store_f64(out, c, kOrder);
  put_size(out, 0);
  put_size(out, 0);
  out += "\n$EndEntities\n$Nodes\n";
  const std::uint64_t nv = mesh.positions.size();
  const std::uint64_t node_blocks = nv > 0 ? 1 : 0;
  for (std::uint64_t v : {node_blocks, nv, node_blocks, nv}) put_size(out, v);
  if (nv > 0) {
    for (std::uint64_t v : {3, 1, 0}) put_int(out, v);
    put_size(out, nv);
    for (std::uint64_t i = 0; i < nv; ++i) put_size(out, i + 1);
    for (const Vec3& p : mesh.positions) {
      for (double c : {p.x, p.y, p.z}) store_f64(out, c, kOrder);
    }
  }
  out += "\n$EndNodes\n$Elements\n";
  const std::uint64_t nt = mesh.tets.size();
  const std::uint64_t element_blocks = nt > 0 ? 1 : 0;
  for (std::uint64_t v : {element_blocks, nt, element_blocks, nt}) put_size(out, v);
  if (nt > 0) {
    for (std::uint64_t v : {3, 1, kGmshTet4}) put_int(out, v);
    put_size(out, nt);
    for (std::uint64_t t = 0; t < nt; ++t) {
      put_size(out, t + 1);
      for (std::uint32_t v : mesh.tets[t]) put_size(out, std::uint64_t{v} + 1);
    }
  }
  out += "\n$EndElements\n";
  return out;
}

}  // namespace tetcut
