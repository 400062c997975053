// Gmsh MSH 2.2, ASCII or binary. Line based: "$Nodes" count, "id x y z" lines, "$EndNodes";
// "$Elements" count, "id type ntags tag... node..." lines, "$EndElements"; in a binary file the
// records between count and marker are raw (gmsh_binary.hpp). Node ids are arbitrary (mapped);
// an element's first tag, its physical group, is its tet's label (RawMesh::labels; the others,
// elementary entity and partitions, are skipped); a file whose tets have no tags is unlabelled.
// Written back: physical tag and elementary entity both the label (1 when unlabelled). Unknown sections ($Comments,
// $PhysicalNames, $NodeData, ...) are skipped to their $End marker.
#include <string>

#include "gmsh_sections.hpp"
#include "tetcut/io.hpp"

namespace tetcut {

namespace {

using namespace io_detail;

class Msh22Reader : public GmshSectionReader {
 public:
  Msh22Reader(std::string_view text, std::string_view name) : GmshSectionReader(text, name) {}

 private:
  void read_format() override {
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

  void read_nodes() override {
    std::uint64_t count = 0;
    if (!read_count_line("node count in $Nodes", "the number of nodes", count)) return;
    if (binary_) {
      if (binary_reader_.msh22_nodes(count, lines_.line_number())) {
        expect_gmsh_marker(lines_, sink_, "$EndNodes", "the last node");
      }
      return;
    }
    read_node_lines(count, "$Nodes", "nodes", "$EndNodes");
  }

  void read_elements() override {
    std::uint64_t count = 0;
    if (!read_count_line("element count in $Elements", "the number of elements", count)) return;
    mesh_.tets.reserve(count);
    if (binary_) {
      if (binary_reader_.msh22_elements(count, lines_.line_number())) {
        expect_gmsh_marker(lines_, sink_, "$EndElements", "the last element");
      }
      return;
    }
    for (std::uint64_t i = 0; i < count; ++i) {
      if (!next_entry("$Elements", "elements", i, count)) return;
      const std::uint64_t at = lines_.line_number();
      if (tokens_.size() < 3) {
        sink_.fail(at, "expected 'id type num-tags ...', got " + std::to_string(tokens_.size()) + " values");
        return;
      }
      std::int64_t id = 0;
      std::int64_t type = 0;
      std::int64_t num_tags = 0;
      if (!parse_id(sink_, at, tokens_[0], id) || !parse_gmsh_type(sink_, at, tokens_[1], type)) return;
      if (!parse_i64(tokens_[2], num_tags) || num_tags < 0 ||
          static_cast<std::uint64_t>(num_tags) > tokens_.size() - 3) {
        sink_.fail(at, "bad number of tags " + quote(tokens_[2]) + " for a line of " +
                           std::to_string(tokens_.size()) + " values");
        return;
      }
      elements_.label.reset();
      if (num_tags > 0) {
        std::uint32_t label = 0;
        if (!parse_label(sink_, at, tokens_[3], "physical tag", label)) return;
        elements_.label = label;
      }
      const std::size_t first_node = 3 + static_cast<std::size_t>(num_tags);
      if (!elements_.add(sink_, at, type, tokens_.data() + first_node, tokens_.size() - first_node)) return;
    }
    expect_gmsh_marker(lines_, sink_, "$EndElements", "the last element");
  }
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
  append_numbered_points(out, mesh.positions);
  out += "$EndNodes\n$Elements\n";
  append_uint(out, mesh.tets.size());
  out += '\n';
  if (mesh.labelled()) {
    // Physical group and elementary entity both the label: one volume per region, as Gmsh
    // writes a multi-region mesh.
    for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
      append_uint(out, t + 1);
      out += " 4 2 ";
      append_uint(out, mesh.labels[t]);
      out += ' ';
      append_uint(out, mesh.labels[t]);
      for (std::uint32_t v : mesh.tets[t]) {
        out += ' ';
        append_uint(out, std::uint64_t{v} + 1);
      }
      out += '\n';
    }
  } else {
    // Every tet in physical group 1 and elementary entity 1, as Gmsh writes a single volume.
    append_numbered_tets(out, mesh.tets, " 4 2 1 1");
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
    // One block: type 4, every tet, 2 tags (physical and elementary entity, as in ASCII).
    for (std::uint64_t v : {std::uint64_t{kGmshTet4}, std::uint64_t{mesh.tets.size()}, std::uint64_t{2}}) {
      store_uint(out, v, 4, kOrder);
    }
    for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
      const std::uint64_t label = label_or(mesh, t, 1);
      for (std::uint64_t v : {std::uint64_t{t + 1}, label, label}) store_uint(out, v, 4, kOrder);
      for (std::uint32_t v : mesh.tets[t]) store_uint(out, std::uint64_t{v} + 1, 4, kOrder);
    }
  }
  out += "\n$EndElements\n";
  return out;
}

}  // namespace tetcut
