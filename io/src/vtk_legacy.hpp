// What the legacy VTK readers (UNSTRUCTURED_GRID in vtk.cpp, POLYDATA in vtk_polydata.cpp)
// share: the three header lines and DATASET, free-format keywords and counts, and the data of a
// section either as ASCII tokens or, in a BINARY file, as big-endian values (the format's byte
// order whatever the host) right after the keyword line. Binary data is reported at the line of
// its keyword. Internal to the engine (not installed).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "tetcut/vec3.hpp"
#include "text_reader.hpp"
#include "vtk_cells.hpp"

namespace tetcut::io_detail {

class VtkLegacyStream {
 public:
  VtkLegacyStream(std::string_view text, ErrorSink& sink) : text_(text), sink_(sink) {}

  // "# vtk DataFile Version x.y", the title, ASCII or BINARY, then "DATASET <dataset>".
  bool read_header(std::string_view dataset);

  [[nodiscard]] bool binary() const { return binary_; }
  [[nodiscard]] std::uint64_t line() const { return tokens_.line_number(); }
  // The next token; false at the end of the file.
  bool next_token(std::string_view& token) { return tokens_.next(token); }
  bool peek_token(std::string_view& token) { return tokens_.peek(token); }
  bool next(std::string_view& token, std::string_view what);
  bool next_keyword(std::string_view keyword);
  bool next_count(std::string_view what, std::uint64_t& count);

  // "POINTS n type" (after the keyword) and its coordinates.
  bool read_points(std::vector<Vec3>& positions);
  // A cell list after its keyword (CELLS, POLYGONS, TRIANGLE_STRIPS, ...): "n size" and n
  // records "k id..." before file version 5; "n_offsets size", OFFSETS and CONNECTIVITY after.
  bool read_cell_list(std::string_view section, VtkCells& cells);
  // "CELL_TYPES n" (after the keyword) and the types, for cells read by read_cell_list.
  bool read_cell_types(VtkCells& cells);
  // FIELD data (after the keyword): skipped.
  bool skip_field();
  // The attribute arrays after "POINT_DATA n" or "CELL_DATA n" (after the count): SCALARS and
  // FIELD arrays are read or skipped, VECTORS, NORMALS and TENSORS skipped; reading stops
  // before any other keyword. The label array (kLabelArrayNames, the best ranked present) goes
  // to `label_values` with its name and line; `label_values` null: everything is skipped.
  struct LabelArray {
    std::string name;
    int rank = -1;
    std::uint64_t line = 0;
    std::vector<std::int64_t> values;
  };
  bool read_attributes(std::uint64_t n, LabelArray* label);
  // METADATA (after the keyword): skipped up to its blank line.
  void skip_metadata() { tokens_.skip_past_blank_line(); }

 private:
  bool next_int(std::string_view what, std::int64_t& value);
  // The bytes of `n` values of `type` after the current line; `what` names them in errors.
  bool binary_block(std::uint64_t n, std::string_view type, std::string_view what, std::string_view& bytes);
  bool read_ints(std::uint64_t n, std::string_view type, std::string_view what, std::vector<std::int64_t>& out);
  bool read_cells_v4(std::string_view section, VtkCells& cells);
  bool read_cells_v5(VtkCells& cells);
  // `n` values of `type`: skipped, or read into `label` when it names a better label array.
  bool read_or_skip(std::string_view name, std::uint64_t components, std::uint64_t n, std::string_view type,
                    std::uint64_t line, LabelArray* label);

  std::string_view text_;
  ErrorSink& sink_;
  TokenReader tokens_{std::string_view()};
  bool version5_ = false;
  bool binary_ = false;
};

}  // namespace tetcut::io_detail
