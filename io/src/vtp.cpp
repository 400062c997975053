// VTK XML PolyData (.vtp): a surface for mesh generation. Each Piece's Points, Polys (split
// into triangle fans) and Strips (into triangles), in every encoding a .vtu may use
// (vtk_xml_arrays.hpp); Verts and Lines are ignored with a notice.
#include <string>

#include "surface_reader.hpp"
#include "tetcut/io.hpp"
#include "vtk_cells.hpp"
#include "vtk_xml.hpp"
#include "vtk_xml_arrays.hpp"

namespace tetcut {

namespace {

using namespace io_detail;

class VtpReader {
 public:
  VtpReader(std::string_view text, std::string_view name) : text_(text), state_(name), arrays_(text, file_, sink_) {}

  SurfaceReadResult read() {
    std::vector<std::string> notices;
    if (scan_vtk_xml(text_, "PolyData", sink_, file_)) {
      for (const VtkXmlPiece& piece : file_.pieces) {
        if (!read_piece(piece)) break;
      }
    }
    if (!sink_.failed() && surface_.triangles.empty()) {
      sink_.fail(file_.pieces.empty() ? 1 : file_.pieces.front().line, "no Polys or Strips: the file holds no surface");
    }
    if (!sink_.failed()) state_.emit_notices(notices);
    return state_.result(std::move(notices));
  }

 private:
  bool count(const VtkXmlPiece& piece, std::string_view name, std::uint64_t& n) {
    const std::size_t room = file_.compressor ? static_cast<std::size_t>(-1) / 4 : text_.size();
    return piece_count(sink_, piece, name, name == "NumberOfPoints", n) && check_count(sink_, piece.line, n, room);
  }

  // The cells of section `section` (Polys, Strips, Verts, Lines): `expected` of them.
  bool read_cells(const VtkXmlPiece& piece, std::string_view section, std::uint64_t expected, VtkCells& cells) {
    const VtkDataArray* connectivity = piece.find(section, "connectivity");
    const VtkDataArray* offsets = piece.find(section, "offsets");
    if (connectivity == nullptr || offsets == nullptr) {
      std::string reason = "<";
      reason += section;
      reason += connectivity == nullptr ? "> has no connectivity DataArray" : "> has no offsets DataArray";
      return sink_.fail(piece.line, std::move(reason));
    }
    std::vector<std::int64_t> ends;
    if (!arrays_.integers(*connectivity, VtkArrayDecoder::kAny, "connectivity", cells.connectivity) ||
        !arrays_.integers(*offsets, expected, "offsets", ends)) {
      return false;
    }
    return append_cell_ends(sink_, ends, offsets->line, cells);
  }

  bool read_piece(const VtkXmlPiece& piece) {
    std::uint64_t points = 0, polys = 0, strips = 0, verts = 0, lines = 0;
    if (!count(piece, "NumberOfPoints", points) || !count(piece, "NumberOfPolys", polys) ||
        !count(piece, "NumberOfStrips", strips) || !count(piece, "NumberOfVerts", verts) ||
        !count(piece, "NumberOfLines", lines)) {
      return false;
    }
    if (verts > 0) state_.ignored.add("Verts cells", verts);
    if (lines > 0) state_.ignored.add("Lines cells", lines);
    if (points == 0) return true;
    const VtkDataArray* coordinates = piece.find("Points", "");
    if (coordinates == nullptr) return sink_.fail(piece.line, "Piece has no Points DataArray");
    if (coordinates->components != 3) {
      return sink_.fail(coordinates->line, "Points must have 3 components, got " + std::to_string(coordinates->components));
    }
    std::vector<double> xyz;
    if (!arrays_.reals(*coordinates, points * 3, "coordinate", xyz)) return false;
    SurfaceMesh piece_surface;
    for (std::uint64_t i = 0; i < points; ++i) piece_surface.positions.push_back({xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]});
    for (const bool is_strips : {false, true}) {
      if ((is_strips ? strips : polys) == 0) continue;
      VtkCells cells;
      if (!read_cells(piece, is_strips ? "Strips" : "Polys", is_strips ? strips : polys, cells) ||
          !vtk_faces_to_triangles(sink_, cells, points, piece.line, is_strips, piece_surface, state_.polygons_split,
                                  state_.strips_split)) {
        return false;
      }
    }
    // Pieces are concatenated: their point ids start after the points before them.
    const auto base = static_cast<std::uint32_t>(surface_.positions.size());
    surface_.positions.insert(surface_.positions.end(), piece_surface.positions.begin(), piece_surface.positions.end());
    for (auto tri : piece_surface.triangles) {
      for (std::uint32_t& v : tri) v += base;
      surface_.triangles.push_back(tri);
    }
    return true;
  }

  std::string_view text_;
  SurfaceReaderState state_;
  ErrorSink& sink_ = state_.sink;
  SurfaceMesh& surface_ = state_.surface;
  VtkXmlFile file_;
  VtkArrayDecoder arrays_;
};

}  // namespace

SurfaceReadResult read_vtp(std::string_view text, std::string_view name) {
  return VtpReader(text, name).read();
}

}  // namespace tetcut
