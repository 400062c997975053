#include "gmsh_sections.hpp"

#include <algorithm>
#include <string>

namespace tetcut::io_detail {

ReadResult GmshSectionReader::read() {
  std::string_view line;
  bool have_format = false;
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
      on_nodes_header();
    } else if (section == "Elements") {
      on_elements_header();
    } else if (section == "Entities") {
      read_entities();
    } else if (section.substr(0, 3) == "End") {
      sink_.fail(lines_.line_number(), "unexpected " + quote(header) + " outside its section");
    } else {
      skip_gmsh_section(lines_, sink_, section);
    }
  }
  if (!sink_.failed()) {
    if (!have_format) sink_.fail(std::max<std::uint64_t>(1, lines_.line_number()), "empty file: no $MeshFormat section");
    else require_nodes_and_elements();
  }
  return result();
}

}  // namespace tetcut::io_detail
