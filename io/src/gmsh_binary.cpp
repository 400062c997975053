#include "gmsh_binary.hpp"

#include <cmath>
#include <limits>
#include <string>

namespace tetcut::io_detail {

namespace {

constexpr std::uint64_t kMaxInt64 = static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max());

const unsigned char* bytes_of(std::string_view s) { return reinterpret_cast<const unsigned char*>(s.data()); }

}  // namespace

bool GmshBinaryReader::take(std::uint64_t n, std::string_view what, std::uint64_t line, std::string_view& bytes) {
  if (n > lines_.remaining_bytes() || !lines_.take_bytes(static_cast<std::size_t>(n), bytes)) {
    return sink_.fail(line, "binary " + std::string(what) + " needs " + std::to_string(n) + " bytes, " +
                                std::to_string(lines_.remaining_bytes()) + " remain (truncated file?)");
  }
  return true;
}

bool GmshBinaryReader::check_count(std::uint64_t count, std::uint64_t record_bytes, std::string_view what,
                                   std::uint64_t line) {
  if (count > lines_.remaining_bytes() / record_bytes || count > 0xFFFFFFFEull) {
    return sink_.fail(line, "count " + std::to_string(count) + " of " + std::string(what) + " exceeds file size");
  }
  return true;
}

bool GmshBinaryReader::read_check_value(std::uint64_t size_bytes) {
  const std::uint64_t line = lines_.line_number();
  if (size_bytes != 4 && size_bytes != 8) {
    return sink_.fail(line, "data-size must be 4 or 8 in a binary MSH file, got " + std::to_string(size_bytes));
  }
  size_bytes_ = static_cast<std::size_t>(size_bytes);
  std::string_view one;
  if (!lines_.take_bytes(4, one)) return sink_.fail(line, "unexpected end of file: missing the binary check value (int 1)");
  if (load_uint(bytes_of(one), 4, ByteOrder::kLittle) == 1) {
    order_ = ByteOrder::kLittle;
  } else if (load_uint(bytes_of(one), 4, ByteOrder::kBig) == 1) {
    order_ = ByteOrder::kBig;
  } else {
    return sink_.fail(line + 1, "binary check value " + quote(one) + " is not the int 1 in either byte order");
  }
  return true;
}

bool GmshBinaryReader::msh22_nodes(std::uint64_t count, std::uint64_t line) {
  constexpr std::uint64_t kRecord = 4 + 3 * 8;
  std::string_view data;
  if (!check_count(count, kRecord, "nodes", line) || !take(count * kRecord, "$Nodes", line, data)) return false;
  mesh_.positions.reserve(mesh_.positions.size() + count);
  const unsigned char* p = bytes_of(data);
  for (std::uint64_t i = 0; i < count; ++i, p += kRecord) {
    const std::int64_t id = int_at(p);
    const Vec3 x{load_f64(p + 4, order_), load_f64(p + 12, order_), load_f64(p + 20, order_)};
    if (!is_finite(x)) return sink_.fail(line, "non-finite coordinate at node id " + std::to_string(id));
    if (!ids_.insert(id, static_cast<std::uint32_t>(mesh_.positions.size()))) {
      return sink_.fail(line, "duplicate node id " + std::to_string(id));
    }
    mesh_.positions.push_back(x);
  }
  return true;
}

