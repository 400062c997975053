// TetGen .node / .ele. '#' starts a comment.
//   .node: "numPoints 3 numAttributes numBoundaryMarkers(0|1)", then
//          "id x y z [attributes...] [marker]" (ids start at 0 or 1, as the file chooses)
//   .ele:  "numTets nodesPerTet(4|10) numAttributes", then "id n1 .. nk [attributes...]"
// The .ele refers to the ids of the .node file, mapped like Gmsh ids.
// Labels (RawMesh::labels): TetGen's -A switch gives each tet a region attribute, "an integer in
// the last column" of the .ele (TetGen's .ele format page, wias-berlin.de/software/tetgen). So the
// last attribute column is the label and any others are skipped with a notice. tetgenio keeps
// attributes as REALs (tetgen.h), so "3.0" reads as 3, while 2.5 or -1 is refused. An .ele
// without attributes reads unlabelled. A labelled mesh is written with one attribute, its label;
// an unlabelled one as before, with none.
#include <algorithm>
#include <cmath>
#include <string>
#include <string_view>

#include "tetcut/io.hpp"
#include "text_reader.hpp"

namespace tetcut {

namespace {

using namespace io_detail;

bool small_count(ErrorSink& sink, std::uint64_t line, std::string_view token, std::uint64_t max,
                 std::string_view what, std::uint64_t& value) {
  if (!parse_u64(token, value) || value > max) {
    return sink.fail(line, "bad " + std::string(what) + " " + quote(token));
  }
  return true;
}

// Both files open with "COUNT [field...]" (`what` names them, at most `max_values`): the number of
// records that follow, bounded by what the file can hold, and fields that header_field() reads.
bool read_header(LineReader& lines, ErrorSink& sink, std::vector<std::string_view>& tokens, std::size_t max_values,
                 std::string_view what, std::uint64_t& count) {
  if (!next_tokens(lines, tokens, '#')) return sink.fail(lines.line_number(), "empty file: missing " + std::string(what));
  if (tokens.empty() || tokens.size() > max_values) {
    return sink.fail(lines.line_number(), "expected " + std::string(what) + ", got " +
                                              std::to_string(tokens.size()) + " values");
  }
  return parse_count(sink, lines.line_number(), tokens[0], lines.remaining_bytes(), count);
}

// The header's field `i`, at most `max`, if the header has it; else `value` keeps its default.
bool header_field(ErrorSink& sink, std::uint64_t line, const std::vector<std::string_view>& tokens, std::size_t i,
                  std::uint64_t max, std::string_view what, std::uint64_t& value) {
  return tokens.size() <= i || small_count(sink, line, tokens[i], max, what, value);
}

// Record `i` of the `count` records (`noun`) the header declared, split into `tokens`.
bool next_record(LineReader& lines, ErrorSink& sink, std::vector<std::string_view>& tokens, std::uint64_t i,
                 std::uint64_t count, std::string_view noun) {
  if (next_tokens(lines, tokens, '#')) return true;
  return sink.fail(lines.line_number(), "unexpected end of file: expected " + std::to_string(count) + " " +
                                            std::string(noun) + ", got " + std::to_string(i));
}

// Only comments may follow the declared records.
bool expect_no_more_records(LineReader& lines, ErrorSink& sink, std::vector<std::string_view>& tokens,
                            std::uint64_t count, std::string_view noun) {
  if (!next_tokens(lines, tokens, '#')) return true;
  return sink.fail(lines.line_number(),
                   "unexpected data after the " + std::to_string(count) + " declared " + std::string(noun));
}

bool read_node_file(std::string_view text, ErrorSink& sink, NodeIdMap& ids, RawMesh& mesh) {
  LineReader lines(text);
  std::vector<std::string_view> tokens;
  std::uint64_t count = 0;
  if (!read_header(lines, sink, tokens, 4, "'numPoints dimension numAttributes numMarkers'", count)) return false;
  const std::uint64_t at = lines.line_number();
  std::uint64_t dim = 3;
  std::uint64_t attributes = 0;
  std::uint64_t markers = 0;
  if (!header_field(sink, at, tokens, 1, 3, "dimension", dim)) return false;
  if (dim != 3) return sink.fail(at, "only 3D points are supported, got dimension " + std::to_string(dim));
  if (!header_field(sink, at, tokens, 2, 1000, "number of attributes", attributes) ||
      !header_field(sink, at, tokens, 3, 1, "number of boundary markers", markers)) {
    return false;
  }
  const std::size_t expected = 4 + attributes + markers;
  mesh.positions.reserve(count);
  for (std::uint64_t i = 0; i < count; ++i) {
    if (!next_record(lines, sink, tokens, i, count, "points")) return false;
    const std::uint64_t line = lines.line_number();
    if (tokens.size() != expected) {
      return sink.fail(line, "expected " + std::to_string(expected) + " values for a point (id, x, y, z, " +
                                 std::to_string(attributes) + " attributes, " + std::to_string(markers) +
                                 " markers), got " + std::to_string(tokens.size()));
    }
    std::int64_t id = 0;
    Vec3 p;
    if (!parse_id(sink, line, tokens[0], id) || !parse_point(sink, line, tokens.data() + 1, p)) return false;
    if (!ids.insert(id, static_cast<std::uint32_t>(mesh.positions.size()))) {
      return sink.fail(line, "duplicate point id " + std::to_string(id));
    }
    mesh.positions.push_back(p);
  }
  return expect_no_more_records(lines, sink, tokens, count, "points");
}

// A region attribute as a label: an integer, or a real with an integer value (TetGen's
// attributes are REALs), in [0, kMaxTetLabel].
bool parse_region_attribute(ErrorSink& sink, std::uint64_t line, std::string_view token, std::uint32_t& label) {
  constexpr std::string_view kWhat = "region attribute";
  std::int64_t integer = 0;
  if (parse_i64(token, integer)) return check_label(sink, line, integer, kWhat, label);
  double real = 0;
  if (!parse_double(token, real) || !std::isfinite(real) || real != std::trunc(real) || real < 0 ||
      real > double{kMaxTetLabel}) {
    return sink.fail(line, std::string(kWhat) + " " + quote(token) + " is not a label (an integer in 0.." +
                               std::to_string(kMaxTetLabel) + ")");
  }
  label = static_cast<std::uint32_t>(real);
  return true;
}

bool read_ele_file(std::string_view text, ErrorSink& sink, const NodeIdMap& ids, RawMesh& mesh,
                   std::vector<std::string>& notices) {
  LineReader lines(text);
  std::vector<std::string_view> tokens;
  std::uint64_t count = 0;
  if (!read_header(lines, sink, tokens, 3, "'numTetrahedra nodesPerTet numAttributes'", count)) return false;
  const std::uint64_t at = lines.line_number();
  std::uint64_t per_tet = 4;
  std::uint64_t attributes = 0;
  if (!header_field(sink, at, tokens, 1, 10, "nodes per tetrahedron", per_tet)) return false;
  if (per_tet != 4 && per_tet != 10) {
    return sink.fail(at, "nodes per tetrahedron must be 4 or 10, got " + std::to_string(per_tet));
  }
  if (!header_field(sink, at, tokens, 2, 1000, "number of attributes", attributes)) return false;
  const std::size_t expected = 1 + per_tet + attributes;
  mesh.tets.reserve(count);
  if (attributes > 0) mesh.labels.reserve(count);
  for (std::uint64_t i = 0; i < count; ++i) {
    if (!next_record(lines, sink, tokens, i, count, "tetrahedra")) return false;
    const std::uint64_t line = lines.line_number();
    if (tokens.size() != expected) {
      return sink.fail(line, "expected " + std::to_string(per_tet) + " node ids for a tetrahedron (after its id, with " +
                                 std::to_string(attributes) + " attributes), got " +
                                 std::to_string(tokens.size() - 1 - std::min<std::size_t>(tokens.size() - 1, attributes)));
    }
    std::int64_t id = 0;
    if (!parse_id(sink, line, tokens[0], id)) return false;
    std::array<std::uint32_t, 4> tet{};
    // TetGen's 10-node tets list the 4 corners first.
    for (std::size_t k = 0; k < per_tet; ++k) {
      std::int64_t node = 0;
      if (!parse_id(sink, line, tokens[1 + k], node)) return false;
      const std::uint32_t index = ids.find(node);
      if (index == NodeIdMap::kNone) return sink.fail(line, "node id " + std::to_string(node) + " not defined");
      if (k < 4) tet[k] = index;
    }
    if (attributes > 0) {
      std::uint32_t label = 0;
      if (!parse_region_attribute(sink, line, tokens[expected - 1], label)) return false;
      mesh.labels.push_back(label);
    }
    mesh.tets.push_back(tet);
  }
  if (!expect_no_more_records(lines, sink, tokens, count, "tetrahedra")) return false;
  if (per_tet == 10 && count > 0) {
    notices.push_back("read " + std::to_string(count) + " 10-node tetrahedra as their 4 corner nodes");
  }
  if (attributes > 1 && count > 0) {
    notices.push_back("read the last of the " + std::to_string(attributes) +
                      " attributes of each tetrahedron as its label (TetGen's region attribute); ignored the others");
  }
  return true;
}

}  // namespace

ReadResult read_tetgen(std::string_view node_text, std::string_view node_name,
                       std::string_view ele_text, std::string_view ele_name) {
  RawMesh mesh;
  NodeIdMap ids;
  std::vector<std::string> notices;
  ErrorSink node_sink(node_name);
  if (!read_node_file(node_text, node_sink, ids, mesh)) return make_result(node_sink, std::move(mesh), std::move(notices));
  ErrorSink ele_sink(ele_name);
  read_ele_file(ele_text, ele_sink, ids, mesh, notices);
  return make_result(ele_sink, std::move(mesh), std::move(notices));
}

namespace {

// Both files have one shape: "COUNT REST-OF-HEADER", the rows numbered from 1 (as TetGen writes
// by default), a closing comment.
template <class Rows, class AppendRows>
std::string format_tetgen_file(const Rows& rows, std::string_view header_rest, std::size_t bytes_per_row,
                               AppendRows append_rows) {
  std::string out;
  out.reserve(64 + rows.size() * bytes_per_row);
  append_uint(out, rows.size());
  out += header_rest;
  append_rows(out, rows);
  out += "# written by tetcut\n";
  return out;
}

}  // namespace

std::string format_tetgen_node(const RawMesh& mesh) {
  return format_tetgen_file(mesh.positions, " 3 0 0\n", 64,
                            [](std::string& out, const auto& rows) { append_numbered_points(out, rows); });
}

std::string format_tetgen_ele(const RawMesh& mesh) {
  // A labelled mesh gets one attribute, the region: what TetGen -A writes and -rA reads back.
  return format_tetgen_file(mesh.tets, mesh.labelled() ? " 4 1\n" : " 4 0\n", 56,
                            [&mesh](std::string& out, const auto& rows) { append_numbered_tets(out, rows, {}, mesh.labels); });
}

}  // namespace tetcut
