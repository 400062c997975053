// Gmsh MSH 2.2, ASCII or binary. Line based: "$Nodes" count, "id x y z" lines, "$EndNodes";
// "$Elements" count, "id type ntags tag... node..." lines, "$EndElements"; in a binary file the
// records between count and marker are raw (gmsh_binary.hpp). Node ids are arbitrary (mapped);
// tags (physical, elementary, partitions) are skipped; unknown sections ($Comments,
// $PhysicalNames, $NodeData, ...) are skipped to their $End marker.
#include <algorithm>
#include <string>

#include "gmsh_binary.hpp"
#include "gmsh_common.hpp"
#include "tetcut/io.hpp"

namespace tetcut {

namespace {

using namespace io_detail;


class Msh22Reader {
 public:
  Msh22Reader(std::string_view text, std::string_view name) : lines_(text), sink_(name) {}

  ReadResult read() {
    std::string_view line;
    bool have_format = false;
    bool have_nodes = false;
    bool have_elements = false;
    while (!sink_.failed() && lines_.next_nonblank(line)) {
      const std::string_view header = trim(line);
      if (header.empty() || header[0] != '$') {
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
  void read_format() {
    std::string_view line;
    if (!lines_.next_nonblank(line)) {
      sink_.fail(lines_.line_number(), "unexpected end of file in $MeshFormat");
      return;
    }
    split_tokens(line, tokens_);
    if (tokens_.size() != 3) {
      sink_.fail(lines_.line_number(), "expected 'version file-type data-size', got " +
                                           std::to_string(tokens_.size()) + " values");
      return;
    }
    double version = 0;
    if (!parse_double(tokens_[0], version) || version < 2.0 || version >= 3.0) {
      sink_.fail(lines_.line_number(), "unsupported MSH version " + quote(tokens_[0]) + " (this reader reads 2.x)");
      return;
    }
    std::int64_t file_type = 0;
    if (!parse_i64(tokens_[1], file_type) || (file_type != 0 && file_type != 1)) {
      sink_.fail(lines_.line_number(), "file-type must be 0 (ASCII) or 1 (binary), got " + quote(tokens_[1]));
      return;
    }
    if (file_type == 1) {
      std::int64_t data_size = 0;
      if (!parse_i64(tokens_[2], data_size) || data_size != 8) {
        sink_.fail(lines_.line_number(), "data-size must be 8 (bytes of a double), got " + quote(tokens_[2]));
        return;
      }
      binary_ = true;
      if (!binary_reader_.read_check_value(8)) return;
    }
    expect_gmsh_marker(lines_, sink_, "$EndMeshFormat", "the format line");
  }

  void read_nodes() {
    std::string_view line;
    if (!lines_.next_nonblank(line)) {
      sink_.fail(lines_.line_number(), "unexpected end of file: missing node count in $Nodes");
      return;
    }
    split_tokens(line, tokens_);
    std::uint64_t count = 0;
    if (tokens_.size() != 1) {
      sink_.fail(lines_.line_number(), "expected the number of nodes, got " + quote(trim(line)));
      return;
    }
    if (!parse_count(sink_, lines_.line_number(), tokens_[0], lines_.remaining_bytes(), count)) return;
    if (binary_) {
      if (binary_reader_.msh22_nodes(count, lines_.line_number())) {
        expect_gmsh_marker(lines_, sink_, "$EndNodes", "the last node");
      }
      return;
    }
    mesh_.positions.reserve(count);
    for (std::uint64_t i = 0; i < count; ++i) {
      if (!lines_.next_nonblank(line)) {
        sink_.fail(lines_.line_number(), "unexpected end of file in $Nodes: expected " +
                                             std::to_string(count) + " nodes, got " + std::to_string(i));
        return;
      }
      split_tokens(line, tokens_);
      if (!tokens_.empty() && tokens_[0].substr(0, 1) == "$") {
        sink_.fail(lines_.line_number(), "section ended after " + std::to_string(i) + " of " +
                                             std::to_string(count) + " nodes");
        return;
      }
      if (!add_gmsh_node(sink_, lines_.line_number(), tokens_, ids_, mesh_.positions)) return;
    }
    expect_gmsh_marker(lines_, sink_, "$EndNodes", "the last node");
  }

  void read_elements() {
    std::string_view line;
    if (!lines_.next_nonblank(line)) {
      sink_.fail(lines_.line_number(), "unexpected end of file: missing element count in $Elements");
      return;
    }
    split_tokens(line, tokens_);
    std::uint64_t count = 0;
    if (tokens_.size() != 1) {
      sink_.fail(lines_.line_number(), "expected the number of elements, got " + quote(trim(line)));
      return;
    }
    if (!parse_count(sink_, lines_.line_number(), tokens_[0], lines_.remaining_bytes(), count)) return;
    mesh_.tets.reserve(count);
    elements_.nodes = &ids_;
    elements_.tets = &mesh_.tets;
    if (binary_) {
      if (binary_reader_.msh22_elements(count, lines_.line_number())) {
        expect_gmsh_marker(lines_, sink_, "$EndElements", "the last element");
      }
      return;
    }
    for (std::uint64_t i = 0; i < count; ++i) {
      if (!lines_.next_nonblank(line)) {
        sink_.fail(lines_.line_number(), "unexpected end of file in $Elements: expected " +
                                             std::to_string(count) + " elements, got " + std::to_string(i));
        return;
      }
      const std::uint64_t at = lines_.line_number();
      split_tokens(line, tokens_);
      if (!tokens_.empty() && tokens_[0].substr(0, 1) == "$") {
        sink_.fail(at, "section ended after " + std::to_string(i) + " of " + std::to_string(count) + " elements");
        return;
      }
      if (tokens_.size() < 3) {
        sink_.fail(at, "expected 'id type num-tags ...', got " + std::to_string(tokens_.size()) + " values");
        return;
      }
      std::int64_t id = 0;
      std::int64_t type = 0;
      std::int64_t num_tags = 0;
      if (!parse_id(sink_, at, tokens_[0], id)) return;
      if (!parse_i64(tokens_[1], type)) {
        sink_.fail(at, "expected an element type, got " + quote(tokens_[1]));
        return;
      }
      if (!parse_i64(tokens_[2], num_tags) || num_tags < 0 ||
          static_cast<std::uint64_t>(num_tags) > tokens_.size() - 3) {
        sink_.fail(at, "bad number of tags " + quote(tokens_[2]) + " for a line of " +
                           std::to_string(tokens_.size()) + " values");
        return;
      }
      const std::size_t first_node = 3 + static_cast<std::size_t>(num_tags);
      if (!elements_.add(sink_, at, type, tokens_.data() + first_node, tokens_.size() - first_node)) return;
    }
    expect_gmsh_marker(lines_, sink_, "$EndElements", "the last element");
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

}  // namespace

ReadResult read_msh22(std::string_view text, std::string_view name) {
  return Msh22Reader(text, name).read();
}

std::string format_msh22(const RawMesh& mesh) {
  std::string out;
  out.reserve(64 + mesh.positions.size() * 64 + mesh.tets.size() * 48);
  out += "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n";
  append_uint(out, mesh.positions.size());
  out += '\n';
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    const Vec3& p = mesh.positions[i];
    append_uint(out, i + 1);
    out += ' ';
    append_point(out, p);
    out += '\n';
  }
  out += "$EndNodes\n$Elements\n";
  append_uint(out, mesh.tets.size());
  out += '\n';
  // Every tet in physical group 1 and elementary entity 1, as Gmsh writes a single volume.
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    append_uint(out, t + 1);
    out += " 4 2 1 1";
    for (std::uint32_t v : mesh.tets[t]) {
      out += ' ';
      append_uint(out, static_cast<std::uint64_t>(v) + 1);
    }
    out += '\n';
  }
  out += "$EndElements\n";
  return out;
}

std::string format_msh22_binary(const RawMesh& mesh) {
  constexpr auto kOrder = ByteOrder::kLittle;
  std::string out;
  out.reserve(128 + mesh.positions.size() * 28 + mesh.tets.size() * 28);
  out += "$MeshFormat\n2.2 1 8\n";
  store_uint(out, 1, 4, kOrder);  // the check value that tells readers the byte order
  out += "\n$EndMeshFormat\n$Nodes\n";
  append_uint(out, mesh.positions.size());
  out += '\n';
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    store_uint(out, i + 1, 4, kOrder);
    for (double c : {mesh.positions[i].x, mesh.positions[i].y, mesh.positions[i].z}) store_f64(out, c, kOrder);
  }
  out += "\n$EndNodes\n$Elements\n";
  append_uint(out, mesh.tets.size());
  out += '\n';
  if (!mesh.tets.empty()) {
    // One block: type 4, every tet, 2 tags (physical and elementary entity 1, as in ASCII).
    for (std::uint64_t v : {std::uint64_t{kGmshTet4}, std::uint64_t{mesh.tets.size()}, std::uint64_t{2}}) {
      store_uint(out, v, 4, kOrder);
    }
    for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
      for (std::uint64_t v : {std::uint64_t{t + 1}, std::uint64_t{1}, std::uint64_t{1}}) store_uint(out, v, 4, kOrder);
      for (std::uint32_t v : mesh.tets[t]) store_uint(out, std::uint64_t{v} + 1, 4, kOrder);
    }
  }
  out += "\n$EndElements\n";
  return out;
}

}  // namespace tetcut
