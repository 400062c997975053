// Gmsh MSH 4.1, ASCII or binary. Nodes and elements come in entity blocks:
//   $Nodes: numBlocks numNodes minTag maxTag, then per block "dim entity parametric n", n tag
//   lines, n coordinate lines ("x y z" plus u [v [w]] when parametric).
//   $Elements: numBlocks numElements minTag maxTag, then per block "dim entity type n" and n lines
//   "tag node...".
//   $Entities: "numPoints numCurves numSurfaces numVolumes", then one line per entity: "tag x y z
//   numPhysicalTags physicalTag..." for a point, "tag minX minY minZ maxX maxY maxZ
//   numPhysicalTags physicalTag... numBounding boundingTag..." for a curve, surface or volume.
// In a binary file the same fields are raw values (gmsh_binary.hpp).
// A tet's label (RawMesh::labels) is the first physical tag of the volume entity its element
// block names; a volume without one gives label 0, and a file where no volume has one (or without
// $Entities) reads unlabelled, as MSH 2.2 does with untagged tets. An $Entities after $Elements
// (Gmsh writes it before $Nodes) is skipped. Written back labelled: one volume per distinct label
// (tags 1.. in increasing label order, physical tag the label), one element block per run of
// consecutive tets with the same label, so the tets keep their order (one block per volume when
// they come grouped by label, as Gmsh writes them). $PhysicalNames, $Comments and the rest are
// skipped.
#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "gmsh_sections.hpp"
#include "tetcut/io.hpp"

namespace tetcut {

namespace {

using namespace io_detail;

class Msh41Reader : public GmshSectionReader {
 public:
  Msh41Reader(std::string_view text, std::string_view name) : GmshSectionReader(text, name) {}

 private:
  // The next non-blank line split into tokens_, which must not be a section marker.
  bool next_record(std::string_view where) {
    std::string_view line;
    if (!lines_.next_nonblank(line)) {
      return sink_.fail(lines_.line_number(), "unexpected end of file in " + std::string(where));
    }
    split_tokens(line, tokens_);
    if (tokens_[0][0] == '$') {
      return sink_.fail(lines_.line_number(), "section ended early: " + quote(tokens_[0]) + " in " + std::string(where));
    }
    return true;
  }

  bool expect_tokens(std::size_t n, std::string_view what) {
    if (tokens_.size() != n) {
      return sink_.fail(lines_.line_number(), "expected " + std::string(what) + ", got " +
                                                  std::to_string(tokens_.size()) + " values");
    }
    return true;
  }

  void read_format() override {
    if (!next_record("$MeshFormat") || !expect_tokens(3, "'version file-type data-size'")) return;
    if (tokens_[0] != "4.1") {
      sink_.fail(lines_.line_number(), "unsupported MSH version " + quote(tokens_[0]) + " (this reader reads 4.1)");
      return;
    }
    if (tokens_[1] == "1") {
      std::uint64_t data_size = 0;
      if (!parse_u64(tokens_[2], data_size)) {
        sink_.fail(lines_.line_number(), "data-size must be 4 or 8, got " + quote(tokens_[2]));
        return;
      }
      binary_ = true;
      if (!binary_reader_.read_check_value(data_size)) return;
    } else if (tokens_[1] != "0") {
      sink_.fail(lines_.line_number(), "file-type must be 0 (ASCII) or 1 (binary), got " + quote(tokens_[1]));
      return;
    }
    expect_gmsh_marker(lines_, sink_, "$EndMeshFormat", "the format line");
  }

  bool read_header(std::string_view section, std::uint64_t& blocks,
                   std::uint64_t& total) {
    if (!next_record(section) ||
        !expect_tokens(4, "'numEntityBlocks count minTag maxTag'")) {
      return false;
    }
    const std::uint64_t at = lines_.line_number();
    return parse_count(sink_, at, tokens_[0], lines_.remaining_bytes(), blocks) &&
           parse_count(sink_, at, tokens_[1], lines_.remaining_bytes(), total);
  }

