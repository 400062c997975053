#include "gmsh_sections.hpp"

#include <algorithm>
#include <string>

namespace tetcut::io_detail {

ReadResult GmshSectionReader::read() {
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
  return result();
}

}  // namespace tetcut::io_detail
