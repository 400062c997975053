// Shared pieces of every text reader: a line reader and a token reader that both know their
// 1-based line number, locale-independent number parsing (std::from_chars), a node-id map for
// formats whose ids are arbitrary, and a first-error sink. Internal to the engine (not installed).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <string>

#include "tetcut/vec3.hpp"
#include <string_view>
#include <unordered_map>
#include <vector>

#include "tetcut/io.hpp"

namespace tetcut::io_detail {

// Remembers the first error of a parse; every parsing step returns false once it has failed.
class ErrorSink {
 public:
  explicit ErrorSink(std::string_view file) : file_(file) {}

  bool fail(std::uint64_t line, std::string reason) {
    if (!error_) error_ = ParseError{file_, line, std::move(reason)};
    return false;
  }
  [[nodiscard]] bool failed() const { return error_.has_value(); }
  [[nodiscard]] const std::optional<ParseError>& error() const { return error_; }
  [[nodiscard]] const std::string& file() const { return file_; }

 private:
  std::string file_;
  std::optional<ParseError> error_;
};

// A token as it may appear in an error message: quoted, printable, at most 40 characters.
std::string quote(std::string_view token);

[[nodiscard]] inline bool is_space(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f';
}
std::string_view trim(std::string_view s);
// Splits `line` on ASCII whitespace into `out` (cleared first).
void split_tokens(std::string_view line, std::vector<std::string_view>& out);
// ASCII case-insensitive equality.
bool iequals(std::string_view a, std::string_view b);

// Whole-token parses; a leading '+' is accepted, trailing garbage is not.
bool parse_u64(std::string_view token, std::uint64_t& value);
bool parse_i64(std::string_view token, std::int64_t& value);
bool parse_double(std::string_view token, double& value);

// Reads line by line. CRLF and lone CR line ends are accepted ('\r' before '\n' is stripped).
class LineReader {
 public:
  explicit LineReader(std::string_view text) : text_(text) {}

  // The next line without its end; false at the end of the text.
  bool next(std::string_view& line);
  // The next line that holds something other than whitespace.
  bool next_nonblank(std::string_view& line);
  // 1-based number of the last line returned; at the end, the number of the last line.
  [[nodiscard]] std::uint64_t line_number() const { return line_; }
  [[nodiscard]] std::size_t remaining_bytes() const { return text_.size() - pos_; }
  [[nodiscard]] std::size_t offset() const { return pos_; }
  [[nodiscard]] bool at_end() const { return pos_ >= text_.size(); }
  // Keeps the position but reports `line` as the current line (end-of-file messages).
  void rewind_line_count(std::uint64_t line) { line_ = line; }
  // Binary data from the start of the next line (binary MSH): the next `n` bytes in `bytes`,
  // moving past them; false, moving nothing, when fewer remain. Line numbers go on counting the
  // line ends inside the data, so they stay the file's.
  bool take_bytes(std::size_t n, std::string_view& bytes);

 private:
  std::string_view text_;
  std::size_t pos_ = 0;
  std::uint64_t line_ = 0;
};

// The next line with at least one token once a comment (from `comment` to the end of the line;
// '\0' for none) is removed, split into `tokens`. False at the end of the text.
bool next_tokens(LineReader& lines, std::vector<std::string_view>& tokens, char comment);

// Reads whitespace-separated tokens across lines (free-format data: legacy VTK, OFF, ...).
// `comment` (if not '\0') starts a comment that runs to the end of the line.
class TokenReader {
 public:
  // `first_line`: the line number of text's first character (when text is a tail of a file).
  explicit TokenReader(std::string_view text, char comment = '\0', std::uint64_t first_line = 1)
      : text_(text), comment_(comment), line_(first_line) {}

  bool next(std::string_view& token);
  bool peek(std::string_view& token);
  // Line of the last token returned (or of the end of text).
  [[nodiscard]] std::uint64_t line_number() const { return line_; }
  [[nodiscard]] std::size_t remaining_bytes() const { return text_.size() - pos_; }
  [[nodiscard]] std::size_t offset() const { return pos_; }
  // The rest of the current line after the last token (for headers such as titles).
  std::string_view rest_of_line();
  // Skips whole lines up to and including the next blank line (VTK's METADATA blocks).
  void skip_past_blank_line();
  // Binary data after a keyword line (legacy VTK BINARY): skips the rest of the current line
  // and its end, then returns the next `n` bytes in `bytes` and moves past them; false, moving
  // nothing, when the line has no end or fewer bytes remain. Line numbers go on counting the
  // line ends inside the data, so they stay the file's.
  bool take_binary(std::size_t n, std::string_view& bytes);