  // An entity block's header line of `section` ("$Nodes", "$Elements"): 4 tokens, `fields` naming
  // them in the error.
  bool next_block_header(std::string_view section, std::string_view fields) {
    return next_record(std::string(section) + " block header") && expect_tokens(4, fields);
  }

  // The block's size, its header's last token: `n` more `kind`s after `done` of the section's
  // `total`, each within what the file can still hold.
  bool block_size(std::string_view kind, std::uint64_t done, std::uint64_t total, std::uint64_t& n) {
    return parse_count(sink_, lines_.line_number(), tokens_[3], lines_.remaining_bytes(), n) &&
           check_block_fits(sink_, lines_.line_number(), kind, done, n, total);
  }

  // The section's blocks held `count` of its `total` `kind`s, then its end marker.
  void end_blocks(std::string_view kind, std::uint64_t count, std::uint64_t total, std::string_view marker) {
    if (check_blocks_add_up(sink_, lines_.line_number(), kind, count, total))
      expect_gmsh_marker(lines_, sink_, marker, "the last " + std::string(kind) + " block");
  }

  // The `n` tokens of the current line from `at` on must be ints (Gmsh's 32-bit tags); an error
  // naming `what` otherwise.
  bool expect_int_tokens(std::size_t at, std::uint64_t n, std::string_view what) {
    for (std::uint64_t i = 0; i < n; ++i) {
      std::int64_t v = 0;
      if (!parse_i64(tokens_[at + i], v) || v < std::numeric_limits<std::int32_t>::min() ||
          v > std::numeric_limits<std::int32_t>::max()) {
        return sink_.fail(lines_.line_number(), std::string(what) + " " + quote(tokens_[at + i]) + " is not an int");
      }
    }
    return true;
  }

  void read_entities() override {
    if (elements_read_) {
      skip_gmsh_section(lines_, sink_, "Entities");
      return;
    }
    if (entities_read_) {
      sink_.fail(lines_.line_number(), "a second $Entities section");
      return;
    }
    entities_read_ = true;
    const std::uint64_t header_line = lines_.line_number();
    if (binary_) {
      if (binary_reader_.msh41_entities(header_line, volumes_)) {
        expect_gmsh_marker(lines_, sink_, "$EndEntities", "the last entity");
      }
      return;
    }
    if (!next_record("$Entities") ||
        !expect_tokens(4, "'numPoints numCurves numSurfaces numVolumes'")) {
      return;
    }
    std::uint64_t counts[4];
    for (int d = 0; d < 4; ++d) {
      if (!parse_count(sink_, lines_.line_number(), tokens_[d], lines_.remaining_bytes(), counts[d])) return;
    }
    static constexpr std::string_view kKinds[] = {"point", "curve", "surface", "volume"};
    for (std::size_t d = 0; d < 4; ++d) {
      const std::size_t coordinates = d == 0 ? 3 : 6;
      const std::string where = "$Entities (" + std::string(kKinds[d]) + "s)";
      for (std::uint64_t e = 0; e < counts[d]; ++e) {
        if (!next_record(where)) return;
        const std::uint64_t at = lines_.line_number();
        // tag, coordinates, numPhysicalTags [, numBounding]: the fields every entity has; each
        // count must fit in the line (a count token that is no count fits nothing).
        const std::size_t fixed = 1 + coordinates + 1 + (d > 0 ? 1 : 0);
        const auto count_at = [&](std::size_t i, std::uint64_t& n) {
          return i < tokens_.size() && parse_u64(tokens_[i], n) && n <= tokens_.size();
        };
        std::uint64_t num_physical = 0;
        std::uint64_t num_bounding = 0;
        if (tokens_.size() < fixed || !count_at(1 + coordinates, num_physical) ||
            (d > 0 && !count_at(2 + coordinates + num_physical, num_bounding)) ||
            tokens_.size() != fixed + num_physical + num_bounding) {
          sink_.fail(at, "expected a " + std::string(kKinds[d]) + " entity 'tag " +
                             (d == 0 ? "x y z" : "minX minY minZ maxX maxY maxZ") + " numPhysicalTags tag..." +
                             (d == 0 ? "" : " numBounding tag...") + "', got " + std::to_string(tokens_.size()) +
                             " values");
          return;
        }
        std::int64_t tag = 0;
        if (!expect_int_tokens(0, 1, "entity tag") || !parse_i64(tokens_[0], tag)) return;
        for (std::size_t c = 1; c <= coordinates; ++c) {
          double x = 0;
          if (!parse_coordinate(sink_, at, tokens_[c], x)) return;
        }
        std::optional<std::uint32_t> label;  // a volume's first physical tag
        if (d == 3 && num_physical > 0) {
          std::uint32_t first = 0;
          if (!parse_label(sink_, at, tokens_[2 + coordinates], "physical tag", first)) return;
          label = first;
        }
        if (!expect_int_tokens(2 + coordinates, num_physical, "physical tag") ||
            !expect_int_tokens(fixed + num_physical, num_bounding, "bounding entity")) {
          return;
        }
        if (d == 3) {
          if (!volumes_.add(sink_, at, tag, label)) return;
        }
      }
    }
    expect_gmsh_marker(lines_, sink_, "$EndEntities", "the last entity");
  }

