// What the three Gmsh readers (1.0, 2.2, 4.1) share: the element-type table, section skipping,
// turning one element's node-id tokens into a tet (or an ignored element), and the state and
// line-based steps of a reader (GmshReader).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "text_reader.hpp"

namespace tetcut::io_detail {

inline constexpr int kGmshTet4 = 4;
inline constexpr int kGmshTet10 = 11;

// "triangle", "tetrahedron", ... or "" for a type we do not name.
std::string_view gmsh_type_name(std::int64_t type);
// "elements of type 2 (triangle)"
std::string gmsh_ignored_kind(std::int64_t type);
// Nodes of an element of `type` (binary MSH lists no count), 0 for a type we do not know.
std::size_t gmsh_type_nodes(std::int64_t type);

// Called on a "$Name" header line: skips to "$EndName". False (and an error) if it is missing.
bool skip_gmsh_section(LineReader& lines, ErrorSink& sink, std::string_view name);
// Reads the next non-blank line and requires it to be `marker` (e.g. "$EndNodes").
bool expect_gmsh_marker(LineReader& lines, ErrorSink& sink, std::string_view marker,
                        std::string_view what);

// State shared while reading elements: the tets, the node map, the tallies for notices.
struct GmshElementSink {
  const NodeIdMap* nodes = nullptr;
  std::vector<std::array<std::uint32_t, 4>>* tets = nullptr;
  // Beside every tet, the physical tag of the element it came from, which the caller sets before
  // add() (none: label 0, Gmsh's "no physical group"); `labelled` once a tet had one, else
  // result() drops the labels (the mesh is unlabelled).
  std::vector<std::uint32_t>* labels = nullptr;
  std::optional<std::uint32_t> label;
  bool labelled = false;
  IgnoredTally ignored;
  std::uint64_t second_order_tets = 0;

  // One element of `type` with the node-id tokens `node_tokens` (already split off its id and
  // tags). Ignores non-tets; errors on a tet with the wrong number of nodes or unknown nodes.
  bool add(ErrorSink& sink, std::uint64_t line, std::int64_t type,
           const std::string_view* node_tokens, std::size_t num_nodes);
  void emit_notices(std::vector<std::string>& notices) const;
  // Counts `n` ignored elements of `type` (binary blocks skip them without decoding).
  void ignore(std::int64_t type, std::uint64_t n);
  // Appends the tet of an element of `type` whose node ids are `ids` (binary: already numbers).
  bool add_ids(ErrorSink& sink, std::uint64_t line, std::int64_t type, const std::int64_t* ids,
               std::size_t num_nodes);

 private:
  // Node `k` of a tet: its index by `id`, kept when a corner (both orders put the 4 corners first,
  // Gmsh node ordering, so a 10-node tet keeps them); an error naming an undefined id.
  bool add_node(ErrorSink& sink, std::uint64_t line, std::int64_t id, std::size_t k, std::array<std::uint32_t, 4>& tet) const;
  // Appends a tet whose nodes were all found, with the current label.
  void push_tet(std::int64_t type, const std::array<std::uint32_t, 4>& tet);
};

// Parses "id x y z" tokens (exactly 4) into the map and positions.
bool add_gmsh_node(ErrorSink& sink, std::uint64_t line, const std::vector<std::string_view>& tokens,
                   NodeIdMap& ids, std::vector<Vec3>& positions);

// Parses an element type (any integer: unknown types are ignored, not refused).
bool parse_gmsh_type(ErrorSink& sink, std::uint64_t line, std::string_view token, std::int64_t& type);

// MSH 4.1 entity blocks, ASCII or binary: a block of `n` more entries must fit in the `total` its
// section header declared (`seen` so far), and the blocks must add up to it. `noun`: "node",
// "element".
bool check_block_fits(ErrorSink& sink, std::uint64_t line, std::string_view noun, std::uint64_t seen,
                      std::uint64_t n, std::uint64_t total);
bool check_blocks_add_up(ErrorSink& sink, std::uint64_t line, std::string_view noun, std::uint64_t seen,
                         std::uint64_t total);

// MSH 4.1's volume entities as $Entities lists them: each volume's first physical tag, the label
// of the tets of every element block naming it (none: the volume has no physical group). When no
// volume has a physical tag the mesh reads unlabelled, as a 2.2 file whose tets have no tags;
// when one has, every tet block must name a volume listed here.
struct GmshVolumeLabels {
  std::unordered_map<std::int64_t, std::optional<std::uint32_t>> by_tag;
  bool labelled = false;

  // Volume `tag` with `label`; a tag listed twice is an error.
  bool add(ErrorSink& sink, std::uint64_t line, std::int64_t tag, std::optional<std::uint32_t> label);
  // Before the tets of a block of entity (`dim`, `tag`): sets `elements.label` to that volume's.
  bool label_block(ErrorSink& sink, std::uint64_t line, std::int64_t dim, std::int64_t tag,
                   GmshElementSink& elements) const;
};

// What every Gmsh reader holds while it reads one file (the lines, the first error, the mesh, its
// node-id map and the element sink wired to both, the current line's tokens) and the steps its
// sections share. Every version has one node section and one element section after it.
class GmshReader {
 public:
  GmshReader(const GmshReader&) = delete;
  GmshReader& operator=(const GmshReader&) = delete;

 protected:
  // `nodes`, `elements`: the headers of the version's two sections ("$Nodes", "$NOD").
  GmshReader(std::string_view text, std::string_view name, std::string_view nodes, std::string_view elements);
  virtual ~GmshReader() = default;

  // Each is called on its section's header line and reads up to its end marker.
  virtual void read_nodes() = 0;
  virtual void read_elements() = 0;
  // On the node or element section's header: reads it, unless it is a second one or (elements)
  // comes before the nodes.
  void on_nodes_header();
  void on_elements_header();
  // At the end of the file: fails unless both sections were there.
  void require_nodes_and_elements();

  // `count` "id x y z" node lines (MSH 1.0 and 2.2) of `section`, then its `end_marker`.
  void read_node_lines(std::uint64_t count, std::string_view section, std::string_view noun,
                       std::string_view end_marker);

  // The line after a section header that holds only a count. Errors: "unexpected end of file:
  // missing <missing>", "expected <expected>, got '<line>'", and parse_count's.
  bool read_count_line(std::string_view missing, std::string_view expected, std::uint64_t& count);
  // Entry `i` of the `count` entries of `section` (what it counts: `noun`), split into tokens_;
  // a "$" line ends the section too early.
  bool next_entry(std::string_view section, std::string_view noun, std::uint64_t i, std::uint64_t count);
  // The mesh or the first error, with notices of the elements read as corners or ignored.
  ReadResult result();

  LineReader lines_;
  ErrorSink sink_;
  RawMesh mesh_;
  NodeIdMap ids_;
  GmshElementSink elements_;
  std::vector<std::string_view> tokens_;

 private:
  std::string_view nodes_header_;
  std::string_view elements_header_;
  bool have_nodes_ = false;
  bool have_elements_ = false;
};

}  // namespace tetcut::io_detail
