// VTK XML UnstructuredGrid (.vtu). A small XML scanner reads the structure
//   VTKFile > UnstructuredGrid > Piece > Points > DataArray, Cells > DataArray
//   (connectivity, offsets, types)
// and each DataArray is decoded from ascii, inline binary (base64 of a UInt32/UInt64 byte count
// then the values) or appended data (raw or base64, at the array's offset after the '_' mark).
// Compressed files are refused with a clear message. Several pieces are concatenated.
#include <cmath>
#include <cstring>
#include <limits>
#include <string>

#include "base64.hpp"
#include "tetcut/io.hpp"
#include "text_reader.hpp"
#include "vtk_cells.hpp"

namespace tetcut {

namespace {

using namespace io_detail;

struct XmlAttribute {
  std::string_view name;
  std::string_view value;
};

struct DataArray {
  std::string_view name;
  std::string_view type;
  std::string_view format;  // ascii | binary | appended
  std::uint64_t components = 1;
  std::uint64_t offset = 0;  // appended only
  std::size_t content_begin = 0;
  std::size_t content_end = 0;
  std::uint64_t line = 0;          // of the tag
  std::uint64_t content_line = 0;  // of the first character of the content
};

struct Piece {
  std::uint64_t points = 0;
  std::uint64_t cells = 0;
  std::uint64_t line = 0;
  std::optional<DataArray> coordinates;
  std::optional<DataArray> connectivity;
  std::optional<DataArray> offsets;
  std::optional<DataArray> types;
};

std::size_t type_size(std::string_view type) {
  if (type == "Int8" || type == "UInt8") return 1;
  if (type == "Int16" || type == "UInt16") return 2;
  if (type == "Int32" || type == "UInt32" || type == "Float32") return 4;
  if (type == "Int64" || type == "UInt64" || type == "Float64") return 8;
  return 0;
}

class VtuReader {
 public:
  VtuReader(std::string_view text, std::string_view name) : text_(text), sink_(name) {}

