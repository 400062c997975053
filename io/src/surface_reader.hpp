// What every surface reader (OFF, OBJ, STL, legacy VTK POLYDATA, VTK XML PolyData) holds while it
// reads a file: the first error, the surface so far, and the tallies its notices report.
// Internal to the engine (not installed).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "tetcut/io.hpp"
#include "text_reader.hpp"

namespace tetcut::io_detail {

struct SurfaceReaderState {
  explicit SurfaceReaderState(std::string_view file) : sink(file) {}

  // Parses the coordinates xyz[0..2] of a point at `line` and appends it.
  bool add_point(std::uint64_t line, const std::string_view* xyz);
  // Appends polygon `corners` (>= 3 vertex indices) as a triangle fan.
  void add_face(const std::vector<std::uint32_t>& corners) { add_polygon(surface, corners, polygons_split); }
  // What was split or left out: polygons made fans, strips made triangles, ignored cells or lines.
  void emit_notices(std::vector<std::string>& notices) const;
  // The surface, or the first error; with `notices` either way.
  SurfaceReadResult result(std::vector<std::string>&& notices);

  ErrorSink sink;
  SurfaceMesh surface;
  IgnoredTally ignored;
  std::uint64_t polygons_split = 0;  // polygons of more than 3 corners
  std::uint64_t strips_split = 0;    // triangle strips
};

}  // namespace tetcut::io_detail
