#include "vtk_xml.hpp"

#include <string>

#include "vtk_cells.hpp"

namespace tetcut::io_detail {

namespace {

// Sections whose DataArrays make up a mesh or a surface; arrays elsewhere (PointData, CellData,
// FieldData, faces, ...) are data on the mesh and are not kept, but for the cell data that
// labels the cells (kLabelArrayNames).
bool is_geometry_section(std::string_view name) {
  return name == "Points" || name == "Cells" || name == "Polys" || name == "Strips" || name == "Verts" ||
         name == "Lines";
}

class VtkXmlScanner {
 public:
  VtkXmlScanner(std::string_view text, std::string_view expected_type, ErrorSink& sink, VtkXmlFile& file)
      : text_(text), expected_type_(expected_type), sink_(sink), file_(file) {}

  // Walks the XML once, collecting pieces and their arrays; stops at AppendedData.
  bool scan() {
    if (trim(text_).empty()) return sink_.fail(1, "empty file");
    std::vector<std::string_view> stack;
    std::size_t pos = 0;
    std::size_t content_begin = 0;
    bool seen_root = false;
    std::optional<VtkDataArray> open_array;
    while (true) {
      const std::size_t lt = text_.find('<', pos);
      if (lt == std::string_view::npos) break;
      if (!open_array && !stack.empty()) {
        // Text between structural tags must be blank.
        const std::string_view between = trim(text_.substr(pos, lt - pos));
        if (!between.empty()) {
          return sink_.fail(line_at(pos + (text_.substr(pos, lt - pos).find(between[0]))),
                            "unexpected text " + quote(between) + " inside <" + std::string(stack.back()) + ">");
        }
      }
      const std::uint64_t line = line_at(lt);
      pos = lt + 1;
      if (text_.substr(pos, 1) == "?") {
        if (!skip_to(pos, "?>", "processing instruction")) return false;
        continue;
      }
      if (text_.substr(pos, 3) == "!--") {
        if (!skip_to(pos, "-->", "comment")) return false;
        continue;
      }
      if (text_.substr(pos, 1) == "!") {
        if (!skip_to(pos, ">", "declaration")) return false;
        continue;
      }
      const bool closing = text_.substr(pos, 1) == "/";
      if (closing) ++pos;
      const std::size_t name_begin = pos;
      while (pos < text_.size() && !is_space(text_[pos]) && text_[pos] != '>' && text_[pos] != '/') ++pos;
      const std::string_view name = text_.substr(name_begin, pos - name_begin);
      if (name.empty()) return sink_.fail(line, "malformed tag");
      if (closing) {
        while (pos < text_.size() && is_space(text_[pos])) ++pos;
        if (pos >= text_.size() || text_[pos] != '>') return sink_.fail(line, "malformed closing tag </" + std::string(name));
        ++pos;
        if (stack.empty() || stack.back() != name) {
          return sink_.fail(line, "unexpected </" + std::string(name) + ">" +
                                      (stack.empty() ? std::string() : ", expected </" + std::string(stack.back()) + ">"));
        }
        if (open_array && name == "DataArray") {
          open_array->content_begin = content_begin;
          open_array->content_end = lt;
          // The stack ends with this DataArray; its parent is the element below.
          open_array->parent = stack.size() >= 2 ? stack[stack.size() - 2] : std::string_view();
          store_array(*open_array);
          open_array.reset();
        }
        stack.pop_back();
        if (stack.empty()) return finish_scan(seen_root, line);
        continue;
      }
      if (open_array) return sink_.fail(line, "unexpected <" + std::string(name) + "> inside a DataArray");
      bool self_closing = false;
      if (!parse_tag(pos, self_closing, line)) return false;
      if (stack.empty()) {
        if (seen_root || name != "VTKFile") {
          return sink_.fail(line, "expected <VTKFile>, got <" + std::string(name) + ">");
        }
        seen_root = true;
        if (!read_root(line)) return false;
      } else if (name == expected_type_) {
        if (stack.back() != "VTKFile") return sink_.fail(line, "<" + std::string(name) + "> outside <VTKFile>");
      } else if (name == "Piece") {
        if (stack.back() != expected_type_) {
          return sink_.fail(line, "<Piece> outside <" + std::string(expected_type_) + ">");
        }
        file_.pieces.push_back(VtkXmlPiece{line, attributes_, {}});
      } else if (name == "AppendedData") {
        return read_appended(pos, line, seen_root);
      } else if (name == "DataArray") {
        VtkDataArray array;
        if (!read_array_tag(line, array)) return false;
        if (self_closing) {
          array.content_begin = array.content_end = pos;
          array.parent = stack.back();
          store_array(array);
        } else {
          // The content starts at its first non-blank character, so that its line is right.
          std::size_t first = pos;
          while (first < text_.size() && is_space(text_[first])) ++first;
          content_begin = first;
          array.content_line = line_at(first);
          open_array = array;
        }
      }
      if (!self_closing) stack.push_back(name);
    }
    // The line of the last character, not the empty line after a final newline.
    const std::uint64_t last_line = line_at(text_.size() - 1);
    if (!seen_root) return sink_.fail(last_line, "not a VTK XML file: no <VTKFile>");
    return sink_.fail(last_line, "unexpected end of file: missing </" +
                                     std::string(stack.empty() ? "VTKFile" : stack.back()) + ">");
  }