 private:
  void skip_space();
  std::string_view text_;
  char comment_;
  std::uint64_t line_ = 1;
  std::size_t pos_ = 0;
};

// A count read from a file is trusted only as far as the bytes that remain could hold it: every
// entry takes at least two bytes (a character and a separator). This keeps a corrupt count from
// allocating more than a small multiple of the file size; a file merely cut short still gets the
// more precise "expected N, got M" from its reader.
bool check_count(ErrorSink& sink, std::uint64_t line, std::uint64_t count,
                 std::size_t remaining_bytes);

// Parses a count token (non-negative, bounded by the remaining bytes).
bool parse_count(ErrorSink& sink, std::uint64_t line, std::string_view token,
                 std::size_t remaining_bytes, std::uint64_t& count);
// Parses a finite coordinate.
bool parse_coordinate(ErrorSink& sink, std::uint64_t line, std::string_view token, double& value);
// Parses the three coordinates xyz[0..2] of a point.
bool parse_point(ErrorSink& sink, std::uint64_t line, const std::string_view* xyz, Vec3& p);
// Parses an integer id, any sign allowed by the caller's range check.
bool parse_id(ErrorSink& sink, std::uint64_t line, std::string_view token, std::int64_t& value);
// A per-tet label (RawMesh::labels): an integer in [0, kMaxTetLabel]; `what` names it in the
// error ("physical tag", "reference", "cell data 'label'").
bool parse_label(ErrorSink& sink, std::uint64_t line, std::string_view token, std::string_view what,
                 std::uint32_t& label);
bool check_label(ErrorSink& sink, std::uint64_t line, std::int64_t value, std::string_view what, std::uint32_t& label);
// Tet t's label for a writer: its own, or `unlabelled` when the mesh has none.
inline std::uint32_t label_or(const RawMesh& mesh, std::size_t t, std::uint32_t unlabelled) {
  return mesh.labels.empty() ? unlabelled : mesh.labels[t];
}

// Maps file node ids (arbitrary, maybe sparse) to 0-based indices. Contiguous ids (the common
// case) need no table; the first gap switches to a hash map used for lookups only, never
// iterated, so results do not depend on its order.
class NodeIdMap {
 public:
  // False if `id` was already defined.
  bool insert(std::int64_t id, std::uint32_t index);
  // kNone if undefined.
  [[nodiscard]] std::uint32_t find(std::int64_t id) const;
  static constexpr std::uint32_t kNone = 0xFFFFFFFFu;

 private:
  bool contiguous_ = true;
  std::int64_t first_ = 0;
  std::uint32_t count_ = 0;
  std::unordered_map<std::int64_t, std::uint32_t> map_;
};

// Counts ignored elements by kind, for one notice per kind in a stable order, and for the
// summary of a file that held no tets ("27 hexahedra, no tetrahedra").
class IgnoredTally {
 public:
  // `kind` as a notice names it ("elements of type 5 (hexahedron)"), `noun` as a summary does
  // (singular: "hexahedron"); an empty noun means the kind.
  void add(std::string kind, std::uint64_t n = 1, std::string noun = {});
  // "ignored 12 elements of type 2 (triangle)" style notices, one per kind.
  void emit(std::vector<std::string>& notices) const;
  // Counts by noun, merged, in the order of their kinds.
  [[nodiscard]] std::vector<CellCount> summary() const;

 private:
  struct Entry {
    std::uint64_t count = 0;
    std::string noun;
  };
  std::map<std::string, Entry> counts_;
};

// "hexahedron" -> "hexahedra", "vertex" -> "vertices", "triangle" -> "triangles".
std::string plural_noun(std::string_view singular);

// The result of a reader: the error if `sink` failed, else the mesh; with the summary of
// `ignored` (when given) for a caller that needs to say what a file without tets held.
ReadResult make_result(ErrorSink& sink, RawMesh&& mesh, std::vector<std::string>&& notices,
                       const IgnoredTally* ignored = nullptr);
SurfaceReadResult make_surface_result(ErrorSink& sink, SurfaceMesh&& surface,
                                      std::vector<std::string>&& notices);

// Adds polygon `corners` (>= 3 vertex indices) as a triangle fan; counts polygons split.
void add_polygon(SurfaceMesh& surface, const std::vector<std::uint32_t>& corners,
                 std::uint64_t& polygons_split);
void polygon_notice(std::uint64_t polygons_split, std::vector<std::string>& notices);

// Shortest text that parses back to the same double (std::to_chars), appended to `out`.
void append_double(std::string& out, double value);
// "x y z", each coordinate as append_double writes it.
void append_point(std::string& out, const Vec3& p);
void append_uint(std::string& out, std::uint64_t value);
// One "x y z" line a position, each between `prefix` and `suffix` (an indent, a reference).
void append_point_lines(std::string& out, const std::vector<Vec3>& positions, std::string_view prefix = {},
                        std::string_view suffix = "\n");
// One "n x y z" line a position, numbered from 1 (Gmsh 2.2 $Nodes, TetGen .node).
void append_numbered_points(std::string& out, const std::vector<Vec3>& positions);
// One "n<fields> a b c d" line a tet, numbered from 1, with 1-based vertex ids (Gmsh elements,
// TetGen .ele); `fields`: what the format puts between number and ids (Gmsh 2.2: type, tags);
// `last_column`, unless empty, one value a tet after its ids (TetGen's region attribute).
void append_numbered_tets(std::string& out, const std::vector<std::array<std::uint32_t, 4>>& tets,
                          std::string_view fields = {}, std::span<const std::uint32_t> last_column = {});

}  // namespace tetcut::io_detail
