#include "vtk_legacy.hpp"

#include <cmath>
#include <optional>
#include <string>

#include "byte_order.hpp"

namespace tetcut::io_detail {

namespace {

struct LegacyType {
  std::size_t size = 0;
  bool real = false;
  bool is_unsigned = false;
};

// The data types of the legacy format ("bit" is packed, and only ever skipped).
std::optional<LegacyType> legacy_type(std::string_view name) {
  struct Entry {
    std::string_view name;
    LegacyType type;
  };
  static constexpr Entry kTypes[] = {
      {"unsigned_char", {1, false, true}}, {"char", {1, false, false}},
      {"unsigned_short", {2, false, true}}, {"short", {2, false, false}},
      {"unsigned_int", {4, false, true}}, {"int", {4, false, false}},
      {"unsigned_long", {8, false, true}}, {"long", {8, false, false}},
      {"float", {4, true, false}}, {"double", {8, true, false}},
      {"vtktypeint8", {1, false, false}}, {"vtktypeuint8", {1, false, true}},
      {"vtktypeint16", {2, false, false}}, {"vtktypeuint16", {2, false, true}},
      {"vtktypeint32", {4, false, false}}, {"vtktypeuint32", {4, false, true}},
      {"vtktypeint64", {8, false, false}}, {"vtktypeuint64", {8, false, true}},
      {"vtkidtype", {8, false, false}},
  };
  for (const Entry& e : kTypes) {
    if (iequals(name, e.name)) return e.type;
  }
  return std::nullopt;
}

constexpr ByteOrder kLegacyOrder = ByteOrder::kBig;  // "binary data must be placed into the file in big endian"

}  // namespace

bool VtkLegacyStream::read_header(std::string_view dataset) {
  LineReader lines(text_);
  std::string_view line;
  if (!lines.next(line) && text_.empty()) return sink_.fail(1, "empty file");
  constexpr std::string_view kMagic = "# vtk DataFile Version";
  line = trim(line);
  if (line.size() < kMagic.size() || !iequals(line.substr(0, kMagic.size()), kMagic)) {
    return sink_.fail(1, "not a legacy VTK file: expected '# vtk DataFile Version x.y', got " + quote(line));
  }
  const std::string_view version = trim(line.substr(kMagic.size()));
  double v = 0;
  if (!parse_double(version, v)) return sink_.fail(1, "bad VTK file version " + quote(version));
  version5_ = v >= 5.0;
  if (!lines.next(line)) return sink_.fail(lines.line_number(), "unexpected end of file: missing title line");
  if (!lines.next(line)) return sink_.fail(lines.line_number(), "unexpected end of file: missing ASCII/BINARY line");
  if (iequals(trim(line), "BINARY")) {
    binary_ = true;
  } else if (!iequals(trim(line), "ASCII")) {
    return sink_.fail(lines.line_number(), "expected ASCII or BINARY, got " + quote(trim(line)));
  }
  tokens_ = TokenReader(text_.substr(lines.offset()), '\0', lines.line_number() + 1);
  std::string_view token;
  if (!next_keyword("DATASET") || !next(token, "a dataset type")) return false;
  if (!iequals(token, dataset)) {
    return sink_.fail(tokens_.line_number(), "dataset " + quote(token) + " is not " +
                                                 (dataset == "POLYDATA" ? "POLYDATA" : "an " + std::string(dataset)));
  }
  return true;
}

bool VtkLegacyStream::next(std::string_view& token, std::string_view what) {
  if (!tokens_.next(token)) {
    return sink_.fail(tokens_.line_number(), "unexpected end of file: expected " + std::string(what));
  }
  return true;
}

bool VtkLegacyStream::next_keyword(std::string_view keyword) {
  std::string_view token;
  if (!next(token, keyword)) return false;
  if (!iequals(token, keyword)) {
    return sink_.fail(tokens_.line_number(), "expected " + std::string(keyword) + ", got " + quote(token));
  }
  return true;
}

bool VtkLegacyStream::next_count(std::string_view what, std::uint64_t& count) {
  std::string_view token;
  return next(token, what) && parse_count(sink_, tokens_.line_number(), token, tokens_.remaining_bytes(), count);
}

bool VtkLegacyStream::next_int(std::string_view what, std::int64_t& value) {
  std::string_view token;
  if (!next(token, what)) return false;
  if (!parse_i64(token, value)) {
    return sink_.fail(tokens_.line_number(), "expected " + std::string(what) + ", got " + quote(token));
  }
  return true;
}

bool VtkLegacyStream::binary_block(std::uint64_t n, std::string_view type, std::string_view what,
                                   std::string_view& bytes) {
  const std::optional<LegacyType> t = legacy_type(type);
  if (!t) return sink_.fail(tokens_.line_number(), "unknown data type " + quote(type) + " for " + std::string(what));
  const std::uint64_t line = tokens_.line_number();
  const std::uint64_t size = n * t->size;  // n is bounded by the file size: no overflow
  if (size > tokens_.remaining_bytes() || !tokens_.take_binary(static_cast<std::size_t>(size), bytes)) {
    return sink_.fail(line, "binary " + std::string(what) + ": " + std::to_string(n) + " " + std::string(type) +
                                " values need " + std::to_string(size) + " bytes after this line, the file has fewer");
  }
  return true;
}

bool VtkLegacyStream::read_points(std::vector<Vec3>& positions) {
  std::uint64_t n = 0;
  std::string_view type;
  if (!next_count("the number of points", n) || !next(type, "the point data type")) return false;
  if (binary_) {
    const std::optional<LegacyType> t = legacy_type(type);
    std::string_view bytes;
    if (!binary_block(3 * n, type, "POINTS", bytes)) return false;
    const auto* p = reinterpret_cast<const unsigned char*>(bytes.data());
    positions.reserve(n);
    for (std::uint64_t i = 0; i < n; ++i) {
      double c[3];
      for (int k = 0; k < 3; ++k, p += t->size) {
        c[k] = t->real ? (t->size == 8 ? load_f64(p, kLegacyOrder) : load_f32(p, kLegacyOrder))
               : t->is_unsigned ? static_cast<double>(load_uint(p, t->size, kLegacyOrder))
                                : static_cast<double>(load_int(p, t->size, kLegacyOrder));
        if (!std::isfinite(c[k])) {
          return sink_.fail(tokens_.line_number(), std::string(std::isnan(c[k]) ? "NaN" : "infinite") +
                                                       " coordinate (point " + std::to_string(i) + ")");
        }
      }
      positions.push_back({c[0], c[1], c[2]});
    }
    return true;
  }
  positions.reserve(n);
  for (std::uint64_t i = 0; i < n; ++i) {
    Vec3 p;
    double* c[3] = {&p.x, &p.y, &p.z};
    for (double* value : c) {
      std::string_view token;
      if (!next(token, "point coordinates (" + std::to_string(n) + " points declared)") ||
          !parse_coordinate(sink_, tokens_.line_number(), token, *value)) {
        return false;
      }
    }
    positions.push_back(p);
  }
  return true;
}

bool VtkLegacyStream::read_ints(std::uint64_t n, std::string_view type, std::string_view what,
                                std::vector<std::int64_t>& out) {
  out.clear();
  if (binary_) {
    const std::optional<LegacyType> t = legacy_type(type);
    if (t && t->real) return sink_.fail(tokens_.line_number(), std::string(what) + " must be integers, got " + quote(type));
    std::string_view bytes;
    if (!binary_block(n, type, what, bytes)) return false;
    const auto* p = reinterpret_cast<const unsigned char*>(bytes.data());
    out.reserve(n);
    for (std::uint64_t i = 0; i < n; ++i, p += t->size) {
      if (t->is_unsigned) {
        const std::uint64_t u = load_uint(p, t->size, kLegacyOrder);
        if (u > static_cast<std::uint64_t>(INT64_MAX)) return sink_.fail(tokens_.line_number(), "value out of range in " + std::string(what));
        out.push_back(static_cast<std::int64_t>(u));
      } else {
        out.push_back(load_int(p, t->size, kLegacyOrder));
      }
    }
    return true;
  }
  out.reserve(n);
  for (std::uint64_t i = 0; i < n; ++i) {
    std::int64_t v = 0;
    if (!next_int(std::string(what) + " values (" + std::to_string(n) + " declared)", v)) return false;
    out.push_back(v);
  }
  return true;
}

bool VtkLegacyStream::read_cell_list(std::string_view section, VtkCells& cells) {
  return version5_ ? read_cells_v5(cells) : read_cells_v4(section, cells);
}

bool VtkLegacyStream::read_cells_v4(std::string_view section, VtkCells& cells) {
  std::uint64_t n = 0;
  std::uint64_t size = 0;
  if (!next_count("the number of cells", n) || !next_count("the cell list size", size)) return false;
  const std::uint64_t size_line = tokens_.line_number();
  std::vector<std::int64_t> values;
  if (binary_ && !read_ints(size, "int", section, values)) return false;
  cells.offsets.reserve(n + 1);
  if (!binary_) cells.lines.reserve(n);
  cells.connectivity.reserve(size);
  std::uint64_t used = 0;
  for (std::uint64_t c = 0; c < n; ++c) {
    std::int64_t k = 0;
    if (binary_) {
      if (used >= size) k = -1;
      else k = values[used];
    } else {
      if (!next_int("a cell's number of points", k)) return false;
      cells.lines.push_back(tokens_.line_number());
    }
    if (k < 0 || static_cast<std::uint64_t>(k) > size - std::min(size, used + 1)) {
      return sink_.fail(tokens_.line_number(), "cell " + std::to_string(c) + " with " + std::to_string(k) +
                                                   " points overruns the declared cell list size " + std::to_string(size));
    }
    for (std::int64_t j = 0; j < k; ++j) {
      std::int64_t id = 0;
      if (binary_) id = values[used + 1 + static_cast<std::uint64_t>(j)];
      else if (!next_int("a point id", id)) return false;
      cells.connectivity.push_back(id);
    }
    used += 1 + static_cast<std::uint64_t>(k);
    cells.offsets.push_back(cells.connectivity.size());
  }
  if (used != size) {
    return sink_.fail(size_line, "cell list size " + std::to_string(size) + " does not match the " +
                                     std::to_string(used) + " values of the cells");
  }
  return true;
}

bool VtkLegacyStream::read_cells_v5(VtkCells& cells) {
  std::uint64_t num_offsets = 0;
  std::uint64_t size = 0;
  if (!next_count("the number of offsets", num_offsets) || !next_count("the connectivity size", size)) return false;
  const std::uint64_t header_line = tokens_.line_number();
  std::vector<std::int64_t> offsets;
  std::string_view type;
  if (!next_keyword("OFFSETS") || !next(type, "the array data type") || !read_ints(num_offsets, type, "OFFSETS", offsets)) {
    return false;
  }
  const std::uint64_t offsets_line = tokens_.line_number();
  if (!next_keyword("CONNECTIVITY") || !next(type, "the array data type") ||
      !read_ints(size, type, "CONNECTIVITY", cells.connectivity)) {
    return false;
  }
  if (num_offsets == 0 || offsets[0] != 0) return sink_.fail(header_line, "OFFSETS must start with 0");
  cells.offsets.assign(1, 0);
  for (std::size_t i = 1; i < offsets.size(); ++i) {
    if (offsets[i] < offsets[i - 1] || static_cast<std::uint64_t>(offsets[i]) > size) {
      return sink_.fail(offsets_line, "OFFSETS not increasing within the connectivity size at entry " + std::to_string(i));
    }
    cells.offsets.push_back(static_cast<std::uint64_t>(offsets[i]));
  }
  return true;
}

bool VtkLegacyStream::read_cell_types(VtkCells& cells) {
  std::uint64_t n = 0;
  if (!next_count("the number of cell types", n)) return false;
  if (n != cells.offsets.size() - 1) {
    return sink_.fail(tokens_.line_number(), "CELL_TYPES declares " + std::to_string(n) + " cells, CELLS " +
                                                 std::to_string(cells.offsets.size() - 1));
  }
  return read_ints(n, "int", "cell type", cells.types);
}

bool VtkLegacyStream::skip_field() {
  std::string_view name;
  std::uint64_t arrays = 0;
  if (!next(name, "the field name") || !next_count("the number of field arrays", arrays)) return false;
  for (std::uint64_t a = 0; a < arrays; ++a) {
    std::string_view array_name;
    std::string_view type;
    std::uint64_t components = 0;
    std::uint64_t tuples = 0;
    if (!next(array_name, "a field array name") || !next_count("the number of components", components) ||
        !next_count("the number of tuples", tuples) || !next(type, "the field data type")) {
      return false;
    }
    if (tuples != 0 && components > tokens_.remaining_bytes() / tuples) {
      return sink_.fail(tokens_.line_number(), "field array size exceeds file size");
    }
    if (binary_) {
      std::string_view bytes;
      // "bit" arrays are packed 8 values a byte.
      const std::uint64_t n = components * tuples;
      if (iequals(type, "bit") ? !binary_block((n + 7) / 8, "char", "FIELD data", bytes)
                               : !binary_block(n, type, "FIELD data", bytes)) {
        return false;
      }
    } else {
      for (std::uint64_t i = 0; i < components * tuples; ++i) {
        std::string_view value;
        if (!next(value, "field values")) return false;
      }
    }
    std::string_view peek;
    if (tokens_.peek(peek) && iequals(peek, "METADATA")) {
      tokens_.next(peek);
      tokens_.skip_past_blank_line();
    }
  }
  return true;
}

bool VtkLegacyStream::read_or_skip(std::string_view name, std::uint64_t components, std::uint64_t n,
                                   std::string_view type, std::uint64_t line, LabelArray* label) {
  const int rank = label_array_rank(name);
  if (label != nullptr && rank >= 0 && (label->rank < 0 || rank < label->rank)) {
    if (n > tokens_.remaining_bytes() / 2) {  // an ASCII value takes 2 bytes at least, a binary one more
      return sink_.fail(line, "cell data " + quote(name) + ": " + std::to_string(n) + " values exceed the file size");
    }
    if (components != 1) {
      return sink_.fail(line, "cell data " + quote(name) + " has " + std::to_string(components) +
                                  " components, a label has 1");
    }
    if (!read_ints(n, type, "cell data " + quote(name), label->values)) return false;
    label->name = std::string(name);
    label->rank = rank;
    label->line = line;
    return true;
  }
  if (n != 0 && components > tokens_.remaining_bytes() / n) {
    return sink_.fail(tokens_.line_number(), "data array " + quote(name) + " exceeds file size");
  }
  const std::uint64_t values = components * n;
  if (binary_) {
    std::string_view bytes;
    return iequals(type, "bit") ? binary_block((values + 7) / 8, "char", "attribute data", bytes)
                                : binary_block(values, type, "attribute data", bytes);
  }
  for (std::uint64_t i = 0; i < values; ++i) {
    std::string_view value;
    if (!next(value, "values of " + quote(name))) return false;
  }
  return true;
}

bool VtkLegacyStream::read_attributes(std::uint64_t n, LabelArray* label) {
  std::string_view keyword;
  while (tokens_.peek(keyword)) {
    std::string_view name;
    std::string_view type;
    if (iequals(keyword, "SCALARS")) {
      tokens_.next(keyword);
      const std::uint64_t header_line = tokens_.line_number();
      if (!next(name, "the SCALARS name") || !next(type, "the SCALARS data type")) return false;
      std::uint64_t components = 1;
      std::string_view peek;
      std::int64_t k = 0;
      if (tokens_.peek(peek) && parse_i64(peek, k)) {
        if (k < 1 || k > 4) return sink_.fail(tokens_.line_number(), "SCALARS components must be 1 to 4, got " + quote(peek));
        tokens_.next(peek);
        components = static_cast<std::uint64_t>(k);
      }
      if (tokens_.peek(peek) && iequals(peek, "LOOKUP_TABLE")) {
        tokens_.next(peek);
        if (!next(peek, "the lookup table name")) return false;
      }
      if (!read_or_skip(name, components, n, type, header_line, label)) return false;
    } else if (iequals(keyword, "VECTORS") || iequals(keyword, "NORMALS") || iequals(keyword, "TENSORS")) {
      tokens_.next(keyword);
      if (!next(name, "the array name") || !next(type, "the data type")) return false;
      if (!read_or_skip(name, iequals(keyword, "TENSORS") ? 9 : 3, n, type, tokens_.line_number(), nullptr)) return false;
    } else if (iequals(keyword, "FIELD")) {
      tokens_.next(keyword);
      std::uint64_t arrays = 0;
      if (!next(name, "the field name") || !next_count("the number of field arrays", arrays)) return false;
      for (std::uint64_t a = 0; a < arrays; ++a) {
        std::uint64_t components = 0;
        std::uint64_t tuples = 0;
        if (!next(name, "a field array name") || !next_count("the number of components", components) ||
            !next_count("the number of tuples", tuples) || !next(type, "the field data type")) {
          return false;
        }
        if (tuples != n && label_array_rank(name) >= 0 && label != nullptr) {
          return sink_.fail(tokens_.line_number(), "cell data " + quote(name) + " has " + std::to_string(tuples) +
                                                       " values for " + std::to_string(n) + " cells");
        }
        if (!read_or_skip(name, components, tuples, type, tokens_.line_number(), label)) return false;
        std::string_view peek;
        if (tokens_.peek(peek) && iequals(peek, "METADATA")) {
          tokens_.next(peek);
          tokens_.skip_past_blank_line();
        }
      }
    } else {
      return true;
    }
    std::string_view peek;
    if (tokens_.peek(peek) && iequals(peek, "METADATA")) {
      tokens_.next(peek);
      tokens_.skip_past_blank_line();
    }
  }
  return true;
}

}  // namespace tetcut::io_detail