 private:
  // ---- line numbers: positions are visited in increasing order during the scan ----------------
  std::uint64_t line_at(std::size_t pos) {
    for (; counted_pos_ < pos && counted_pos_ < text_.size(); ++counted_pos_) {
      const char c = text_[counted_pos_];
      if (c == '\n' || (c == '\r' && (counted_pos_ + 1 >= text_.size() || text_[counted_pos_ + 1] != '\n'))) {
        ++counted_line_;
      }
    }
    return counted_line_;
  }

  [[nodiscard]] const XmlAttribute* find_attribute(std::string_view name) const {
    for (const XmlAttribute& a : attributes_) {
      if (a.name == name) return &a;
    }
    return nullptr;
  }
  [[nodiscard]] std::string_view attribute(std::string_view name) const {
    const XmlAttribute* a = find_attribute(name);
    return a != nullptr ? a->value : std::string_view();
  }

  bool count_attribute(std::string_view name, std::uint64_t line, std::uint64_t& value) {
    const std::string_view text = attribute(name);
    if (!parse_u64(text, value)) {
      return sink_.fail(line, "attribute " + std::string(name) + " must be a non-negative integer, got " + quote(text));
    }
    return true;
  }

  // Parses the attributes of a start tag from `pos` (after its name) to its '>'.
  bool parse_tag(std::size_t& pos, bool& self_closing, std::uint64_t line) {
    attributes_.clear();
    self_closing = false;
    while (true) {
      while (pos < text_.size() && is_space(text_[pos])) ++pos;
      if (pos >= text_.size()) return sink_.fail(line, "unexpected end of file inside a tag");
      if (text_[pos] == '>') {
        ++pos;
        return true;
      }
      if (text_[pos] == '/' && pos + 1 < text_.size() && text_[pos + 1] == '>') {
        pos += 2;
        self_closing = true;
        return true;
      }
      const std::size_t name_begin = pos;
      while (pos < text_.size() && !is_space(text_[pos]) && text_[pos] != '=' && text_[pos] != '>' && text_[pos] != '/') ++pos;
      const std::string_view name = text_.substr(name_begin, pos - name_begin);
      while (pos < text_.size() && is_space(text_[pos])) ++pos;
      if (name.empty() || pos >= text_.size() || text_[pos] != '=') {
        return sink_.fail(line_at(pos), "malformed attribute " + quote(name) + " in a tag");
      }
      ++pos;
      while (pos < text_.size() && is_space(text_[pos])) ++pos;
      if (pos >= text_.size() || (text_[pos] != '"' && text_[pos] != '\'')) {
        return sink_.fail(line_at(pos), "attribute " + quote(name) + " has no quoted value");
      }
      const char q = text_[pos++];
      const std::size_t value_begin = pos;
      while (pos < text_.size() && text_[pos] != q) ++pos;
      if (pos >= text_.size()) return sink_.fail(line, "unterminated attribute value for " + quote(name));
      attributes_.push_back({name, text_.substr(value_begin, pos - value_begin)});
      ++pos;
    }
  }

  bool skip_to(std::size_t& pos, std::string_view end, std::string_view what) {
    const std::size_t found = text_.find(end, pos);
    if (found == std::string_view::npos) {
      return sink_.fail(line_at(pos), "unterminated " + std::string(what));
    }
    pos = found + end.size();
    return true;
  }

  bool finish_scan(bool seen_root, std::uint64_t line) {
    if (!seen_root) return sink_.fail(line, "not a VTK XML file: no <VTKFile>");
    if (file_.pieces.empty()) return sink_.fail(line, "no <Piece> in the file");
    return true;
  }

