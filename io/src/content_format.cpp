#include "content_format.hpp"

#include "text_reader.hpp"

namespace tetcut::io_detail {

namespace {

// How far into a file the signatures are looked for: headers are short.
constexpr std::size_t kHead = 4096;

bool starts_with_ci(std::string_view s, std::string_view prefix) {
  return s.size() >= prefix.size() && iequals(s.substr(0, prefix.size()), prefix);
}

// The value of attribute `name` in the tag starting at `tag` (crudely: enough for a header).
std::string attribute_in_tag(std::string_view head, std::size_t tag, std::string_view name) {
  const std::size_t end = head.find('>', tag);
  const std::string_view t = head.substr(tag, end == std::string_view::npos ? std::string_view::npos : end - tag);
  for (std::size_t at = t.find(name); at != std::string_view::npos; at = t.find(name, at + 1)) {
    if (at == 0 || !is_space(t[at - 1])) continue;
    std::size_t p = at + name.size();
    while (p < t.size() && is_space(t[p])) ++p;
    if (p >= t.size() || t[p] != '=') continue;
    ++p;
    while (p < t.size() && is_space(t[p])) ++p;
    if (p >= t.size() || (t[p] != '"' && t[p] != '\'')) continue;
    const std::size_t close = t.find(t[p], p + 1);
    if (close == std::string_view::npos) return {};
    return std::string(t.substr(p + 1, close - p - 1));
  }
  return {};
}

std::string legacy_dataset(std::string_view head) {
  LineReader lines(head);
  std::string_view line;
  std::vector<std::string_view> tokens;
  for (int i = 0; i < 8 && lines.next(line); ++i) {
    split_tokens(line, tokens);
    if (tokens.size() >= 2 && i >= 2 && iequals(tokens[0], "DATASET")) return std::string(tokens[1]);
  }
  return {};
}

bool looks_binary(std::string_view head) {
  std::size_t odd = 0;
  for (char c : head.substr(0, 512)) {
    const auto u = static_cast<unsigned char>(c);
    if (u == 0 || (u < 0x20 && !is_space(c))) ++odd;
  }
  return odd > 0;
}

}  // namespace

DetectedContent detect_content(std::string_view bytes) {
  std::string_view head = bytes.substr(0, kHead);
  if (head.substr(0, 3) == "\xEF\xBB\xBF") head.remove_prefix(3);  // UTF-8 byte order mark
  std::size_t first = 0;
  while (first < head.size() && is_space(head[first])) ++first;
  const std::string_view text = head.substr(first);
  DetectedContent d;
  if (text.starts_with("<?xml") || text.starts_with("<VTKFile") || text.starts_with("<!--")) {
    const std::size_t tag = text.find("<VTKFile");
    if (tag == std::string_view::npos) {
      d.description = "an XML file that is not VTK";
      return d;
    }
    d.format = ContentFormat::kVtkXml;
    d.dataset = attribute_in_tag(text, tag, "type");
    d.description = "VTK XML " + (d.dataset.empty() ? std::string("(no type)") : d.dataset);
    return d;
  }
  if (starts_with_ci(text, "# vtk DataFile Version")) {
    d.format = ContentFormat::kLegacyVtk;
    d.dataset = legacy_dataset(text);
    d.description = "legacy VTK " + (d.dataset.empty() ? std::string("(no DATASET)") : d.dataset);
    return d;
  }
  LineReader lines(text);
  std::string_view line;
  lines.next(line);
  const std::string_view first_line = trim(line);
  if (first_line == "$MeshFormat" || first_line == "$NOD" || first_line == "$Comments" || first_line == "$COMMENTS") {
    d.format = ContentFormat::kGmsh;
    d.description = "Gmsh MSH";
    return d;
  }
  // medit: the first keyword, after '#' comment lines.
  LineReader medit(text);
  std::vector<std::string_view> tokens;
  if (next_tokens(medit, tokens, '#') && iequals(tokens[0], "MeshVersionFormatted")) {
    d.format = ContentFormat::kMedit;
    d.description = "medit MESH";
    return d;
  }
  if (starts_with_ci(first_line, "solid") && text.find("facet") != std::string_view::npos) {
    d.format = ContentFormat::kSurface;
    d.description = "an ASCII STL surface";
  } else if (first_line.starts_with("OFF") || first_line.starts_with("COFF") || first_line.starts_with("NOFF")) {
    d.format = ContentFormat::kSurface;
    d.description = "an OFF surface";
  } else if (text.empty()) {
    d.description = "an empty file";
  } else if (looks_binary(text)) {
    d.description = "binary data";
  } else {
    d.description = "text starting " + quote(first_line);
  }
  return d;
}

}  // namespace tetcut::io_detail
