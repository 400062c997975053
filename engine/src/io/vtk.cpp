// Legacy VTK ASCII, DATASET UNSTRUCTURED_GRID. Free format after the 3 header lines: POINTS,
// CELLS (version < 5: "k id..." records; version 5.x: OFFSETS and CONNECTIVITY arrays),
// CELL_TYPES. FIELD and METADATA blocks are skipped; POINT_DATA / CELL_DATA end the reading.
#include <string>

#include "tetcut/io.hpp"
#include "text_reader.hpp"
#include "vtk_cells.hpp"

namespace tetcut {

namespace {

using namespace io_detail;

class VtkReader {
 public:
  VtkReader(std::string_view text, std::string_view name) : text_(text), sink_(name) {}

  ReadResult read() {
    std::vector<std::string> notices;
    if (read_header()) read_body(notices);
    return make_result(sink_, std::move(mesh_), std::move(notices));
  }

 private:
  bool read_header() {
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
      return sink_.fail(lines.line_number(), "binary legacy VTK is not supported; save as ASCII");
    }
    if (!iequals(trim(line), "ASCII")) {
      return sink_.fail(lines.line_number(), "expected ASCII or BINARY, got " + quote(trim(line)));
    }
    tokens_ = TokenReader(text_.substr(lines.offset()), '\0', lines.line_number() + 1);
    return true;
  }

  bool next(std::string_view& token, std::string_view what) {
    if (!tokens_.next(token)) {
      return sink_.fail(tokens_.line_number(), "unexpected end of file: expected " + std::string(what));
    }
    return true;
  }

  bool next_keyword(std::string_view keyword) {
    std::string_view token;
    if (!next(token, keyword)) return false;
    if (!iequals(token, keyword)) {
      return sink_.fail(tokens_.line_number(), "expected " + std::string(keyword) + ", got " + quote(token));
    }
    return true;
  }

  bool next_count(std::string_view what, std::uint64_t& count) {
    std::string_view token;
    return next(token, what) &&
           parse_count(sink_, tokens_.line_number(), token, tokens_.remaining_bytes(), count);
  }

  bool next_int(std::string_view what, std::int64_t& value) {
    std::string_view token;
    if (!next(token, what)) return false;
    if (!parse_i64(token, value)) {
      return sink_.fail(tokens_.line_number(), "expected " + std::string(what) + ", got " + quote(token));
    }
    return true;
  }

  void read_body(std::vector<std::string>& notices) {
    if (!next_keyword("DATASET")) return;
    std::string_view token;
    if (!next(token, "a dataset type")) return;
    if (!iequals(token, "UNSTRUCTURED_GRID")) {
      sink_.fail(tokens_.line_number(), "dataset " + quote(token) + " is not an UNSTRUCTURED_GRID");
      return;
    }
    bool have_points = false;
    bool have_cells = false;
    bool have_types = false;
    VtkCells cells;
    while (!sink_.failed() && tokens_.next(token)) {
      if (iequals(token, "POINTS")) {
        if (have_points) { sink_.fail(tokens_.line_number(), "second POINTS section"); return; }
        read_points();
        have_points = true;
      } else if (iequals(token, "METADATA")) {
        tokens_.skip_past_blank_line();
      } else if (iequals(token, "FIELD")) {
        skip_field();
      } else if (iequals(token, "CELLS")) {
        if (!have_points) { sink_.fail(tokens_.line_number(), "CELLS before POINTS"); return; }
        if (have_cells) { sink_.fail(tokens_.line_number(), "second CELLS section"); return; }
        if (version5_) read_cells_v5(cells);
        else read_cells_v4(cells);
        have_cells = true;
      } else if (iequals(token, "CELL_TYPES")) {
        if (!have_cells) { sink_.fail(tokens_.line_number(), "CELL_TYPES before CELLS"); return; }
        if (have_types) { sink_.fail(tokens_.line_number(), "second CELL_TYPES section"); return; }
        read_types(cells);
        have_types = true;
      } else if (iequals(token, "POINT_DATA") || iequals(token, "CELL_DATA")) {
        break;  // attributes: not part of the mesh
      } else {
        sink_.fail(tokens_.line_number(), "unexpected keyword " + quote(token));
      }
    }
    if (sink_.failed()) return;
    const std::uint64_t end_line = tokens_.line_number();
    if (!have_points) { sink_.fail(end_line, "missing POINTS section"); return; }
    if (!have_cells) { sink_.fail(end_line, "missing CELLS section"); return; }
    if (!have_types) { sink_.fail(end_line, "missing CELL_TYPES section"); return; }
    vtk_cells_to_tets(sink_, cells, mesh_.positions.size(), end_line, mesh_.tets, notices);
  }

  void read_points() {
    std::uint64_t n = 0;
    std::string_view type;
    if (!next_count("the number of points", n) || !next(type, "the point data type")) return;
    mesh_.positions.reserve(n);
    for (std::uint64_t i = 0; i < n; ++i) {
      Vec3 p;
      double* c[3] = {&p.x, &p.y, &p.z};
      for (double* value : c) {
        std::string_view token;
        if (!next(token, "point coordinates (" + std::to_string(n) + " points declared)") ||
            !parse_coordinate(sink_, tokens_.line_number(), token, *value)) {
          return;
        }
      }
      mesh_.positions.push_back(p);
    }
  }

