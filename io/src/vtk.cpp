// Legacy VTK, DATASET UNSTRUCTURED_GRID, ASCII or BINARY (vtk_legacy.hpp reads the sections):
// POINTS, CELLS (version < 5: "k id..." records; version 5.x: OFFSETS and CONNECTIVITY arrays),
// CELL_TYPES. FIELD and METADATA blocks are skipped. POINT_DATA is skipped; CELL_DATA gives the
// tets' labels (RawMesh::labels) from the first array named as kLabelArrayNames says
// (vtk_cells.hpp: "label", "gmsh:physical", "medit:ref", "CellEntityIds"; SCALARS or FIELD), and
// the reading ends at an attribute kind neither reads. A labelled mesh is written with CELL_DATA
// and "SCALARS label int" (what meshio reads back as cell_data["label"]).
// Written as version 3.0, ASCII or BINARY (big-endian, as the format says).
#include <string>

#include "byte_order.hpp"
#include "tetcut/io.hpp"
#include "text_reader.hpp"
#include "vtk_cells.hpp"
#include "vtk_legacy.hpp"

namespace tetcut {

namespace {

using namespace io_detail;

class VtkReader {
 public:
  VtkReader(std::string_view text, std::string_view name) : sink_(name), stream_(text, sink_) {}

  ReadResult read() {
    std::vector<std::string> notices;
    if (stream_.read_header("UNSTRUCTURED_GRID")) read_body(notices);
    if (!sink_.failed()) ignored_.emit(notices);
    return make_result(sink_, std::move(mesh_), std::move(notices), &ignored_);
  }

 private:
  void read_body(std::vector<std::string>& notices) {
    bool have_points = false;
    bool have_cells = false;
    bool have_types = false;
    VtkCells cells;
    VtkLegacyStream::LabelArray label;
    std::string_view token;
    while (!sink_.failed() && stream_.next_token(token)) {
      if (iequals(token, "POINTS")) {
        if (have_points) { sink_.fail(stream_.line(), "second POINTS section"); return; }
        stream_.read_points(mesh_.positions);
        have_points = true;
      } else if (iequals(token, "METADATA")) {
        stream_.skip_metadata();
      } else if (iequals(token, "FIELD")) {
        stream_.skip_field();
      } else if (iequals(token, "CELLS")) {
        if (!have_points) { sink_.fail(stream_.line(), "CELLS before POINTS"); return; }
        if (have_cells) { sink_.fail(stream_.line(), "second CELLS section"); return; }
        stream_.read_cell_list("CELLS", cells);
        have_cells = true;
      } else if (iequals(token, "CELL_TYPES")) {
        if (!have_cells) { sink_.fail(stream_.line(), "CELL_TYPES before CELLS"); return; }
        if (have_types) { sink_.fail(stream_.line(), "second CELL_TYPES section"); return; }
        stream_.read_cell_types(cells);
        have_types = true;
      } else if (iequals(token, "POINT_DATA") || iequals(token, "CELL_DATA")) {
        const bool cell_data = iequals(token, "CELL_DATA");
        // A count only: nothing is allocated for it but a label array's, which is held to the
        // file's size where it is read (a bare "CELL_DATA 3" at the end of a file is fine).
        std::uint64_t n = 0;
        std::string_view count;
        if (!stream_.next(count, "the number of values")) return;
        if (!parse_u64(count, n)) {
          sink_.fail(stream_.line(), "expected the number of values, got " + quote(count));
          return;
        }
        if (cell_data && have_types && n != cells.types.size()) {
          sink_.fail(stream_.line(), "CELL_DATA declares " + std::to_string(n) + " values for " +
                                         std::to_string(cells.types.size()) + " cells");
          return;
        }
        if (!stream_.read_attributes(n, cell_data ? &label : nullptr)) return;
        std::string_view next;
        if (!stream_.peek_token(next) || !(iequals(next, "POINT_DATA") || iequals(next, "CELL_DATA"))) break;
      } else {
        sink_.fail(stream_.line(), "unexpected keyword " + quote(token));
      }
    }
    if (sink_.failed()) return;
    const std::uint64_t end_line = stream_.line();
    if (!have_points) { sink_.fail(end_line, "missing POINTS section"); return; }
    if (!have_cells) { sink_.fail(end_line, "missing CELLS section"); return; }
    if (!have_types) { sink_.fail(end_line, "missing CELL_TYPES section"); return; }
    std::vector<std::uint32_t> tet_cells;
    if (!vtk_cells_to_tets(sink_, cells, mesh_.positions.size(), end_line, mesh_.tets, ignored_, notices, &tet_cells)) {
      return;
    }
    if (label.rank >= 0) {
      labels_from_cell_data(sink_, label.line, label.name, label.values, cells.types.size(), tet_cells, mesh_.labels);
    }
  }