  void read_nodes() override {
    if (binary_) {
      if (binary_reader_.msh41_nodes(lines_.line_number())) {
        expect_gmsh_marker(lines_, sink_, "$EndNodes", "the last node block");
      }
      return;
    }
    std::uint64_t blocks = 0;
    std::uint64_t total = 0;
    if (!read_header("$Nodes", blocks, total)) return;
    mesh_.positions.reserve(total);
    for (std::uint64_t b = 0; b < blocks; ++b) {
      if (!next_block_header("$Nodes", "'entityDim entityTag parametric numNodesInBlock'")) return;
      std::uint64_t n = 0;
      std::int64_t parametric = 0;
      if (!parse_i64(tokens_[2], parametric) || (parametric != 0 && parametric != 1)) {
        sink_.fail(lines_.line_number(), "parametric must be 0 or 1, got " + quote(tokens_[2]));
        return;
      }
      if (!block_size("node", mesh_.positions.size(), total, n)) return;
      for (std::uint64_t i = 0; i < n; ++i) {
        if (!next_record("$Nodes (node tags)") || !expect_tokens(1, "one node tag")) return;
        std::int64_t id = 0;
        if (!parse_id(sink_, lines_.line_number(), tokens_[0], id)) return;
        if (!ids_.insert(id, static_cast<std::uint32_t>(mesh_.positions.size() + i))) {
          sink_.fail(lines_.line_number(), "duplicate node id " + std::to_string(id));
          return;
        }
      }
      for (std::uint64_t i = 0; i < n; ++i) {
        if (!next_record("$Nodes (coordinates)")) return;
        const std::size_t expected = parametric == 0 ? 3 : 0;
        if ((expected == 3 && tokens_.size() != 3) || tokens_.size() < 3 || tokens_.size() > 6) {
          sink_.fail(lines_.line_number(), "expected 3 coordinates, got " + std::to_string(tokens_.size()) + " values");
          return;
        }
        Vec3 p;
        if (!parse_point(sink_, lines_.line_number(), tokens_.data(), p)) return;
        mesh_.positions.push_back(p);
      }
    }
    end_blocks("node", mesh_.positions.size(), total, "$EndNodes");
  }

