// Small readers of the SVG text the render library writes, for assertions. Not an XML parser:
// just enough to find elements and attribute values in our own output.
#pragma once

#include <cstdlib>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace tetcut::render::testing {

inline std::size_t count_of(std::string_view text, std::string_view needle) {
  std::size_t n = 0;
  for (std::size_t at = text.find(needle); at != std::string_view::npos; at = text.find(needle, at + needle.size())) ++n;
  return n;
}

// Every element starting with `open` (e.g. "<polygon"), as the text up to its closing '>'.
inline std::vector<std::string> elements(std::string_view svg, std::string_view open) {
  std::vector<std::string> out;
  for (std::size_t at = svg.find(open); at != std::string_view::npos; at = svg.find(open, at + 1)) {
    const std::size_t end = svg.find('>', at);
    out.emplace_back(svg.substr(at, end - at + 1));
  }
  return out;
}

// The value of attribute `name` in `element`, or "" when absent.
inline std::string attribute(std::string_view element, std::string_view name) {
  std::string key = " ";  // built by append: GCC 12 warns (-Wrestrict) on " " + std::string
  key.append(name);
  key.append("=\"");
  const std::size_t at = element.find(key);
  if (at == std::string_view::npos) return {};
  const std::size_t begin = at + key.size();
  return std::string(element.substr(begin, element.find('"', begin) - begin));
}

inline double number_attribute(std::string_view element, std::string_view name) {
  return std::strtod(attribute(element, name).c_str(), nullptr);
}

// "x,y x,y ..." -> points.
inline std::vector<std::pair<double, double>> points(const std::string& list) {
  std::vector<std::pair<double, double>> out;
  const char* p = list.c_str();
  while (*p != '\0') {
    char* end = nullptr;
    const double x = std::strtod(p, &end);
    if (end == p || *end != ',') break;
    p = end + 1;
    const double y = std::strtod(p, &end);
    out.emplace_back(x, y);
    p = end;
    while (*p == ' ') ++p;
  }
  return out;
}

inline bool is_svg_document(std::string_view svg) {
  return svg.starts_with("<svg xmlns=\"http://www.w3.org/2000/svg\"") && svg.ends_with("</svg>") &&
         count_of(svg, "<svg") == 1 && count_of(svg, "</svg>") == 1;
}

}  // namespace tetcut::render::testing