  ReadResult read() {
    std::vector<std::string> notices;
    if (scan() && check_pieces()) {
      for (const Piece& piece : pieces_) {
        if (!read_piece(piece, notices)) break;
      }
    }
    return make_result(sink_, std::move(mesh_), std::move(notices));
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

  std::string_view attribute(std::string_view name) const {
    for (const XmlAttribute& a : attributes_) {
      if (a.name == name) return a.value;
    }
    return {};
  }

  bool has_attribute(std::string_view name) const {
    for (const XmlAttribute& a : attributes_) {
      if (a.name == name) return true;
    }
    return false;
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

  // Walks the XML once, collecting pieces and their arrays; stops at AppendedData.
  bool scan() {
    if (trim(text_).empty()) return sink_.fail(1, "empty file");
    std::vector<std::string_view> stack;
    std::size_t pos = 0;
    std::size_t content_begin = 0;
    bool seen_root = false;
    std::optional<DataArray> open_array;
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
          if (!store_array(stack.size() >= 2 ? stack[stack.size() - 2] : std::string_view(), *open_array)) return false;
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
      } else if (name == "UnstructuredGrid") {
        if (stack.back() != "VTKFile") return sink_.fail(line, "<UnstructuredGrid> outside <VTKFile>");
      } else if (name == "Piece") {
        if (stack.back() != "UnstructuredGrid") return sink_.fail(line, "<Piece> outside <UnstructuredGrid>");
        Piece piece;
        piece.line = line;
        if (!count_attribute("NumberOfPoints", line, piece.points) ||
            !count_attribute("NumberOfCells", line, piece.cells)) {
          return false;
        }
        // Each point takes at least a few bytes somewhere in the file, each cell too.
        if (!check_count(sink_, line, piece.points, text_.size()) ||
            !check_count(sink_, line, piece.cells, text_.size())) {
          return false;
        }
        pieces_.push_back(piece);
      } else if (name == "AppendedData") {
        return read_appended(pos, line, seen_root);
      } else if (name == "DataArray") {
        DataArray array;
        array.line = line;
        array.name = attribute("Name");
        array.type = attribute("type");
        array.format = attribute("format");
        if (has_attribute("NumberOfComponents") && !count_attribute("NumberOfComponents", line, array.components)) return false;
        if (array.format == "appended" && !count_attribute("offset", line, array.offset)) return false;
        if (array.format != "ascii" && array.format != "binary" && array.format != "appended") {
          return sink_.fail(line, "DataArray format must be ascii, binary or appended, got " + quote(array.format));
        }
        if (type_size(array.type) == 0) return sink_.fail(line, "unsupported DataArray type " + quote(array.type));
        if (self_closing) {
          array.content_begin = array.content_end = pos;
          if (!store_array(stack.back(), array)) return false;
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

  bool finish_scan(bool seen_root, std::uint64_t line) {
    if (!seen_root) return sink_.fail(line, "not a VTK XML file: no <VTKFile>");
    return true;
  }

  bool read_root(std::uint64_t line) {
    const std::string_view type = attribute("type");
    if (type != "UnstructuredGrid") {
      return sink_.fail(line, "VTKFile type " + quote(type) + " is not UnstructuredGrid");
    }
    const std::string_view compressor = attribute("compressor");
    if (!compressor.empty()) {
      return sink_.fail(line, "compressed data (" + std::string(compressor) +
                                  ") is not supported; save the .vtu without compression");
    }
    const std::string_view header = attribute("header_type");
    if (header.empty() || header == "UInt32") header_size_ = 4;
    else if (header == "UInt64") header_size_ = 8;
    else return sink_.fail(line, "header_type must be UInt32 or UInt64, got " + quote(header));
    const std::string_view order = attribute("byte_order");
    if (order.empty() || order == "LittleEndian") big_endian_ = false;
    else if (order == "BigEndian") big_endian_ = true;
    else return sink_.fail(line, "byte_order must be LittleEndian or BigEndian, got " + quote(order));
    return true;
  }

  bool store_array(std::string_view parent, const DataArray& array) {
    if (pieces_.empty()) return true;
    Piece& piece = pieces_.back();
    std::optional<DataArray>* slot = nullptr;
    if (parent == "Points") {
      slot = &piece.coordinates;
    } else if (parent == "Cells") {
      if (array.name == "connectivity") slot = &piece.connectivity;
      else if (array.name == "offsets") slot = &piece.offsets;
      else if (array.name == "types") slot = &piece.types;
    }
    if (slot == nullptr) return true;  // PointData, CellData, faces, ...: not part of the mesh
    if (slot->has_value()) return sink_.fail(array.line, "second DataArray for the same role in a Piece");
    *slot = array;
    return true;
  }

  bool read_appended(std::size_t pos, std::uint64_t line, bool seen_root) {
    if (!seen_root) return sink_.fail(line, "<AppendedData> outside <VTKFile>");
    const std::string_view encoding = attribute("encoding");
    if (encoding == "raw") appended_base64_ = false;
    else if (encoding == "base64") appended_base64_ = true;
    else return sink_.fail(line, "AppendedData encoding must be raw or base64, got " + quote(encoding));
    while (pos < text_.size() && is_space(text_[pos])) ++pos;
    if (pos >= text_.size() || text_[pos] != '_') {
      return sink_.fail(line_at(pos), "AppendedData must start with '_'");
    }
    appended_begin_ = pos + 1;
    have_appended_ = true;
    return true;
  }

  bool check_pieces() {
    if (pieces_.empty()) return sink_.fail(line_at(text_.size()), "no <Piece> in the file");
    return true;
  }

  // ---- decoding ------------------------------------------------------------------------------

  std::uint64_t read_header_value(const std::uint8_t* p) const {
    std::uint64_t v = 0;
    for (std::size_t i = 0; i < header_size_; ++i) {
      const std::size_t k = big_endian_ ? i : header_size_ - 1 - i;
      v = (v << 8) | p[k];
    }
    return v;
  }

  // The raw bytes of a binary or appended array.
  bool array_bytes(const DataArray& a, std::vector<std::uint8_t>& bytes) {
    bytes.clear();
    if (a.format == "binary") {
      if (!decode_base64(text_.substr(0, a.content_end), a.content_begin, static_cast<std::size_t>(-1), bytes)) {
        return sink_.fail(a.content_line, "invalid base64 data in DataArray");
      }
    } else {
      if (!have_appended_) return sink_.fail(a.line, "DataArray refers to appended data but the file has no <AppendedData>");
      if (a.offset > text_.size() - appended_begin_) {
        return sink_.fail(a.line, "appended offset " + std::to_string(a.offset) + " exceeds file size");
      }
      const std::size_t start = appended_begin_ + static_cast<std::size_t>(a.offset);
      if (appended_base64_) {
        if (!decode_base64(text_, start, header_size_, bytes) || bytes.size() < header_size_) {
          return sink_.fail(a.line, "invalid or truncated base64 appended data");
        }
        const std::uint64_t n = read_header_value(bytes.data());
        if (n > (text_.size() - start) / 4 * 3) {
          return sink_.fail(a.line, "byte count " + std::to_string(n) + " exceeds file size");
        }
        bytes.clear();
        if (!decode_base64(text_, start, header_size_ + static_cast<std::size_t>(n), bytes)) {
          return sink_.fail(a.line, "invalid base64 appended data");
        }
      } else {
        const std::size_t available = text_.size() - start;
        const std::size_t take = std::min<std::size_t>(available, header_size_);
        bytes.assign(text_.begin() + static_cast<std::ptrdiff_t>(start),
                     text_.begin() + static_cast<std::ptrdiff_t>(start + take));
        if (bytes.size() == header_size_) {
          const std::uint64_t n = read_header_value(bytes.data());
          if (n > available - header_size_) {
            return sink_.fail(a.line, "byte count " + std::to_string(n) + " exceeds file size");
          }
          bytes.insert(bytes.end(), text_.begin() + static_cast<std::ptrdiff_t>(start + header_size_),
                       text_.begin() + static_cast<std::ptrdiff_t>(start + header_size_ + n));
        }
      }
    }
    if (bytes.size() < header_size_) return sink_.fail(a.line, "binary DataArray shorter than its header");
    const std::uint64_t n = read_header_value(bytes.data());
    if (n != bytes.size() - header_size_) {
      return sink_.fail(a.line, "binary DataArray declares " + std::to_string(n) + " bytes but holds " +
                                    std::to_string(bytes.size() - header_size_));
    }
    if (n % type_size(a.type) != 0) {
      return sink_.fail(a.line, "binary DataArray size " + std::to_string(n) + " is not a multiple of its " +
                                    std::string(a.type) + " values");
    }
    return true;
  }

  // One binary value of `type` at `p`, as a double and (for integers) an exact integer.
  void binary_value(std::string_view type, const std::uint8_t* p, double& real, std::int64_t& integer,
                    bool& integer_ok) const {
    const std::size_t size = type_size(type);
    std::uint8_t b[8] = {};
    for (std::size_t i = 0; i < size; ++i) b[i] = big_endian_ ? p[size - 1 - i] : p[i];
    // memcpy from a little-endian byte image (the host is little-endian on every supported target).
    integer_ok = true;
    if (type == "Float64") { double v; std::memcpy(&v, b, 8); real = v; integer_ok = false; return; }
    if (type == "Float32") { float v; std::memcpy(&v, b, 4); real = v; integer_ok = false; return; }
    if (type == "Int8") { std::int8_t v; std::memcpy(&v, b, 1); integer = v; }
    else if (type == "UInt8") { integer = b[0]; }
    else if (type == "Int16") { std::int16_t v; std::memcpy(&v, b, 2); integer = v; }
    else if (type == "UInt16") { std::uint16_t v; std::memcpy(&v, b, 2); integer = v; }
    else if (type == "Int32") { std::int32_t v; std::memcpy(&v, b, 4); integer = v; }
    else if (type == "UInt32") { std::uint32_t v; std::memcpy(&v, b, 4); integer = v; }
    else if (type == "Int64") { std::int64_t v; std::memcpy(&v, b, 8); integer = v; }
    else {
      std::uint64_t v;
      std::memcpy(&v, b, 8);
      if (v > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max())) integer_ok = false;
      integer = static_cast<std::int64_t>(v & 0x7FFFFFFFFFFFFFFFull);
    }
    real = static_cast<double>(integer);
  }

  // Decodes `a` into exactly `expected` values (or any number if expected is kAny).
  static constexpr std::uint64_t kAny = std::numeric_limits<std::uint64_t>::max();

  bool decode_reals(const DataArray& a, std::uint64_t expected, std::vector<double>& out) {
    out.clear();
    if (a.format == "ascii") {
      TokenReader tokens(text_.substr(a.content_begin, a.content_end - a.content_begin), '\0', a.content_line);
      std::string_view token;
      while (tokens.next(token)) {
        double v = 0;
        if (!parse_coordinate(sink_, tokens.line_number(), token, v)) return false;
        if (out.size() >= expected) return sink_.fail(tokens.line_number(), "more coordinates than NumberOfPoints declares");
        out.push_back(v);
      }
    } else {
      if (!array_bytes(a, bytes_)) return false;
      const std::size_t size = type_size(a.type);
      const std::size_t n = (bytes_.size() - header_size_) / size;
      out.reserve(n);
      for (std::size_t i = 0; i < n; ++i) {
        double real = 0;
        std::int64_t integer = 0;
        bool integer_ok = false;
        binary_value(a.type, bytes_.data() + header_size_ + i * size, real, integer, integer_ok);
        if (std::isnan(real)) return sink_.fail(a.line, "NaN coordinate (value " + std::to_string(i) + ")");
        if (std::isinf(real)) return sink_.fail(a.line, "infinite coordinate (value " + std::to_string(i) + ")");
        out.push_back(real);
      }
    }
    if (expected != kAny && out.size() != expected) {
      return sink_.fail(a.line, "expected " + std::to_string(expected) + " coordinate values, got " + std::to_string(out.size()));
    }
    return true;
  }

  bool decode_integers(const DataArray& a, std::uint64_t expected, std::string_view role,
                       std::vector<std::int64_t>& out) {
    out.clear();
    if (a.type == "Float32" || a.type == "Float64") {
      return sink_.fail(a.line, std::string(role) + " must have an integer type, got " + quote(a.type));
    }
    if (a.format == "ascii") {
      TokenReader tokens(text_.substr(a.content_begin, a.content_end - a.content_begin), '\0', a.content_line);
      std::string_view token;
      while (tokens.next(token)) {
        std::int64_t v = 0;
        if (!parse_i64(token, v)) return sink_.fail(tokens.line_number(), "expected an integer in " + std::string(role) + ", got " + quote(token));
        if (out.size() >= expected) return sink_.fail(tokens.line_number(), "more " + std::string(role) + " values than NumberOfCells declares");
        out.push_back(v);
      }
    } else {
      if (!array_bytes(a, bytes_)) return false;
      const std::size_t size = type_size(a.type);
      const std::size_t n = (bytes_.size() - header_size_) / size;
      out.reserve(n);
      for (std::size_t i = 0; i < n; ++i) {
        double real = 0;
        std::int64_t integer = 0;
        bool integer_ok = false;
        binary_value(a.type, bytes_.data() + header_size_ + i * size, real, integer, integer_ok);
        if (!integer_ok) return sink_.fail(a.line, "value out of range in " + std::string(role));
        out.push_back(integer);
      }
    }
    if (expected != kAny && out.size() != expected) {
      return sink_.fail(a.line, "expected " + std::to_string(expected) + " " + std::string(role) +
                                    " values, got " + std::to_string(out.size()));
    }
    return true;
  }

  bool read_piece(const Piece& piece, std::vector<std::string>& notices) {
    const char* missing = !piece.coordinates ? "Points" : !piece.connectivity ? "connectivity"
                        : !piece.offsets     ? "offsets" : !piece.types       ? "types" : nullptr;
    if (piece.points == 0 && piece.cells == 0) return true;
    if (missing != nullptr) return sink_.fail(piece.line, std::string("Piece has no ") + missing + " DataArray");
    if (piece.coordinates->components != 3) {
      return sink_.fail(piece.coordinates->line, "Points must have 3 components, got " +
                                                     std::to_string(piece.coordinates->components));
    }
    std::vector<double> xyz;
    if (!decode_reals(*piece.coordinates, piece.points * 3, xyz)) return false;
    const std::uint64_t base = mesh_.positions.size();
    for (std::uint64_t i = 0; i < piece.points; ++i) {
      mesh_.positions.push_back({xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]});
    }
    VtkCells cells;
    std::vector<std::int64_t> ends;
    if (!decode_integers(*piece.connectivity, kAny, "connectivity", cells.connectivity) ||
        !decode_integers(*piece.offsets, piece.cells, "offsets", ends) ||
        !decode_integers(*piece.types, piece.cells, "types", cells.types)) {
      return false;
    }
    // VTK's offsets are where each cell ends.
    for (std::size_t c = 0; c < ends.size(); ++c) {
      if (ends[c] < 0 || static_cast<std::uint64_t>(ends[c]) < cells.offsets.back() ||
          static_cast<std::uint64_t>(ends[c]) > cells.connectivity.size()) {
        return sink_.fail(piece.offsets->line, "offsets not increasing within the connectivity at cell " + std::to_string(c));
      }
      cells.offsets.push_back(static_cast<std::uint64_t>(ends[c]));
    }
    const std::size_t first_tet = mesh_.tets.size();
    if (!vtk_cells_to_tets(sink_, cells, piece.points, piece.types->line, mesh_.tets, notices)) return false;
    for (std::size_t t = first_tet; t < mesh_.tets.size(); ++t) {
      for (std::uint32_t& v : mesh_.tets[t]) v += static_cast<std::uint32_t>(base);
    }
    return true;
  }

  std::string_view text_;
  ErrorSink sink_;
  RawMesh mesh_;
  std::vector<XmlAttribute> attributes_;
  std::vector<Piece> pieces_;
  std::vector<std::uint8_t> bytes_;
  std::size_t counted_pos_ = 0;
  std::uint64_t counted_line_ = 1;
  std::size_t header_size_ = 4;
  bool big_endian_ = false;
  bool have_appended_ = false;
  bool appended_base64_ = false;
  std::size_t appended_begin_ = 0;
};

}  // namespace

ReadResult read_vtu(std::string_view text, std::string_view name) {
  return VtuReader(text, name).read();
}

std::string format_vtu(const RawMesh& mesh) {
  std::string out;
  out.reserve(512 + mesh.positions.size() * 60 + mesh.tets.size() * 48);
  out += "<?xml version=\"1.0\"?>\n"
         "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
         "  <UnstructuredGrid>\n    <Piece NumberOfPoints=\"";
  append_uint(out, mesh.positions.size());
  out += "\" NumberOfCells=\"";
  append_uint(out, mesh.tets.size());
  out += "\">\n      <Points>\n        <DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (const Vec3& p : mesh.positions) {
    out += "          ";
    append_point(out, p);
    out += '\n';
  }
  out += "        </DataArray>\n      </Points>\n      <Cells>\n"
         "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  for (const auto& tet : mesh.tets) {
    out += "         ";
    for (std::uint32_t v : tet) {
      out += ' ';
      append_uint(out, v);
    }
    out += '\n';
  }
  out += "        </DataArray>\n        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    out += "          ";
    append_uint(out, 4 * (t + 1));
    out += '\n';
  }
  out += "        </DataArray>\n        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) out += "          10\n";
  out += "        </DataArray>\n      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
  return out;
}

}  // namespace tetcut
