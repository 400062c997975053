// Wavefront .obj surfaces: "v x y z [w]" and "f a b c ..." where a corner is "v", "v/vt",
// "v/vt/vn" or "v//vn", 1-based, negative = relative to the last vertex. Other records
// (vn, vt, g, o, s, usemtl, mtllib, l, p) are skipped. '#' comments.
#include <string>

#include "surface_reader.hpp"
#include "tetcut/io.hpp"

namespace tetcut {

using namespace io_detail;

SurfaceReadResult read_obj(std::string_view text, std::string_view name) {
  SurfaceReaderState state(name);
  ErrorSink& sink = state.sink;
  const std::vector<Vec3>& positions = state.surface.positions;
  LineReader lines(text);
  std::vector<std::string_view> tokens;
  std::uint64_t skipped_lines = 0;
  // Faces may name vertices defined later; resolve once all vertices are known.
  std::vector<std::int64_t> face_ids;
  std::vector<std::uint64_t> face_lines;
  std::vector<std::size_t> face_sizes;
  bool ok = [&] {
    while (next_tokens(lines, tokens, '#')) {
      const std::uint64_t line = lines.line_number();
      if (tokens[0] == "v") {
        if (tokens.size() < 4 || tokens.size() > 7) {  // x y z, then w or an r g b colour
          return sink.fail(line, "expected 3 coordinates after 'v', got " + std::to_string(tokens.size() - 1));
        }
        if (!state.add_point(line, tokens.data() + 1)) return false;
      } else if (tokens[0] == "f") {
        if (tokens.size() < 4) {
          return sink.fail(line, "a face needs at least 3 vertices, got " + std::to_string(tokens.size() - 1));
        }
        for (std::size_t k = 1; k < tokens.size(); ++k) {
          const std::string_view corner = tokens[k].substr(0, tokens[k].find('/'));
          std::int64_t id = 0;
          if (!parse_id(sink, line, corner, id)) return false;
          if (id == 0) return sink.fail(line, "vertex index 0 (OBJ indices start at 1)");
          if (id < 0) {
            // Relative to the vertices defined so far.
            const std::int64_t resolved = static_cast<std::int64_t>(positions.size()) + id + 1;
            if (resolved < 1) return sink.fail(line, "relative vertex index " + std::to_string(id) + " not defined");
            id = resolved;
          }
          face_ids.push_back(id);
        }
        face_sizes.push_back(tokens.size() - 1);
        face_lines.push_back(line);
      } else {
        ++skipped_lines;
      }
    }
    return true;
  }();
  if (ok) {
    std::vector<std::uint32_t> corners;
    std::size_t at = 0;
    for (std::size_t f = 0; f < face_sizes.size() && ok; ++f) {
      corners.clear();
      for (std::size_t k = 0; k < face_sizes[f]; ++k) {
        const std::int64_t id = face_ids[at++];
        if (static_cast<std::uint64_t>(id) > positions.size()) {
          ok = sink.fail(face_lines[f], "vertex index " + std::to_string(id) + " not defined (" +
                                            std::to_string(positions.size()) + " vertices)");
          break;
        }
        corners.push_back(static_cast<std::uint32_t>(id - 1));
      }
      if (ok) state.add_face(corners);
    }
  }
  if (ok && state.surface.triangles.empty()) sink.fail(lines.line_number(), "no faces in the file");
  if (skipped_lines > 0) state.ignored.add("non-geometry lines", skipped_lines);
  std::vector<std::string> notices;
  state.emit_notices(notices);
  return state.result(std::move(notices));
}

}  // namespace tetcut