  void read_cells_v4(VtkCells& cells) {
    std::uint64_t n = 0;
    std::uint64_t size = 0;
    if (!next_count("the number of cells", n) || !next_count("the cell list size", size)) return;
    const std::uint64_t size_line = tokens_.line_number();
    cells.offsets.reserve(n + 1);
    cells.lines.reserve(n);
    cells.connectivity.reserve(size);
    std::uint64_t used = 0;
    for (std::uint64_t c = 0; c < n; ++c) {
      std::int64_t k = 0;
      if (!next_int("a cell's number of points", k)) return;
      cells.lines.push_back(tokens_.line_number());
      if (k < 0 || static_cast<std::uint64_t>(k) > size - std::min(size, used + 1)) {
        sink_.fail(tokens_.line_number(), "cell " + std::to_string(c) + " with " + std::to_string(k) +
                                              " points overruns the declared cell list size " +
                                              std::to_string(size));
        return;
      }
      for (std::int64_t j = 0; j < k; ++j) {
        std::int64_t id = 0;
        if (!next_int("a point id", id)) return;
        cells.connectivity.push_back(id);
      }
      used += 1 + static_cast<std::uint64_t>(k);
      cells.offsets.push_back(cells.connectivity.size());
    }
    if (used != size) {
      sink_.fail(size_line, "cell list size " + std::to_string(size) + " does not match the " +
                                std::to_string(used) + " values of the cells");
    }
  }

  bool read_int_array(std::string_view keyword, std::uint64_t n, std::vector<std::int64_t>& out) {
    std::string_view type;
    if (!next_keyword(keyword) || !next(type, "the array data type")) return false;
    out.reserve(n);
    for (std::uint64_t i = 0; i < n; ++i) {
      std::int64_t v = 0;
      if (!next_int(std::string(keyword) + " values (" + std::to_string(n) + " declared)", v)) return false;
      out.push_back(v);
    }
    return true;
  }

  void read_cells_v5(VtkCells& cells) {
    std::uint64_t num_offsets = 0;
    std::uint64_t size = 0;
    if (!next_count("the number of offsets", num_offsets) ||
        !next_count("the connectivity size", size)) {
      return;
    }
    const std::uint64_t header_line = tokens_.line_number();
    std::vector<std::int64_t> offsets;
    if (!read_int_array("OFFSETS", num_offsets, offsets)) return;
    const std::uint64_t offsets_line = tokens_.line_number();
    if (!read_int_array("CONNECTIVITY", size, cells.connectivity)) return;
    if (num_offsets == 0 || offsets[0] != 0) {
      sink_.fail(header_line, "OFFSETS must start with 0");
      return;
    }
    cells.offsets.assign(1, 0);
    for (std::size_t i = 1; i < offsets.size(); ++i) {
      if (offsets[i] < offsets[i - 1] || static_cast<std::uint64_t>(offsets[i]) > size) {
        sink_.fail(offsets_line, "OFFSETS not increasing within the connectivity size at entry " + std::to_string(i));
        return;
      }
      cells.offsets.push_back(static_cast<std::uint64_t>(offsets[i]));
    }
  }

  void read_types(VtkCells& cells) {
    std::uint64_t n = 0;
    if (!next_count("the number of cell types", n)) return;
    if (n != cells.offsets.size() - 1) {
      sink_.fail(tokens_.line_number(), "CELL_TYPES declares " + std::to_string(n) + " cells, CELLS " +
                                            std::to_string(cells.offsets.size() - 1));
      return;
    }
    cells.types.reserve(n);
    for (std::uint64_t i = 0; i < n; ++i) {
      std::int64_t t = 0;
      if (!next_int("a cell type", t)) return;
      cells.types.push_back(t);
    }
  }

  void skip_field() {
    std::string_view name;
    std::uint64_t arrays = 0;
    if (!next(name, "the field name") || !next_count("the number of field arrays", arrays)) return;
    for (std::uint64_t a = 0; a < arrays; ++a) {
      std::string_view array_name;
      std::string_view type;
      std::uint64_t components = 0;
      std::uint64_t tuples = 0;
      if (!next(array_name, "a field array name") ||
          !next_count("the number of components", components) ||
          !next_count("the number of tuples", tuples) || !next(type, "the field data type")) {
        return;
      }
      if (tuples != 0 && components > tokens_.remaining_bytes() / tuples) {
        sink_.fail(tokens_.line_number(), "field array size exceeds file size");
        return;
      }
      for (std::uint64_t i = 0; i < components * tuples; ++i) {
        std::string_view value;
        if (!next(value, "field values")) return;
      }
      std::string_view peek;
      if (tokens_.peek(peek) && iequals(peek, "METADATA")) {
        tokens_.next(peek);
        tokens_.skip_past_blank_line();
      }
    }
  }

  std::string_view text_;
  ErrorSink sink_;
  TokenReader tokens_{std::string_view()};
  bool version5_ = false;
  RawMesh mesh_;
};

}  // namespace

ReadResult read_vtk(std::string_view text, std::string_view name) {
  return VtkReader(text, name).read();
}

std::string format_vtk(const RawMesh& mesh) {
  std::string out;
  out.reserve(128 + mesh.positions.size() * 60 + mesh.tets.size() * 40);
  out += "# vtk DataFile Version 3.0\ntetcut mesh\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS ";
  append_uint(out, mesh.positions.size());
  out += " double\n";
  for (const Vec3& p : mesh.positions) {
    append_point(out, p);
    out += '\n';
  }
  out += "CELLS ";
  append_uint(out, mesh.tets.size());
  out += ' ';
  append_uint(out, mesh.tets.size() * 5);
  out += '\n';
  for (const auto& tet : mesh.tets) {
    out += '4';
    for (std::uint32_t v : tet) {
      out += ' ';
      append_uint(out, v);
    }
    out += '\n';
  }
  out += "CELL_TYPES ";
  append_uint(out, mesh.tets.size());
  out += '\n';
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) out += "10\n";
  return out;
}

}  // namespace tetcut