bool GmshBinaryReader::msh22_elements(std::uint64_t count, std::uint64_t line) {
  if (!check_count(count, 8, "elements", line)) return false;
  std::int64_t ids[10];
  for (std::uint64_t seen = 0; seen < count;) {
    std::string_view header;
    if (!take(12, "$Elements block header", line, header)) return false;
    const std::int64_t type = int_at(bytes_of(header));
    const std::int64_t n = int_at(bytes_of(header) + 4);
    const std::int64_t tags = int_at(bytes_of(header) + 8);
    const std::size_t nodes = gmsh_type_nodes(type);
    if (nodes == 0) return sink_.fail(line, "unknown element type " + std::to_string(type) + " in binary $Elements");
    if (n <= 0 || static_cast<std::uint64_t>(n) > count - seen) {
      return sink_.fail(line, "element block of " + std::to_string(n) + " elements after " + std::to_string(seen) +
                                  " of the " + std::to_string(count) + " declared");
    }
    if (tags < 0 || static_cast<std::uint64_t>(tags) > lines_.remaining_bytes() / 4) {
      return sink_.fail(line, "bad number of tags " + std::to_string(tags) + " in an element block");
    }
    const std::uint64_t record = 4 * (1 + static_cast<std::uint64_t>(tags) + nodes);
    std::string_view data;
    if (static_cast<std::uint64_t>(n) > lines_.remaining_bytes() / record) {
      return sink_.fail(line, "element block of " + std::to_string(n) + " elements exceeds file size");
    }
    if (!take(static_cast<std::uint64_t>(n) * record, "$Elements block", line, data)) return false;
    if (type != kGmshTet4 && type != kGmshTet10) {
      elements_.ignore(type, static_cast<std::uint64_t>(n));
    } else {
      const unsigned char* p = bytes_of(data);
      for (std::int64_t e = 0; e < n; ++e, p += record) {
        for (std::size_t k = 0; k < nodes; ++k) ids[k] = int_at(p + 4 * (1 + static_cast<std::size_t>(tags) + k));
        elements_.label.reset();
        if (tags > 0) {  // the first tag is the physical group (msh22.cpp)
          std::uint32_t label = 0;
          if (!check_label(sink_, line, int_at(p + 4), "physical tag", label)) return false;
          elements_.label = label;
        }
        if (!elements_.add_ids(sink_, line, type, ids, nodes)) return false;
      }
    }
    seen += static_cast<std::uint64_t>(n);
  }
  return true;
}

bool GmshBinaryReader::msh41_section_header(std::string_view section, std::string_view noun,
                                            std::uint64_t entry_bytes, std::uint64_t line, std::uint64_t& blocks,
                                            std::uint64_t& total) {
  const std::uint64_t s = size_bytes_;
  std::string_view header;
  if (!take(4 * s, std::string(section) + " header", line, header)) return false;
  blocks = size_at(bytes_of(header));
  total = size_at(bytes_of(header) + s);
  return check_count(blocks, 12 + s, std::string(noun) + " blocks", line) &&
         check_count(total, entry_bytes, std::string(noun) + "s", line);
}

bool GmshBinaryReader::msh41_nodes(std::uint64_t line) {
  const std::uint64_t s = size_bytes_;
  std::uint64_t blocks = 0;
  std::uint64_t total = 0;
  if (!msh41_section_header("$Nodes", "node", s + 24, line, blocks, total)) return false;
  mesh_.positions.reserve(total);
  for (std::uint64_t b = 0; b < blocks; ++b) {
    std::string_view block;
    if (!take(12 + s, "$Nodes block header", line, block)) return false;
    const std::int64_t dim = int_at(bytes_of(block));
    const std::int64_t parametric = int_at(bytes_of(block) + 8);
    const std::uint64_t n = size_at(bytes_of(block) + 12);
    if (parametric != 0 && parametric != 1) return sink_.fail(line, "parametric must be 0 or 1, got " + std::to_string(parametric));
    if (dim < 0 || dim > 3) return sink_.fail(line, "entity dimension must be 0 to 3, got " + std::to_string(dim));
    const std::uint64_t values = 3 + (parametric == 1 ? static_cast<std::uint64_t>(dim) : 0);
    if (!check_block_fits(sink_, line, "node", mesh_.positions.size(), n, total)) return false;
    std::string_view tags;
    std::string_view coordinates;
    if (!take(n * s, "$Nodes tags", line, tags) || !take(n * 8 * values, "$Nodes coordinates", line, coordinates)) return false;
    for (std::uint64_t i = 0; i < n; ++i) {
      const std::uint64_t tag = size_at(bytes_of(tags) + i * s);
      const unsigned char* c = bytes_of(coordinates) + i * 8 * values;
      const Vec3 x{load_f64(c, order_), load_f64(c + 8, order_), load_f64(c + 16, order_)};
      if (tag > kMaxInt64) return sink_.fail(line, "node tag " + std::to_string(tag) + " out of range");
      if (!is_finite(x)) return sink_.fail(line, "non-finite coordinate at node tag " + std::to_string(tag));
      if (!ids_.insert(static_cast<std::int64_t>(tag), static_cast<std::uint32_t>(mesh_.positions.size()))) {
        return sink_.fail(line, "duplicate node id " + std::to_string(tag));
      }
      mesh_.positions.push_back(x);
    }
  }
  return check_blocks_add_up(sink_, line, "node", mesh_.positions.size(), total);
}