  ErrorSink sink_;
  VtkLegacyStream stream_;
  RawMesh mesh_;
  IgnoredTally ignored_;
};

void append_header(std::string& out, const RawMesh& mesh, bool binary) {
  out += "# vtk DataFile Version 3.0\ntetcut mesh\n";
  out += binary ? "BINARY" : "ASCII";
  out += "\nDATASET UNSTRUCTURED_GRID\nPOINTS ";
  append_uint(out, mesh.positions.size());
  out += " double\n";
}

void append_cells_line(std::string& out, const RawMesh& mesh) {
  out += "CELLS ";
  append_uint(out, mesh.tets.size());
  out += ' ';
  append_uint(out, mesh.tets.size() * 5);
  out += '\n';
}

void append_types_line(std::string& out, const RawMesh& mesh) {
  out += "CELL_TYPES ";
  append_uint(out, mesh.tets.size());
  out += '\n';
}

// The tets' labels as a SCALARS array of cell data ("int": VTK's legacy readers and meshio).
void append_label_header(std::string& out, const RawMesh& mesh) {
  out += "CELL_DATA ";
  append_uint(out, mesh.tets.size());
  out += "\nSCALARS label int 1\nLOOKUP_TABLE default\n";
}

}  // namespace

ReadResult read_vtk(std::string_view text, std::string_view name) {
  return VtkReader(text, name).read();
}

std::string format_vtk(const RawMesh& mesh) {
  std::string out;
  out.reserve(128 + mesh.positions.size() * 60 + mesh.tets.size() * 40);
  append_header(out, mesh, false);
  append_point_lines(out, mesh.positions);
  append_cells_line(out, mesh);
  for (const auto& tet : mesh.tets) {
    out += '4';
    for (std::uint32_t v : tet) {
      out += ' ';
      append_uint(out, v);
    }
    out += '\n';
  }
  append_types_line(out, mesh);
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) out += "10\n";
  if (mesh.labelled()) {
    append_label_header(out, mesh);
    for (std::uint32_t label : mesh.labels) {
      append_uint(out, label);
      out += '\n';
    }
  }
  return out;
}

std::string format_vtk_binary(const RawMesh& mesh) {
  constexpr auto kOrder = ByteOrder::kBig;
  std::string out;
  out.reserve(128 + mesh.positions.size() * 24 + mesh.tets.size() * 24);
  append_header(out, mesh, true);
  for (const Vec3& p : mesh.positions) {
    for (double c : {p.x, p.y, p.z}) store_f64(out, c, kOrder);
  }
  out += '\n';
  append_cells_line(out, mesh);
  for (const auto& tet : mesh.tets) {
    store_uint(out, 4, 4, kOrder);
    for (std::uint32_t v : tet) store_uint(out, v, 4, kOrder);
  }
  out += '\n';
  append_types_line(out, mesh);
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) store_uint(out, kVtkTetra, 4, kOrder);
  out += '\n';
  if (mesh.labelled()) {
    append_label_header(out, mesh);
    for (std::uint32_t label : mesh.labels) store_uint(out, label, 4, kOrder);
    out += '\n';
  }
  return out;
}

}  // namespace tetcut