  bool read_root(std::uint64_t line) {
    file_.type = attribute("type");
    if (file_.type != expected_type_) {
      return sink_.fail(line, "VTKFile type " + quote(file_.type) + " is not " + std::string(expected_type_));
    }
    const std::string_view compressor = attribute("compressor");
    if (compressor == "vtkZLibDataCompressor") {
      file_.compressor = Compressor::kZlib;
    } else if (compressor == "vtkLZMADataCompressor") {
      file_.compressor = Compressor::kLzma;
    } else if (!compressor.empty()) {
      return sink_.fail(line, "compressor " + quote(compressor) +
                                  " is not supported (vtkZLibDataCompressor and vtkLZMADataCompressor are); "
                                  "save with one of those or without compression");
    }
    const std::string_view header = attribute("header_type");
    if (header.empty() || header == "UInt32") file_.header_size = 4;
    else if (header == "UInt64") file_.header_size = 8;
    else return sink_.fail(line, "header_type must be UInt32 or UInt64, got " + quote(header));
    const std::string_view order = attribute("byte_order");
    if (order.empty() || order == "LittleEndian") file_.order = ByteOrder::kLittle;
    else if (order == "BigEndian") file_.order = ByteOrder::kBig;
    else return sink_.fail(line, "byte_order must be LittleEndian or BigEndian, got " + quote(order));
    return true;
  }

  bool read_array_tag(std::uint64_t line, VtkDataArray& array) {
    array.line = line;
    array.name = attribute("Name");
    array.type = attribute("type");
    array.format = attribute("format");
    if (find_attribute("NumberOfComponents") != nullptr &&
        !count_attribute("NumberOfComponents", line, array.components)) {
      return false;
    }
    if (array.format == "appended" && !count_attribute("offset", line, array.offset)) return false;
    if (array.format != "ascii" && array.format != "binary" && array.format != "appended") {
      return sink_.fail(line, "DataArray format must be ascii, binary or appended, got " + quote(array.format));
    }
    if (vtk_type_size(array.type) == 0) return sink_.fail(line, "unsupported DataArray type " + quote(array.type));
    return true;
  }

  void store_array(const VtkDataArray& array) {
    if (file_.pieces.empty()) return;
    if (!is_geometry_section(array.parent) && !(array.parent == "CellData" && label_array_rank(array.name) >= 0)) return;
    file_.pieces.back().arrays.push_back(array);
  }

  bool read_appended(std::size_t pos, std::uint64_t line, bool seen_root) {
    if (!seen_root) return sink_.fail(line, "<AppendedData> outside <VTKFile>");
    if (file_.pieces.empty()) return sink_.fail(line, "no <Piece> in the file");
    const std::string_view encoding = attribute("encoding");
    if (encoding == "raw") file_.appended_base64 = false;
    else if (encoding == "base64") file_.appended_base64 = true;
    else return sink_.fail(line, "AppendedData encoding must be raw or base64, got " + quote(encoding));
    while (pos < text_.size() && is_space(text_[pos])) ++pos;
    if (pos >= text_.size() || text_[pos] != '_') {
      return sink_.fail(line_at(pos), "AppendedData must start with '_'");
    }
    file_.appended_begin = pos + 1;
    file_.have_appended = true;
    return true;
  }

  std::string_view text_;
  std::string_view expected_type_;
  ErrorSink& sink_;
  VtkXmlFile& file_;
  std::vector<XmlAttribute> attributes_;
  std::size_t counted_pos_ = 0;
  std::uint64_t counted_line_ = 1;
};

}  // namespace

const VtkDataArray* VtkXmlPiece::find(std::string_view parent, std::string_view name) const {
  for (const VtkDataArray& a : arrays) {
    if (a.parent == parent && (name.empty() || a.name == name)) return &a;
  }
  return nullptr;
}

std::size_t vtk_type_size(std::string_view type) {
  if (type == "Int8" || type == "UInt8") return 1;
  if (type == "Int16" || type == "UInt16") return 2;
  if (type == "Int32" || type == "UInt32" || type == "Float32") return 4;
  if (type == "Int64" || type == "UInt64" || type == "Float64") return 8;
  return 0;
}

bool scan_vtk_xml(std::string_view text, std::string_view expected_type, ErrorSink& sink, VtkXmlFile& file) {
  return VtkXmlScanner(text, expected_type, sink, file).scan();
}

bool piece_count(ErrorSink& sink, const VtkXmlPiece& piece, std::string_view name, bool required,
                 std::uint64_t& count) {
  count = 0;
  const XmlAttribute* found = nullptr;
  for (const XmlAttribute& a : piece.attributes) {
    if (a.name == name) found = &a;
  }
  if (found == nullptr && !required) return true;
  const std::string_view value = found != nullptr ? found->value : std::string_view();
  if (!parse_u64(value, count)) {
    return sink.fail(piece.line, "attribute " + std::string(name) + " must be a non-negative integer, got " +
                                     quote(value));
  }
  return true;
}

}  // namespace tetcut::io_detail
