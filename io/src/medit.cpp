// medit / Mmg .mesh ASCII: keyword sections, 1-based vertex ids, a reference after each entry.
//   MeshVersionFormatted 2 / Dimension 3 / Vertices n, "x y z ref" / Tetrahedra n,
//   "a b c d ref" / ... / End
// A tet's reference is its label (RawMesh::labels; a tet without one: 0, a file where none has
// one: unlabelled), written back as it was read (1 for every tet of an unlabelled mesh).
// '#' starts a comment. Every other section (Triangles, Edges, Corners, Normals, ...) is a count
// followed by one line per entry, and is skipped with a notice.
#include <string>

#include "tetcut/io.hpp"
#include "text_reader.hpp"

namespace tetcut {

namespace {

using namespace io_detail;

// "Hexahedra" -> "hexahedron", "Vertices" -> "vertex", "Triangles" -> "triangle".
std::string keyword_noun(std::string_view keyword) {
  std::string s;
  for (char c : keyword) s += (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c;
  const auto ends_with = [&](std::string_view tail) { return s.size() > tail.size() && s.ends_with(tail); };
  if (ends_with("hedra")) return s.substr(0, s.size() - 1) + "on";
  if (ends_with("ices")) return s.substr(0, s.size() - 4) + "ex";
  if (ends_with("s")) return s.substr(0, s.size() - 1);
  return s;
}

class MeditReader {
 public:
  MeditReader(std::string_view text, std::string_view name) : lines_(text), sink_(name) {}

  ReadResult read() {
    bool have_version = false;
    bool have_vertices = false;
    bool have_tets = false;
    bool have_end = false;
    while (!sink_.failed() && next_tokens(lines_, tokens_, '#')) {
      const std::string keyword(tokens_[0]);
      const std::uint64_t at = lines_.line_number();
      if (!have_version) {
        if (!iequals(keyword, "MeshVersionFormatted")) {
          sink_.fail(at, "expected MeshVersionFormatted, got " + quote(keyword));
          break;
        }
        std::string_view value;
        if (!keyword_value(value)) break;
        if (value != "1" && value != "2" && value != "3" && value != "4") {
          sink_.fail(lines_.line_number(), "unsupported MeshVersionFormatted " + quote(value));
        }
        have_version = true;
      } else if (iequals(keyword, "Dimension")) {
        std::string_view value;
        if (!keyword_value(value)) break;
        if (value != "3") sink_.fail(lines_.line_number(), "only 3D meshes are supported, got Dimension " + quote(value));
      } else if (iequals(keyword, "Vertices")) {
        if (have_vertices) sink_.fail(at, "second Vertices section");
        else read_vertices();
        have_vertices = true;
      } else if (iequals(keyword, "Tetrahedra")) {
        if (have_tets) sink_.fail(at, "second Tetrahedra section");
        else if (!have_vertices) sink_.fail(at, "Tetrahedra before Vertices");
        else read_tets();
        have_tets = true;
      } else if (iequals(keyword, "End")) {
        have_end = true;
        break;
      } else {
        skip_section(keyword);
      }
    }
    if (!sink_.failed()) {
      const std::uint64_t at = lines_.line_number();
      if (!have_version) sink_.fail(at, "empty file: no MeshVersionFormatted");
      else if (!have_vertices) sink_.fail(at, "missing Vertices section");
      else if (!have_tets) sink_.fail(at, "missing Tetrahedra section");
      else if (!have_end) sink_.fail(at, "missing End");
    }
    std::vector<std::string> notices;
    ignored_.emit(notices);
    return make_result(sink_, std::move(mesh_), std::move(notices), &ignored_);
  }

 private:
  // The value after a keyword: on the keyword's line or on the next one.
  bool keyword_value(std::string_view& value) {
    if (tokens_.size() > 2) {
      return sink_.fail(lines_.line_number(), "expected one value after " + quote(tokens_[0]));
    }
    if (tokens_.size() == 2) {
      value = tokens_[1];
      return true;
    }
    const std::string keyword(tokens_[0]);
    if (!next_tokens(lines_, tokens_, '#')) {
      return sink_.fail(lines_.line_number(), "unexpected end of file after " + quote(keyword));
    }
    if (tokens_.size() != 1) {
      return sink_.fail(lines_.line_number(), "expected one value after " + quote(keyword) + ", got " +
                                                  std::to_string(tokens_.size()));
    }
    value = tokens_[0];
    return true;
  }

  bool section_count(std::uint64_t& count) {
    std::string_view value;
    return keyword_value(value) &&
           parse_count(sink_, lines_.line_number(), value, lines_.remaining_bytes(), count);
  }

  bool next_entry(std::string_view section, std::uint64_t i, std::uint64_t count) {
    if (!next_tokens(lines_, tokens_, '#')) {
      return sink_.fail(lines_.line_number(), "unexpected end of file in " + std::string(section) +
                                                  ": expected " + std::to_string(count) + " entries, got " +
                                                  std::to_string(i));
    }
    return true;
  }

  void read_vertices() {
    std::uint64_t count = 0;
    if (!section_count(count)) return;
    mesh_.positions.reserve(count);
    for (std::uint64_t i = 0; i < count; ++i) {
      if (!next_entry("Vertices", i, count)) return;
      const std::uint64_t at = lines_.line_number();
      if (tokens_.size() != 4 && tokens_.size() != 3) {
        sink_.fail(at, "expected 3 coordinates and a reference for a vertex, got " +
                           std::to_string(tokens_.size()) + " values");
        return;
      }
      Vec3 p;
      if (!parse_point(sink_, at, tokens_.data(), p)) return;
      if (tokens_.size() == 4) {
        std::int64_t ref = 0;
        if (!parse_i64(tokens_[3], ref)) {
          sink_.fail(at, "expected an integer reference, got " + quote(tokens_[3]));
          return;
        }
      }
      mesh_.positions.push_back(p);
    }
  }

  void read_tets() {
    std::uint64_t count = 0;
    if (!section_count(count)) return;
    mesh_.tets.reserve(count);
    mesh_.labels.reserve(count);
    bool labelled = false;
    const std::uint64_t nv = mesh_.positions.size();
    for (std::uint64_t i = 0; i < count; ++i) {
      if (!next_entry("Tetrahedra", i, count)) return;
      const std::uint64_t at = lines_.line_number();
      if (tokens_.size() != 5 && tokens_.size() != 4) {
        sink_.fail(at, "expected 4 vertex ids and a reference for a tetrahedron, got " +
                           std::to_string(tokens_.size()) + " values");
        return;
      }
      std::array<std::uint32_t, 4> tet{};
      for (int k = 0; k < 4; ++k) {
        std::int64_t id = 0;
        if (!parse_id(sink_, at, tokens_[k], id)) return;
        if (id < 1 || static_cast<std::uint64_t>(id) > nv) {
          sink_.fail(at, "vertex id " + std::to_string(id) + " not defined (ids are 1-based, " +
                             std::to_string(nv) + " vertices)");
          return;
        }
        tet[k] = static_cast<std::uint32_t>(id - 1);
      }
      std::uint32_t label = 0;
      if (tokens_.size() == 5) {
        if (!parse_label(sink_, at, tokens_[4], "tetrahedron reference", label)) return;
        labelled = true;
      }
      mesh_.tets.push_back(tet);
      mesh_.labels.push_back(label);
    }
    if (!labelled) mesh_.labels.clear();
  }

  void skip_section(const std::string& keyword) {
    std::uint64_t count = 0;
    std::string_view value;
    if (!keyword_value(value)) return;
    std::uint64_t n = 0;
    if (!parse_u64(value, n)) {
      sink_.fail(lines_.line_number(), "unknown keyword " + quote(keyword) + " (not followed by a count)");
      return;
    }
    if (!check_count(sink_, lines_.line_number(), n, lines_.remaining_bytes())) return;
    count = n;
    for (std::uint64_t i = 0; i < count; ++i) {
      if (!next_entry(keyword, i, count)) return;
    }
    if (count > 0) ignored_.add("entries of " + keyword, count, keyword_noun(keyword));
  }

  LineReader lines_;
  ErrorSink sink_;
  RawMesh mesh_;
  IgnoredTally ignored_;
  std::vector<std::string_view> tokens_;
};

}  // namespace

ReadResult read_medit(std::string_view text, std::string_view name) {
  return MeditReader(text, name).read();
}

std::string format_medit(const RawMesh& mesh) {
  std::string out;
  out.reserve(128 + mesh.positions.size() * 64 + mesh.tets.size() * 40);
  out += "MeshVersionFormatted 2\n\nDimension 3\n\nVertices\n";
  append_uint(out, mesh.positions.size());
  out += '\n';
  append_point_lines(out, mesh.positions, "", " 0\n");
  out += "\nTetrahedra\n";
  append_uint(out, mesh.tets.size());
  out += '\n';
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    for (std::uint32_t v : mesh.tets[t]) {
      append_uint(out, static_cast<std::uint64_t>(v) + 1);
      out += ' ';
    }
    append_uint(out, label_or(mesh, t, 1));
    out += '\n';
  }
  out += "\nEnd\n";
  return out;
}

}  // namespace tetcut
