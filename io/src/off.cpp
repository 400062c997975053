// Object File Format (.off) surfaces: "OFF" (also COFF, NOFF, CNOFF...), "nv nf ne", vertex lines
// "x y z [colour...]", face lines "n i0 .. i(n-1) [colour...]" with 0-based ids. '#' comments.
#include <string>

#include "surface_reader.hpp"
#include "tetcut/io.hpp"

namespace tetcut {

using namespace io_detail;

SurfaceReadResult read_off(std::string_view text, std::string_view name) {
  SurfaceReaderState state(name);
  ErrorSink& sink = state.sink;
  LineReader lines(text);
  std::vector<std::string_view> tokens;
  [&] {
    if (!next_tokens(lines, tokens, '#')) return sink.fail(lines.line_number(), "empty file");
    const std::string_view magic = tokens[0];
    if (magic.size() < 3 || magic.substr(magic.size() - 3) != "OFF") {
      return sink.fail(lines.line_number(), "expected an OFF header, got " + quote(magic));
    }
    if (tokens.size() > 1 && iequals(tokens[1], "BINARY")) {
      return sink.fail(lines.line_number(), "binary OFF is not supported");
    }
    if (magic.find('4') != std::string_view::npos || magic.find("n") != std::string_view::npos) {
      return sink.fail(lines.line_number(), "unsupported OFF variant " + quote(magic));
    }
    // The counts may share the header line.
    std::vector<std::string_view> counts(tokens.begin() + 1, tokens.end());
    if (counts.empty()) {
      if (!next_tokens(lines, tokens, '#')) return sink.fail(lines.line_number(), "unexpected end of file: missing counts");
      counts = tokens;
    }
    const std::uint64_t at = lines.line_number();
    if (counts.size() < 2 || counts.size() > 3) {
      return sink.fail(at, "expected 'vertices faces [edges]' counts, got " + std::to_string(counts.size()) + " values");
    }
    std::uint64_t nv = 0;
    std::uint64_t nf = 0;
    if (!parse_count(sink, at, counts[0], lines.remaining_bytes(), nv) ||
        !parse_count(sink, at, counts[1], lines.remaining_bytes(), nf)) {
      return false;
    }
    state.surface.positions.reserve(nv);
    for (std::uint64_t i = 0; i < nv; ++i) {
      if (!next_tokens(lines, tokens, '#')) {
        return sink.fail(lines.line_number(), "unexpected end of file: expected " + std::to_string(nv) +
                                                  " vertices, got " + std::to_string(i));
      }
      const std::uint64_t line = lines.line_number();
      if (tokens.size() < 3) return sink.fail(line, "expected 3 coordinates, got " + std::to_string(tokens.size()));
      if (!state.add_point(line, tokens.data())) return false;
    }
    std::vector<std::uint32_t> corners;
    for (std::uint64_t f = 0; f < nf; ++f) {
      if (!next_tokens(lines, tokens, '#')) {
        return sink.fail(lines.line_number(), "unexpected end of file: expected " + std::to_string(nf) +
                                                  " faces, got " + std::to_string(f));
      }
      const std::uint64_t line = lines.line_number();
      std::uint64_t n = 0;
      if (!parse_u64(tokens[0], n)) return sink.fail(line, "expected a face's vertex count, got " + quote(tokens[0]));
      if (n < 3) return sink.fail(line, "a face needs at least 3 vertices, got " + std::to_string(n));
      if (n > tokens.size() - 1) {
        return sink.fail(line, "face declares " + std::to_string(n) + " vertices but lists " +
                                   std::to_string(tokens.size() - 1));
      }
      corners.clear();
      for (std::uint64_t k = 0; k < n; ++k) {
        std::int64_t id = 0;
        if (!parse_id(sink, line, tokens[1 + k], id)) return false;
        if (id < 0 || static_cast<std::uint64_t>(id) >= nv) {
          return sink.fail(line, "vertex id " + std::to_string(id) + " not defined (" + std::to_string(nv) + " vertices)");
        }
        corners.push_back(static_cast<std::uint32_t>(id));
      }
      state.add_face(corners);
    }
    return true;
  }();
  std::vector<std::string> notices;
  state.emit_notices(notices);
  return state.result(std::move(notices));
}

}  // namespace tetcut