  void read_elements() override {
    elements_read_ = true;
    if (binary_) {
      if (binary_reader_.msh41_elements(lines_.line_number(), volumes_)) {
        expect_gmsh_marker(lines_, sink_, "$EndElements", "the last element block");
      }
      return;
    }
    std::uint64_t blocks = 0;
    std::uint64_t total = 0;
    if (!read_header("$Elements", blocks, total)) return;
    mesh_.tets.reserve(total);
    std::uint64_t seen = 0;
    for (std::uint64_t b = 0; b < blocks; ++b) {
      if (!next_block_header("$Elements", "'entityDim entityTag elementType numElementsInBlock'")) return;
      std::int64_t dim = 0;
      std::int64_t entity = 0;
      std::int64_t type = 0;
      std::uint64_t n = 0;
      if (!parse_i64(tokens_[0], dim) || !parse_i64(tokens_[1], entity)) {
        sink_.fail(lines_.line_number(), "entity dimension and tag must be integers, got " + quote(tokens_[0]) +
                                             " " + quote(tokens_[1]));
        return;
      }
      if (!parse_gmsh_type(sink_, lines_.line_number(), tokens_[2], type)) return;
      if ((type == kGmshTet4 || type == kGmshTet10) &&
          !volumes_.label_block(sink_, lines_.line_number(), dim, entity, elements_)) {
        return;
      }
      if (!block_size("element", seen, total, n)) return;
      for (std::uint64_t i = 0; i < n; ++i) {
        if (!next_record("$Elements")) return;
        std::int64_t id = 0;
        if (!parse_id(sink_, lines_.line_number(), tokens_[0], id)) return;
        if (!elements_.add(sink_, lines_.line_number(), type, tokens_.data() + 1, tokens_.size() - 1)) return;
      }
      seen += n;
    }
    end_blocks("element", seen, total, "$EndElements");
  }

  GmshVolumeLabels volumes_;
  bool entities_read_ = false;
  bool elements_read_ = false;
};

// The bounding box of every position ({0,0,0}, {0,0,0} for none), for the volume entity.
std::array<double, 6> bounding_box(const RawMesh& mesh) {
  Vec3 lo{0, 0, 0};
  Vec3 hi{0, 0, 0};
  if (!mesh.positions.empty()) {
    lo = hi = mesh.positions[0];
    for (const Vec3& p : mesh.positions) {
      lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
      hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
    }
  }
  return {lo.x, lo.y, lo.z, hi.x, hi.y, hi.z};
}

// A labelled mesh as MSH 4.1 volumes: the distinct labels in increasing order (volume tag =
// index + 1, physical tag = the label), the bounding box of each volume's tets, and the runs of
// consecutive tets with one label (an element block each, so the tets keep their order).
struct LabelledVolumes {
  struct Run {
    std::size_t first;
    std::size_t count;
    std::uint64_t volume;  // its tag
  };
  std::vector<std::uint32_t> labels;
  std::vector<std::array<double, 6>> boxes;
  std::vector<Run> runs;

  explicit LabelledVolumes(const RawMesh& mesh) : labels(mesh.labels) {
    std::sort(labels.begin(), labels.end());
    labels.erase(std::unique(labels.begin(), labels.end()), labels.end());
    std::vector<bool> seen(labels.size(), false);
    boxes.resize(labels.size());
    for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
      const std::size_t v = volume_index(mesh.labels[t]);
      if (runs.empty() || runs.back().volume != v + 1) runs.push_back({t, 0, v + 1});
      ++runs.back().count;
      for (std::uint32_t corner : mesh.tets[t]) {
        const Vec3& p = mesh.positions[corner];
        std::array<double, 6>& b = boxes[v];
        if (!seen[v]) b = {p.x, p.y, p.z, p.x, p.y, p.z};
        seen[v] = true;
        b = {std::min(b[0], p.x), std::min(b[1], p.y), std::min(b[2], p.z),
             std::max(b[3], p.x), std::max(b[4], p.y), std::max(b[5], p.z)};
      }
    }
  }

