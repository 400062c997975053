#include "gmsh_common.hpp"

#include <string>

namespace tetcut::io_detail {

std::string_view gmsh_type_name(std::int64_t type) {
  switch (type) {
    case 1: return "line";
    case 2: return "triangle";
    case 3: return "quadrangle";
    case 4: return "tetrahedron";
    case 5: return "hexahedron";
    case 6: return "prism";
    case 7: return "pyramid";
    case 8: return "second-order line";
    case 9: return "second-order triangle";
    case 10: return "second-order quadrangle";
    case 11: return "second-order tetrahedron";
    case 12: return "second-order hexahedron";
    case 13: return "second-order prism";
    case 14: return "second-order pyramid";
    case 15: return "point";
    case 16: return "8-node quadrangle";
    case 17: return "20-node hexahedron";
    case 18: return "15-node prism";
    case 19: return "13-node pyramid";
    default: return "";
  }
}

std::string gmsh_ignored_kind(std::int64_t type) {
  std::string kind = "elements of type " + std::to_string(type);
  const std::string_view name = gmsh_type_name(type);
  if (!name.empty()) {
    kind += " (";
    kind += name;
    kind += ")";
  }
  return kind;
}

std::size_t gmsh_type_nodes(std::int64_t type) {
  // Gmsh's reference manual, "MSH file format": element types and their node counts.
  switch (type) {
    case 1: return 2;   case 2: return 3;   case 3: return 4;   case 4: return 4;
    case 5: return 8;   case 6: return 6;   case 7: return 5;   case 8: return 3;
    case 9: return 6;   case 10: return 9;  case 11: return 10; case 12: return 27;
    case 13: return 18; case 14: return 14; case 15: return 1;  case 16: return 8;
    case 17: return 20; case 18: return 15; case 19: return 13; case 20: return 9;
    case 21: return 10; case 22: return 12; case 23: return 15; case 24: return 15;
    case 25: return 21; case 26: return 4;  case 27: return 5;  case 28: return 6;
    case 29: return 20; case 30: return 35; case 31: return 56; case 92: return 64;
    case 93: return 125;
    default: return 0;
  }
}

bool skip_gmsh_section(LineReader& lines, ErrorSink& sink, std::string_view name) {
  const std::uint64_t start = lines.line_number();
  const std::string end = "$End" + std::string(name);
  std::string_view line;
  while (lines.next(line)) {
    if (trim(line) == end) return true;
  }
  return sink.fail(start, "section $" + std::string(name) + " has no " + end);
}

bool expect_gmsh_marker(LineReader& lines, ErrorSink& sink, std::string_view marker,
                        std::string_view what) {
  std::string_view line;
  if (!lines.next_nonblank(line)) {
    return sink.fail(lines.line_number(),
                     "unexpected end of file: missing " + std::string(marker) + " after " +
                         std::string(what));
  }
  if (trim(line) != marker) {
    return sink.fail(lines.line_number(), "expected " + std::string(marker) + " after " +
                                              std::string(what) + ", got " + quote(trim(line)));
  }
  return true;
}

bool GmshElementSink::add(ErrorSink& sink, std::uint64_t line, std::int64_t type,
                          const std::string_view* node_tokens, std::size_t num_nodes) {
  std::size_t expected = 0;
  if (type == kGmshTet4) {
    expected = 4;
  } else if (type == kGmshTet10) {
    expected = 10;
  } else {
    ignore(type, 1);
    return true;
  }
  if (num_nodes != expected) {
    return sink.fail(line, "expected " + std::to_string(expected) + " node ids for a " +
                               std::string(gmsh_type_name(type)) + ", got " +
                               std::to_string(num_nodes));
  }
  std::array<std::uint32_t, 4> tet{};
  for (std::size_t k = 0; k < expected; ++k) {
    std::int64_t id = 0;
    if (!parse_id(sink, line, node_tokens[k], id) || !add_node(sink, line, id, k, tet)) return false;
  }
  push_tet(type, tet);
  return true;
}

bool GmshElementSink::add_node(ErrorSink& sink, std::uint64_t line, std::int64_t id, std::size_t k,
                               std::array<std::uint32_t, 4>& tet) const {
  const std::uint32_t index = nodes->find(id);
  if (index == NodeIdMap::kNone) return sink.fail(line, "node id " + std::to_string(id) + " not defined");
  if (k < 4) tet[k] = index;
  return true;
}

void GmshElementSink::push_tet(std::int64_t type, const std::array<std::uint32_t, 4>& tet) {
  if (type == kGmshTet10) ++second_order_tets;
  tets->push_back(tet);
  labels->push_back(label.value_or(0));
  labelled = labelled || label.has_value();
}

void GmshElementSink::ignore(std::int64_t type, std::uint64_t n) {
  const std::string_view name = gmsh_type_name(type);
  ignored.add(gmsh_ignored_kind(type), n,
              name.empty() ? "element of Gmsh type " + std::to_string(type) : std::string(name));
}

bool GmshElementSink::add_ids(ErrorSink& sink, std::uint64_t line, std::int64_t type, const std::int64_t* ids,
                              std::size_t num_nodes) {
  if (type != kGmshTet4 && type != kGmshTet10) {
    ignore(type, 1);
    return true;
  }
  std::array<std::uint32_t, 4> tet{};
  for (std::size_t k = 0; k < num_nodes; ++k)
    if (!add_node(sink, line, ids[k], k, tet)) return false;
  push_tet(type, tet);
  return true;
}

void GmshElementSink::emit_notices(std::vector<std::string>& notices) const {
  if (second_order_tets > 0) {
    notices.push_back("read " + std::to_string(second_order_tets) +
                      " second-order tetrahedra (type 11) as their 4 corner nodes");
  }
  ignored.emit(notices);
}

bool add_gmsh_node(ErrorSink& sink, std::uint64_t line, const std::vector<std::string_view>& tokens,
                   NodeIdMap& ids, std::vector<Vec3>& positions) {
  if (tokens.size() != 4) {
    return sink.fail(line, "expected a node id and 3 coordinates, got " +
                               std::to_string(tokens.size()) + " values");
  }
  std::int64_t id = 0;
  Vec3 p;
  if (!parse_id(sink, line, tokens[0], id) || !parse_point(sink, line, tokens.data() + 1, p)) return false;
  if (!ids.insert(id, static_cast<std::uint32_t>(positions.size()))) {
    return sink.fail(line, "duplicate node id " + std::to_string(id));
  }
  positions.push_back(p);
  return true;
}

bool parse_gmsh_type(ErrorSink& sink, std::uint64_t line, std::string_view token, std::int64_t& type) {
  if (!parse_i64(token, type)) return sink.fail(line, "expected an element type, got " + quote(token));
  return true;
}

bool check_block_fits(ErrorSink& sink, std::uint64_t line, std::string_view noun, std::uint64_t seen,
                      std::uint64_t n, std::uint64_t total) {
  if (n <= total - seen) return true;
  return sink.fail(line, std::string(noun) + " blocks hold more than the " + std::to_string(total) + " " +
                             std::string(noun) + "s declared");
}

bool check_blocks_add_up(ErrorSink& sink, std::uint64_t line, std::string_view noun, std::uint64_t seen,
                         std::uint64_t total) {
  if (seen == total) return true;
  return sink.fail(line, std::string(noun) + " blocks hold " + std::to_string(seen) + " " + std::string(noun) +
                             "s, the header declares " + std::to_string(total));
}

GmshReader::GmshReader(std::string_view text, std::string_view name, std::string_view nodes,
                       std::string_view elements)
    : lines_(text), sink_(name), nodes_header_(nodes), elements_header_(elements) {
  elements_.nodes = &ids_;
  elements_.tets = &mesh_.tets;
  elements_.labels = &mesh_.labels;
}

void GmshReader::on_nodes_header() {
  if (have_nodes_) sink_.fail(lines_.line_number(), "second " + std::string(nodes_header_) + " section");
  else read_nodes();
  have_nodes_ = true;
}

void GmshReader::on_elements_header() {
  if (have_elements_) {
    sink_.fail(lines_.line_number(), "second " + std::string(elements_header_) + " section");
  } else if (!have_nodes_) {
    sink_.fail(lines_.line_number(), std::string(elements_header_) + " before " + std::string(nodes_header_));
  } else {
    read_elements();
  }
  have_elements_ = true;
}

void GmshReader::require_nodes_and_elements() {
  if (!have_nodes_) sink_.fail(lines_.line_number(), "missing " + std::string(nodes_header_) + " section");
  else if (!have_elements_) sink_.fail(lines_.line_number(), "missing " + std::string(elements_header_) + " section");
}

void GmshReader::read_node_lines(std::uint64_t count, std::string_view section, std::string_view noun,
                                 std::string_view end_marker) {
  mesh_.positions.reserve(count);
  for (std::uint64_t i = 0; i < count; ++i) {
    if (!next_entry(section, noun, i, count)) return;
    if (!add_gmsh_node(sink_, lines_.line_number(), tokens_, ids_, mesh_.positions)) return;
  }
  expect_gmsh_marker(lines_, sink_, end_marker, "the last node");
}

bool GmshReader::read_count_line(std::string_view missing, std::string_view expected, std::uint64_t& count) {
  std::string_view line;
  if (!lines_.next_nonblank(line)) {
    return sink_.fail(lines_.line_number(), "unexpected end of file: missing " + std::string(missing));
  }
  split_tokens(line, tokens_);
  if (tokens_.size() != 1) {
    return sink_.fail(lines_.line_number(), "expected " + std::string(expected) + ", got " + quote(trim(line)));
  }
  return parse_count(sink_, lines_.line_number(), tokens_[0], lines_.remaining_bytes(), count);
}

bool GmshReader::next_entry(std::string_view section, std::string_view noun, std::uint64_t i,
                            std::uint64_t count) {
  std::string_view line;
  if (!lines_.next_nonblank(line)) {
    return sink_.fail(lines_.line_number(), "unexpected end of file in " + std::string(section) + ": expected " +
                                                std::to_string(count) + " " + std::string(noun) + ", got " +
                                                std::to_string(i));
  }
  split_tokens(line, tokens_);
  if (tokens_[0][0] == '$') {
    return sink_.fail(lines_.line_number(), "section ended after " + std::to_string(i) + " of " +
                                                std::to_string(count) + " " + std::string(noun));
  }
  return true;
}

ReadResult GmshReader::result() {
  std::vector<std::string> notices;
  elements_.emit_notices(notices);
  if (!elements_.labelled) mesh_.labels.clear();
  return make_result(sink_, std::move(mesh_), std::move(notices), &elements_.ignored);
}

bool GmshVolumeLabels::add(ErrorSink& sink, std::uint64_t line, std::int64_t tag,
                           std::optional<std::uint32_t> label) {
  if (!by_tag.emplace(tag, label).second) {
    return sink.fail(line, "volume entity " + std::to_string(tag) + " listed twice in $Entities");
  }
  labelled = labelled || label.has_value();
  return true;
}

bool GmshVolumeLabels::label_block(ErrorSink& sink, std::uint64_t line, std::int64_t dim, std::int64_t tag,
                                   GmshElementSink& elements) const {
  elements.label.reset();
  if (!labelled) return true;
  if (dim != 3) {
    return sink.fail(line, "tetrahedra in an element block of entity dimension " + std::to_string(dim) +
                               " (a volume's block has dimension 3; its physical tag is the label)");
  }
  const auto it = by_tag.find(tag);
  if (it == by_tag.end()) {
    return sink.fail(line, "element block names volume entity " + std::to_string(tag) +
                               ", which $Entities does not list (its physical tag is the label)");
  }
  elements.label = it->second;
  return true;
}

}  // namespace tetcut::io_detail
