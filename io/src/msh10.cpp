// Gmsh MSH 1.0 (read only): "$NOD" count, "id x y z" lines, "$ENDNOD"; "$ELM" count,
// "id type reg-phys reg-elem num-nodes node..." lines, "$ENDELM". reg-phys is the tet's label.
#include <algorithm>
#include <string>

#include "gmsh_common.hpp"
#include "tetcut/io.hpp"

namespace tetcut {

namespace {

using namespace io_detail;

class Msh10Reader : public GmshReader {
 public:
  Msh10Reader(std::string_view text, std::string_view name) : GmshReader(text, name, "$NOD", "$ELM") {}

  ReadResult read() {
    std::string_view line;
    while (!sink_.failed() && lines_.next_nonblank(line)) {
      const std::string_view header = trim(line);
      if (header == "$NOD") {
        on_nodes_header();
      } else if (header == "$ELM") {
        on_elements_header();
      } else if (header == "$Comments" || header == "$COMMENTS") {
        skip_gmsh_section(lines_, sink_, header.substr(1));
      } else {
        sink_.fail(lines_.line_number(), "expected $NOD or $ELM, got " + quote(header));
      }
    }
    if (!sink_.failed()) require_nodes_and_elements();
    return result();
  }

 private:
  void read_nodes() override {
    std::uint64_t count = 0;
    if (read_count_line("count in $NOD", "a count", count)) read_node_lines(count, "$NOD", "entries", "$ENDNOD");
  }

  void read_elements() override {
    std::uint64_t count = 0;
    if (!read_count_line("count in $ELM", "a count", count)) return;
    mesh_.tets.reserve(count);
    for (std::uint64_t i = 0; i < count; ++i) {
      if (!next_entry("$ELM", "entries", i, count)) return;
      const std::uint64_t at = lines_.line_number();
      if (tokens_.size() < 5) {
        sink_.fail(at, "expected 'id type reg-phys reg-elem num-nodes node...', got " +
                           std::to_string(tokens_.size()) + " values");
        return;
      }
      std::int64_t id = 0;
      std::int64_t type = 0;
      std::int64_t num_nodes = 0;
      if (!parse_id(sink_, at, tokens_[0], id) || !parse_gmsh_type(sink_, at, tokens_[1], type)) return;
      if (!parse_i64(tokens_[4], num_nodes) || num_nodes < 0 ||
          static_cast<std::uint64_t>(num_nodes) != tokens_.size() - 5) {
        sink_.fail(at, "element declares " + quote(tokens_[4]) + " nodes but lists " +
                           std::to_string(tokens_.size() - 5));
        return;
      }
      std::uint32_t label = 0;  // reg-phys: the physical region, the tet's label (as in 2.2)
      if (!parse_label(sink_, at, tokens_[2], "physical region", label)) return;
      elements_.label = label;
      if (!elements_.add(sink_, at, type, tokens_.data() + 5, tokens_.size() - 5)) return;
    }
    expect_gmsh_marker(lines_, sink_, "$ENDELM", "the last element");
  }
};

}  // namespace

ReadResult read_msh10(std::string_view text, std::string_view name) {
  return Msh10Reader(text, name).read();
}

// Tells the versions apart by the first section: $NOD is 1.0; $MeshFormat gives the version.
ReadResult read_msh(std::string_view text, std::string_view name) {
  LineReader lines(text);
  std::string_view line;
  std::vector<std::string_view> tokens;
  bool other_header = false;
  while (lines.next_nonblank(line)) {
    const std::string_view header = trim(line);
    if (header == "$NOD" || header == "$Comments" || header == "$COMMENTS") {
      if (header == "$NOD") return read_msh10(text, name);
      // Comments may precede either header; look past them.
      std::string_view skipped;
      while (lines.next(skipped) && trim(skipped) != "$EndComments" && trim(skipped) != "$ENDCOMMENTS") {
      }
      continue;
    }
    if (header == "$MeshFormat") {
      if (lines.next_nonblank(line)) {
        split_tokens(line, tokens);
        if (!tokens.empty() && tokens[0] == "4.1") return read_msh41(text, name);
        if (!tokens.empty() && (tokens[0] == "4" || tokens[0] == "4.0")) {
          ReadResult r;
          r.error = ParseError{std::string(name), lines.line_number(),
                               "MSH 4.0 is not supported; save the mesh as MSH 4.1 or 2.2"};
          return r;
        }
      }
      // 2.x, and every other version for read_msh22 to refuse with a precise message.
      return read_msh22(text, name);
    }
    other_header = true;
    break;
  }
  ReadResult r;
  if (!other_header) {
    r.error = ParseError{std::string(name), std::max<std::uint64_t>(1, lines.line_number()), "empty file: no $MeshFormat section"};
  } else {
    r.error = ParseError{std::string(name), lines.line_number(),
                         "expected $MeshFormat (or $NOD for MSH 1.0), got " + io_detail::quote(trim(line))};
  }
  return r;
}

}  // namespace tetcut