  [[nodiscard]] std::size_t volume_index(std::uint32_t label) const {
    return static_cast<std::size_t>(std::lower_bound(labels.begin(), labels.end(), label) - labels.begin());
  }
};

// A block header "entityDim(3) entityTag <kind> n", kind = parametric flag (0) or element type.
void append_block_header(std::string& out, std::uint64_t entity, std::uint64_t kind, std::uint64_t n) {
  out += "3 ";
  append_uint(out, entity);
  out += ' ';
  append_uint(out, kind);
  out += ' ';
  append_uint(out, n);
  out += '\n';
}

void append_section_header(std::string& out, std::uint64_t blocks, std::uint64_t n) {
  // minTag is 1 (written as `blocks` so that an empty section reads "0 0 0 0"), maxTag n.
  for (std::uint64_t v : {blocks, n, std::min<std::uint64_t>(blocks, 1)}) {
    append_uint(out, v);
    out += ' ';
  }
  append_uint(out, n);
  out += '\n';
}

// The unlabelled writers put all `n` nodes (or elements) of a section in one block of volume 1,
// tagged 1 to n: the section header "numEntityBlocks n minTag maxTag" and, when n > 0, the block
// header. (Labelled, the nodes still do; the elements come in runs.)
void append_single_block_headers(std::string& out, std::uint64_t n, std::uint64_t kind) {
  const std::uint64_t blocks = n > 0 ? 1 : 0;
  append_section_header(out, blocks, n);
  if (n > 0) append_block_header(out, 1, kind, n);
}

// The same headers in a binary file: sizes are 8 bytes, dimension, tag and kind 4-byte ints.
constexpr auto kBinaryOrder = ByteOrder::kLittle;
void put_int(std::string& out, std::uint64_t v) { store_uint(out, v, 4, kBinaryOrder); }
void put_size(std::string& out, std::uint64_t v) { store_uint(out, v, 8, kBinaryOrder); }

void store_section_header(std::string& out, std::uint64_t blocks, std::uint64_t n) {
  for (std::uint64_t v : {blocks, n, std::min<std::uint64_t>(blocks, 1), n}) put_size(out, v);
}

void store_block_header(std::string& out, std::uint64_t entity, std::uint64_t kind, std::uint64_t n) {
  for (std::uint64_t v : {std::uint64_t{3}, entity, kind}) put_int(out, v);
  put_size(out, n);
}

void store_single_block_headers(std::string& out, std::uint64_t n, std::uint64_t kind) {
  const std::uint64_t blocks = n > 0 ? 1 : 0;
  store_section_header(out, blocks, n);
  if (n > 0) store_block_header(out, 1, kind, n);
}

void store_tet(std::string& out, const RawMesh& mesh, std::size_t t) {
  put_size(out, t + 1);
  for (std::uint32_t v : mesh.tets[t]) put_size(out, std::uint64_t{v} + 1);
}

// The ASCII $Nodes body: one block on entity 0, every node numbered 1.. in order.
void append_nodes_section(std::string& out, const std::vector<Vec3>& positions) {
  append_single_block_headers(out, positions.size(), 0);
  for (std::uint64_t i = 0; i < positions.size(); ++i) {
    append_uint(out, i + 1);
    out += '\n';
  }
  append_point_lines(out, positions);
}

}  // namespace

ReadResult read_msh41(std::string_view text, std::string_view name) {
  return Msh41Reader(text, name).read();
}

