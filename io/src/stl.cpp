// STL surfaces, ASCII ("solid ... facet normal ... outer loop vertex x y z ... endsolid") or
// binary (80-byte header, uint32 count, 50 bytes per triangle). A file is binary when its size
// is exactly 84 + 50 * count, whatever its first bytes say (binary files often start with
// "solid" too). STL is a triangle soup: vertices with equal coordinates are merged.
#include <array>
#include <cmath>
#include <cstring>
#include <map>
#include <string>

#include "surface_reader.hpp"
#include "tetcut/io.hpp"

namespace tetcut {

using namespace io_detail;

namespace {

// Merges equal positions (-0 and +0 alike) into one vertex, numbered in order of first use.
class VertexWelder {
 public:
  std::uint32_t add(const Vec3& p, SurfaceMesh& surface) {
    const Vec3 q{p.x + 0.0, p.y + 0.0, p.z + 0.0};
    std::array<std::uint64_t, 3> key{};
    std::memcpy(&key[0], &q.x, 8);
    std::memcpy(&key[1], &q.y, 8);
    std::memcpy(&key[2], &q.z, 8);
    const auto [it, inserted] = index_.emplace(key, static_cast<std::uint32_t>(surface.positions.size()));
    if (inserted) surface.positions.push_back(q);
    return it->second;
  }

 private:
  std::map<std::array<std::uint64_t, 3>, std::uint32_t> index_;
};

float read_float_le(const unsigned char* p) {
  const std::uint32_t bits = static_cast<std::uint32_t>(p[0]) | (static_cast<std::uint32_t>(p[1]) << 8) |
                             (static_cast<std::uint32_t>(p[2]) << 16) | (static_cast<std::uint32_t>(p[3]) << 24);
  float f;
  std::memcpy(&f, &bits, 4);
  return f;
}

bool read_binary(std::string_view bytes, ErrorSink& sink, SurfaceMesh& surface, std::uint64_t count) {
  VertexWelder welder;
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
  surface.triangles.reserve(count);
  for (std::uint64_t t = 0; t < count; ++t) {
    const unsigned char* rec = data + 84 + 50 * t + 12;  // skip the normal
    std::array<std::uint32_t, 3> tri{};
    for (int k = 0; k < 3; ++k) {
      const Vec3 p{read_float_le(rec + 12 * k), read_float_le(rec + 12 * k + 4), read_float_le(rec + 12 * k + 8)};
      if (!is_finite(p)) {
        // Binary STL has no lines; the triangle number locates the problem instead.
        return sink.fail(0, "non-finite coordinate in triangle " + std::to_string(t));
      }
      tri[k] = welder.add(p, surface);
    }
    surface.triangles.push_back(tri);
  }
  return true;
}

bool read_ascii(std::string_view text, ErrorSink& sink, SurfaceMesh& surface) {
  TokenReader tokens(text);
  VertexWelder welder;
  std::string_view token;
  const auto expect = [&](std::string_view word) {
    if (!tokens.next(token)) return sink.fail(tokens.line_number(), "unexpected end of file: expected '" + std::string(word) + "'");
    if (!iequals(token, word)) return sink.fail(tokens.line_number(), "expected '" + std::string(word) + "', got " + quote(token));
    return true;
  };
  if (!expect("solid")) return false;
  tokens.rest_of_line();  // the solid's name
  while (true) {
    if (!tokens.next(token)) return sink.fail(tokens.line_number(), "unexpected end of file: missing 'endsolid'");
    if (iequals(token, "endsolid")) break;
    if (!iequals(token, "facet")) return sink.fail(tokens.line_number(), "expected 'facet' or 'endsolid', got " + quote(token));
    if (!expect("normal")) return false;
    for (int k = 0; k < 3; ++k) {
      double ignored = 0;
      if (!tokens.next(token)) return sink.fail(tokens.line_number(), "unexpected end of file in a facet normal");
      if (!parse_double(token, ignored)) return sink.fail(tokens.line_number(), "expected a normal component, got " + quote(token));
    }
    if (!expect("outer") || !expect("loop")) return false;
    std::array<std::uint32_t, 3> tri{};
    for (int k = 0; k < 3; ++k) {
      if (!expect("vertex")) return false;
      Vec3 p;
      for (double* c : {&p.x, &p.y, &p.z}) {
        if (!tokens.next(token)) return sink.fail(tokens.line_number(), "unexpected end of file in a vertex");
        if (!parse_coordinate(sink, tokens.line_number(), token, *c)) return false;
      }
      tri[k] = welder.add(p, surface);
    }
    if (!tokens.next(token)) return sink.fail(tokens.line_number(), "unexpected end of file: expected 'endloop'");
    if (iequals(token, "vertex")) return sink.fail(tokens.line_number(), "facet with more than 3 vertices");
    if (!iequals(token, "endloop")) return sink.fail(tokens.line_number(), "expected 'endloop', got " + quote(token));
    if (!expect("endfacet")) return false;
    surface.triangles.push_back(tri);
  }
  return true;
}

}  // namespace

SurfaceReadResult read_stl(std::string_view bytes, std::string_view name) {
  SurfaceReaderState state(name);
  ErrorSink& sink = state.sink;
  SurfaceMesh& surface = state.surface;
  if (trim(bytes).empty()) {
    sink.fail(bytes.empty() ? 0 : 1, "empty file");
  } else {
    std::uint64_t count = 0;
    bool binary = false;
    if (bytes.size() >= 84) {
      const auto* p = reinterpret_cast<const unsigned char*>(bytes.data()) + 80;
      count = static_cast<std::uint64_t>(p[0]) | (static_cast<std::uint64_t>(p[1]) << 8) |
              (static_cast<std::uint64_t>(p[2]) << 16) | (static_cast<std::uint64_t>(p[3]) << 24);
      binary = 84 + 50 * count == bytes.size();
    }
    const std::string_view start = trim(bytes).substr(0, 5);
    if (binary) {
      read_binary(bytes, sink, surface, count);
    } else if (iequals(start, "solid")) {
      read_ascii(bytes, sink, surface);
    } else if (bytes.size() >= 84) {
      sink.fail(0, "binary STL header declares " + std::to_string(count) + " triangles (" +
                       std::to_string(84 + 50 * count) + " bytes) but the file has " +
                       std::to_string(bytes.size()) + " bytes");
    } else {
      sink.fail(1, "not an STL file: expected 'solid' or a binary header");
    }
    if (!sink.failed() && surface.triangles.empty()) sink.fail(0, "no triangles in the file");
  }
  return state.result({});
}

}  // namespace tetcut