bool GmshBinaryReader::msh41_entities(std::uint64_t line, GmshVolumeLabels& volumes) {
  // Per entity: tag (int), a point (3 doubles) or a box (6), numPhysicalTags (size_t) and the
  // tags (ints), then for curves, surfaces, volumes numBounding (size_t) and their tags (ints).
  const std::uint64_t s = size_bytes_;
  std::string_view header;
  if (!take(4 * s, "$Entities header", line, header)) return false;
  static constexpr std::string_view kKinds[] = {"points", "curves", "surfaces", "volumes"};
  std::uint64_t counts[4];
  for (int d = 0; d < 4; ++d) {
    counts[d] = size_at(bytes_of(header) + d * s);
    if (!check_count(counts[d], 4 + 24 + s, "$Entities " + std::string(kKinds[d]), line)) return false;
  }
  for (std::uint64_t d = 0; d < 4; ++d) {
    const std::uint64_t fixed = 4 + (d == 0 ? 24 : 48) + s;
    for (std::uint64_t e = 0; e < counts[d]; ++e) {
      std::string_view entity;
      std::string_view physical;
      if (!take(fixed, "$Entities entity", line, entity)) return false;
      const std::int64_t tag = int_at(bytes_of(entity));
      const std::uint64_t num_physical = size_at(bytes_of(entity) + fixed - s);
      if (!check_count(num_physical, 4, "physical tags", line) ||
          !take(num_physical * 4, "$Entities physical tags", line, physical)) {
        return false;
      }
      if (d > 0) {
        std::string_view count;
        std::string_view bounding;
        if (!take(s, "$Entities bounding count", line, count)) return false;
        const std::uint64_t num_bounding = size_at(bytes_of(count));
        if (!check_count(num_bounding, 4, "bounding entities", line) ||
            !take(num_bounding * 4, "$Entities bounding entities", line, bounding)) {
          return false;
        }
      }
      if (d == 3) {
        std::optional<std::uint32_t> label;
        if (num_physical > 0) {
          std::uint32_t first = 0;
          if (!check_label(sink_, line, int_at(bytes_of(physical)), "physical tag", first)) return false;
          label = first;
        }
        if (!volumes.add(sink_, line, tag, label)) return false;
      }
    }
  }
  return true;
}

bool GmshBinaryReader::msh41_elements(std::uint64_t line, const GmshVolumeLabels& volumes) {
  const std::uint64_t s = size_bytes_;
  std::uint64_t blocks = 0;
  std::uint64_t total = 0;
  if (!msh41_section_header("$Elements", "element", 2 * s, line, blocks, total)) return false;
  std::uint64_t seen = 0;
  std::int64_t ids[10];
  for (std::uint64_t b = 0; b < blocks; ++b) {
    std::string_view block;
    if (!take(12 + s, "$Elements block header", line, block)) return false;
    const std::int64_t dim = int_at(bytes_of(block));
    const std::int64_t entity = int_at(bytes_of(block) + 4);
    const std::int64_t type = int_at(bytes_of(block) + 8);
    const std::uint64_t n = size_at(bytes_of(block) + 12);
    const std::size_t nodes = gmsh_type_nodes(type);
    if (nodes == 0) return sink_.fail(line, "unknown element type " + std::to_string(type) + " in binary $Elements");
    if (!check_block_fits(sink_, line, "element", seen, n, total)) return false;
    const std::uint64_t record = s * (1 + nodes);
    std::string_view data;
    if (!take(n * record, "$Elements block", line, data)) return false;
    if (type != kGmshTet4 && type != kGmshTet10) {
      elements_.ignore(type, n);
    } else {
      if (!volumes.label_block(sink_, line, dim, entity, elements_)) return false;
      for (std::uint64_t e = 0; e < n; ++e) {
        const unsigned char* p = bytes_of(data) + e * record;
        for (std::size_t k = 0; k < nodes; ++k) {
          const std::uint64_t tag = size_at(p + s * (1 + k));
          if (tag > kMaxInt64) return sink_.fail(line, "node id " + std::to_string(tag) + " not defined");
          ids[k] = static_cast<std::int64_t>(tag);
        }
        if (!elements_.add_ids(sink_, line, type, ids, nodes)) return false;
      }
    }
    seen += n;
  }
  return check_blocks_add_up(sink_, line, "element", seen, total);
}

}  // namespace tetcut::io_detail