std::string format_msh41(const RawMesh& mesh) {
  std::string out;
  out.reserve(256 + mesh.positions.size() * 64 + mesh.tets.size() * 40);
  out += "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";
  if (mesh.labelled()) {
    const LabelledVolumes volumes(mesh);
    out += "$Entities\n0 0 0 ";
    append_uint(out, volumes.labels.size());
    out += '\n';
    for (std::size_t v = 0; v < volumes.labels.size(); ++v) {
      append_uint(out, v + 1);
      out += ' ';
      for (double c : volumes.boxes[v]) {
        append_double(out, c);
        out += ' ';
      }
      out += "1 ";
      append_uint(out, volumes.labels[v]);
      out += " 0\n";
    }
    out += "$EndEntities\n$Nodes\n";
    append_nodes_section(out, mesh.positions);
    out += "$EndNodes\n$Elements\n";
    append_section_header(out, volumes.runs.size(), mesh.tets.size());
    for (const LabelledVolumes::Run& run : volumes.runs) {
      append_block_header(out, run.volume, kGmshTet4, run.count);
      for (std::size_t t = run.first; t < run.first + run.count; ++t) {
        append_uint(out, t + 1);
        for (std::uint32_t v : mesh.tets[t]) {
          out += ' ';
          append_uint(out, std::uint64_t{v} + 1);
        }
        out += '\n';
      }
    }
    out += "$EndElements\n";
    return out;
  }
  // One volume entity (tag 1) holding everything, with its bounding box, as Gmsh expects.
  out += "$Entities\n0 0 0 1\n1 ";
  for (double c : bounding_box(mesh)) {
    append_double(out, c);
    out += ' ';
  }
  out += "0 0\n$EndEntities\n$Nodes\n";
  append_nodes_section(out, mesh.positions);
  out += "$EndNodes\n$Elements\n";
  append_single_block_headers(out, mesh.tets.size(), kGmshTet4);
  append_numbered_tets(out, mesh.tets);
  out += "$EndElements\n";
  return out;
}

std::string format_msh41_binary(const RawMesh& mesh) {
  std::string out;
  out.reserve(256 + mesh.positions.size() * 32 + mesh.tets.size() * 40);
  out += "$MeshFormat\n4.1 1 8\n";
  put_int(out, 1);  // the check value that tells readers the byte order
  out += "\n$EndMeshFormat\n$Entities\n";
  const std::optional<LabelledVolumes> labelled =
      mesh.labelled() ? std::optional<LabelledVolumes>(mesh) : std::nullopt;
  if (labelled) {
    // No points, curves or surfaces; a volume per label (its box, one physical tag, no bounding
    // surfaces).
    const LabelledVolumes& volumes = *labelled;
    for (std::uint64_t n : {std::size_t{0}, std::size_t{0}, std::size_t{0}, volumes.labels.size()}) put_size(out, n);
    for (std::size_t v = 0; v < volumes.labels.size(); ++v) {
      put_int(out, v + 1);
      for (double c : volumes.boxes[v]) store_f64(out, c, kBinaryOrder);
      put_size(out, 1);
      put_int(out, volumes.labels[v]);
      put_size(out, 0);
    }
    out += "\n$EndEntities\n$Nodes\n";
  } else {
    // No points, curves or surfaces; one volume (tag 1) with its bounding box, no physical tags
    // and no bounding surfaces.
    for (std::uint64_t n : {0, 0, 0, 1}) put_size(out, n);
    put_int(out, 1);
    for (double c : bounding_box(mesh)) store_f64(out, c, kBinaryOrder);
    put_size(out, 0);
    put_size(out, 0);
    out += "\n$EndEntities\n$Nodes\n";
  }
  store_single_block_headers(out, mesh.positions.size(), 0);
  for (std::uint64_t i = 0; i < mesh.positions.size(); ++i) put_size(out, i + 1);
  for (const Vec3& p : mesh.positions) {
    for (double c : {p.x, p.y, p.z}) store_f64(out, c, kBinaryOrder);
  }
  out += "\n$EndNodes\n$Elements\n";
  if (labelled) {
    store_section_header(out, labelled->runs.size(), mesh.tets.size());
    for (const LabelledVolumes::Run& run : labelled->runs) {
      store_block_header(out, run.volume, kGmshTet4, run.count);
      for (std::size_t t = run.first; t < run.first + run.count; ++t) store_tet(out, mesh, t);
    }
  } else {
    store_single_block_headers(out, mesh.tets.size(), kGmshTet4);
    for (std::size_t t = 0; t < mesh.tets.size(); ++t) store_tet(out, mesh, t);
  }
  out += "\n$EndElements\n";
  return out;
}

}  // namespace tetcut
