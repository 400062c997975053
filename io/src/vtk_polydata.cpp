// Legacy VTK, DATASET POLYDATA, ASCII or BINARY: a surface for mesh generation. POINTS, then
// POLYGONS (split into triangle fans) and TRIANGLE_STRIPS (into triangles); VERTICES and LINES
// are ignored with a notice; FIELD and METADATA are skipped; POINT_DATA / CELL_DATA end it.
#include <string>

#include "surface_reader.hpp"
#include "tetcut/io.hpp"
#include "vtk_cells.hpp"
#include "vtk_legacy.hpp"

namespace tetcut {

namespace {

using namespace io_detail;

class VtkPolydataReader {
 public:
  VtkPolydataReader(std::string_view text, std::string_view name) : state_(name), stream_(text, sink_) {}

  SurfaceReadResult read() {
    std::vector<std::string> notices;
    if (stream_.read_header("POLYDATA")) read_body(notices);
    return state_.result(std::move(notices));
  }

 private:
  // One cell list section; `kind` says what becomes of it.
  enum class Kind { kPolygons, kStrips, kIgnored };

  bool read_section(std::string_view keyword, Kind kind) {
    if (!have_points_) return sink_.fail(stream_.line(), std::string(keyword) + " before POINTS");
    const std::uint64_t line = stream_.line();
    VtkCells cells;
    if (!stream_.read_cell_list(keyword, cells)) return false;
    if (kind == Kind::kIgnored) {
      state_.ignored.add(std::string(keyword) + " cells", cells.offsets.size() - 1);
      return true;
    }
    return vtk_faces_to_triangles(sink_, cells, surface_.positions.size(), line, kind == Kind::kStrips, surface_,
                                  state_.polygons_split, state_.strips_split);
  }

  void read_body(std::vector<std::string>& notices) {
    std::string_view token;
    while (!sink_.failed() && stream_.next_token(token)) {
      if (iequals(token, "POINTS")) {
        if (have_points_) { sink_.fail(stream_.line(), "second POINTS section"); return; }
        stream_.read_points(surface_.positions);
        have_points_ = true;
      } else if (iequals(token, "POLYGONS")) {
        read_section("POLYGONS", Kind::kPolygons);
      } else if (iequals(token, "TRIANGLE_STRIPS")) {
        read_section("TRIANGLE_STRIPS", Kind::kStrips);
      } else if (iequals(token, "VERTICES") || iequals(token, "LINES")) {
        read_section(iequals(token, "LINES") ? "LINES" : "VERTICES", Kind::kIgnored);
      } else if (iequals(token, "METADATA")) {
        stream_.skip_metadata();
      } else if (iequals(token, "FIELD")) {
        stream_.skip_field();
      } else if (iequals(token, "POINT_DATA") || iequals(token, "CELL_DATA")) {
        break;  // attributes: not part of the surface
      } else {
        sink_.fail(stream_.line(), "unexpected keyword " + quote(token));
      }
    }
    if (sink_.failed()) return;
    if (!have_points_) { sink_.fail(stream_.line(), "missing POINTS section"); return; }
    if (surface_.triangles.empty()) {
      sink_.fail(stream_.line(), "no POLYGONS or TRIANGLE_STRIPS: the file holds no surface");
      return;
    }
    state_.emit_notices(notices);
  }

  SurfaceReaderState state_;
  ErrorSink& sink_ = state_.sink;
  SurfaceMesh& surface_ = state_.surface;
  VtkLegacyStream stream_;
  bool have_points_ = false;
};

}  // namespace

SurfaceReadResult read_vtk_polydata(std::string_view text, std::string_view name) {
  return VtkPolydataReader(text, name).read();
}

}  // namespace tetcut
