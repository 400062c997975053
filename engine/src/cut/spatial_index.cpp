#include "cut/spatial_index.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

#include "core/random.hpp"
#include "tetcut/detail/local_tables.hpp"
#include "tetcut/detail/reserve_touched.hpp"

namespace tetcut {
namespace {

// std::nextafter(x, +inf) for a float x >= 0, as its bits: the same value without a call into
// libm, once per tet indexed.
float next_up(float x) {
  return x == std::numeric_limits<float>::infinity() ? x : std::bit_cast<float>(std::bit_cast<std::uint32_t>(x) + 1);
}

}  // namespace

std::int32_t SpatialIndex::cell_coordinate(double x, double cell_size) {
  // Clamped to 21 bits of signed range: a mesh a million cells wide is already absurd.
  const double c = std::floor(x / cell_size);
  return static_cast<std::int32_t>(std::clamp(c, -1048575.0, 1048575.0));
}

std::uint64_t SpatialIndex::pack(std::int32_t i, std::int32_t j, std::int32_t k) {
  auto bits = [](std::int32_t v) { return static_cast<std::uint64_t>(v + 1048576) & 0x1FFFFFu; };
  return (bits(i) << 42) | (bits(j) << 21) | bits(k);
}

std::array<std::int32_t, 3> SpatialIndex::unpack(std::uint64_t key) {
  auto value = [](std::uint64_t b) { return static_cast<std::int32_t>(b & 0x1FFFFFu) - 1048576; };
  return {value(key >> 42), value(key >> 21), value(key)};
}

std::size_t SpatialIndex::find_slot(std::uint64_t key) const {
  if (table_.empty()) return kNoSlot;
  const std::size_t mask = table_.size() - 1;
  for (std::size_t s = mix64(key) & mask;; s = (s + 1) & mask) {
    if (!table_[s].used()) return kNoSlot;
    if (table_[s].key == key) return s;
  }
}

void SpatialIndex::grow_table() {
  std::vector<Slot> old;
  old.swap(table_);
  table_.assign(old.empty() ? 1024 : old.size() * 2, Slot{});
  const std::size_t mask = table_.size() - 1;
  for (const Slot& o : old) {
    if (!o.used()) continue;
    std::size_t s = mix64(o.key) & mask;
    while (table_[s].used()) s = (s + 1) & mask;
    table_[s] = o;
    for (std::uint32_t b = o.head; b != kNone; b = blocks_[b].next) blocks_[b].slot = static_cast<std::uint32_t>(s);
  }
}

std::size_t SpatialIndex::cell_for(std::uint64_t key) {
  if ((used_slots_ + 1) * 2 > table_.size()) grow_table();
  const std::size_t mask = table_.size() - 1;
  std::size_t s = mix64(key) & mask;
  for (; table_[s].used(); s = (s + 1) & mask)
    if (table_[s].key == key) return s;
  // Cells are never deleted: an emptied cell keeps its slot for the next tets there.
  table_[s] = {key, kNone, kNone, 0.0f};
  ++used_slots_;
  return s;
}

std::uint32_t SpatialIndex::new_block() {
  if (free_block_ != kNone) {
    const std::uint32_t b = free_block_;
    free_block_ = blocks_[b].next;
    blocks_[b] = Block{};
    return b;
  }
  blocks_.emplace_back();
  return static_cast<std::uint32_t>(blocks_.size() - 1);
}

void SpatialIndex::build(const TetMesh& mesh, Keep keep) {
  table_.clear();
  used_slots_ = 0;
  blocks_.clear();
  free_block_ = kNone;
  // The locations' room first, at the size the cuts will want: growing it after the build would
  // hold the old and the new array at once, the Cutter's peak.
  where_.clear();
  detail::reserve_touched(where_, mesh.tet_capacity() + mesh.tet_capacity() / 2 + 1024);
  where_.assign(mesh.tet_capacity(), Location{});
  entries_ = 0;
  reach_ = 0.0;
  occupied_lo_ = {1, 1, 1};
  occupied_hi_ = {0, 0, 0};
  for (std::uint32_t t = 0; t < mesh.tet_capacity(); ++t)
    if (mesh.is_live(TetId{t}) && (!keep || keep(mesh, TetId{t}))) insert(mesh, TetId{t});
  // Headroom, so that the cuts that follow find locations, blocks and slots without growing.
  detail::reserve_touched(blocks_, blocks_.size() + blocks_.size() / 2 + 256);
  while ((used_slots_ + used_slots_ / 2 + 1) * 2 > table_.size()) grow_table();
}

void SpatialIndex::insert(const TetMesh& mesh, TetId t) {
  if (where_.size() <= t.value) where_.resize(std::max<std::size_t>(t.value + 1, where_.size() * 3 / 2));
  if (where_[t.value].indexed()) erase(t);
  const auto v = mesh.tet(t);
  const Vec3 p[4] = {mesh.position(v[0]), mesh.position(v[1]), mesh.position(v[2]), mesh.position(v[3])};
  const Vec3 c = 0.25 * (p[0] + p[1] + p[2] + p[3]);
  double r2 = 0.0;
  for (const Vec3& q : p) r2 = std::max(r2, dot(q - c, q - c));
  // Single precision: the centroid moves by at most `slack` when rounded; the outer radius grows
  // by that (and is rounded outwards).
  const float fx = static_cast<float>(c.x), fy = static_cast<float>(c.y), fz = static_cast<float>(c.z);
  const double slack = 1e-6 * (std::abs(c.x) + std::abs(c.y) + std::abs(c.z)) + 1e-30;
  const float outer = next_up(static_cast<float>(std::sqrt(r2) * (1.0 + 1e-6) + slack));
  const std::int32_t i = cell_of(c.x), j = cell_of(c.y), k = cell_of(c.z);
  if (occupied_lo_[0] > occupied_hi_[0]) {
    occupied_lo_ = occupied_hi_ = {i, j, k};
  } else {
    occupied_lo_ = {std::min(occupied_lo_[0], i), std::min(occupied_lo_[1], j), std::min(occupied_lo_[2], k)};
    occupied_hi_ = {std::max(occupied_hi_[0], i), std::max(occupied_hi_[1], j), std::max(occupied_hi_[2], k)};
  }
  const std::size_t slot = cell_for(pack(i, j, k));
  Slot& cell = table_[slot];
  cell.reach = std::max(cell.reach, outer);
  reach_ = std::max(reach_, static_cast<double>(outer));
  if (cell.tail == kNone || blocks_[cell.tail].count == kBlockEntries) {
    const std::uint32_t b = new_block();  // may move blocks_, never table_
    blocks_[b].slot = static_cast<std::uint32_t>(slot);
    if (cell.tail == kNone) {
      cell.head = b;
    } else {
      blocks_[cell.tail].next = b;
    }
    cell.tail = b;
  }
  Block& block = blocks_[cell.tail];
  const std::uint32_t e = block.count;
  block.x[e] = fx;
  block.y[e] = fy;
  block.z[e] = fz;
  block.outer[e] = outer;
  block.tet[e] = t.value;
  where_[t.value] = Location{cell.tail, block.count};
  ++block.count;
  ++entries_;
}

void SpatialIndex::erase(TetId t) {
  if (t.value >= where_.size() || !where_[t.value].indexed()) return;
  const Location at = where_[t.value];
  where_[t.value] = Location{};
  --entries_;
  // The cell's last entry fills the hole. The cell is the one whose chain holds the block.
  Slot& cell = table_[blocks_[at.block()].slot];
  Block& tail = blocks_[cell.tail];
  const std::uint32_t last = tail.count - 1;
  --tail.count;
  if (tail.tet[last] != t.value) {
    Block& hole = blocks_[at.block()];
    hole.x[at.index()] = tail.x[last];
    hole.y[at.index()] = tail.y[last];
    hole.z[at.index()] = tail.z[last];
    hole.outer[at.index()] = tail.outer[last];
    hole.tet[at.index()] = tail.tet[last];
    where_[tail.tet[last]] = at;
  }
  if (tail.count == 0 && cell.tail != cell.head) {
    const std::uint32_t b = cell.tail;
    std::uint32_t before = cell.head;
    while (blocks_[before].next != b) before = blocks_[before].next;
    cell.tail = before;
    blocks_[cell.tail].next = kNone;
    blocks_[b].next = free_block_;
    free_block_ = b;
  }
}

void SpatialIndex::apply(const TetMesh& mesh, const ChangeLog& log, std::size_t removed_from, std::size_t created_from) {
  for (std::size_t i = removed_from; i < log.removed.size(); ++i) erase(log.removed[i]);
  for (std::size_t i = created_from; i < log.created.size(); ++i) {
    const TetId t = log.created[i].tet;
    // A tet created and removed again within the log is gone; a reused id is re-indexed.
    if (mesh.is_live(t)) insert(mesh, t);
  }
}

// Distance from the interval [q_lo, q_hi] to slab i of cells along one axis (0 when they meet).
double SpatialIndex::axis_gap(std::int32_t i, double q_lo, double q_hi) const {
  const double lo = i * cell_size_, hi = lo + cell_size_;
  return q_hi < lo ? lo - q_hi : q_lo > hi ? q_lo - hi : 0.0;
}

// Distance from the box [lo, hi] to the box of cell `key` (0 when they meet). query() computes
// the same sum axis by axis in its loops: keep the two in step (the same bits decide which cells
// are passed over).
double SpatialIndex::gap_to_cell(const Vec3& lo, const Vec3& hi, std::uint64_t key) const {
  const std::array<std::int32_t, 3> ijk = unpack(key);
  const double gx = axis_gap(ijk[0], lo.x, hi.x), gy = axis_gap(ijk[1], lo.y, hi.y), gz = axis_gap(ijk[2], lo.z, hi.z);
  return std::sqrt(gx * gx + gy * gy + gz * gz);
}

void SpatialIndex::query(const TetMesh& mesh, const Tool& tool, std::vector<TetId>& out) {
  out.clear();
  if (occupied_lo_[0] > occupied_hi_[0]) return;  // nothing was ever indexed
  if (tool.is_ball()) query_cells<false>(mesh, tool, out);
  else query_cells<true>(mesh, tool, out);
  std::sort(out.begin(), out.end());
}

template <bool kCapsule>
void SpatialIndex::query_cells(const TetMesh& mesh, const Tool& tool, std::vector<TetId>& out) {
  // The axis's box: the centre of a ball.
  const Vec3 c_lo{std::min(tool.a.x, tool.b.x), std::min(tool.a.y, tool.b.y), std::min(tool.a.z, tool.b.z)};
  const Vec3 c_hi{std::max(tool.a.x, tool.b.x), std::max(tool.a.y, tool.b.y), std::max(tool.a.z, tool.b.z)};
  // Centroids farther than r + reach from the axis belong to tets that cannot meet the tool.
  const double r = tool.radius + reach_;
  // The box, clamped to the occupied bounds: beyond them every cell is empty, and a tool a
  // thousand times the mesh's size must not pay for the cells around the mesh.
  std::array<std::int32_t, 3> lo = {cell_of(c_lo.x - r), cell_of(c_lo.y - r), cell_of(c_lo.z - r)};
  std::array<std::int32_t, 3> hi = {cell_of(c_hi.x + r), cell_of(c_hi.y + r), cell_of(c_hi.z + r)};
  std::uint64_t box_cells = 1;
  for (int a = 0; a < 3; ++a) {
    lo[a] = std::max(lo[a], occupied_lo_[a]);
    hi[a] = std::min(hi[a], occupied_hi_[a]);
    if (lo[a] > hi[a]) return;
    box_cells *= static_cast<std::uint64_t>(hi[a] - lo[a] + 1);  // < 2^21 per axis: no overflow
  }
  if (box_cells > used_slots_) {
    // More cells in the box than in the table (a thin or diagonal mesh leaves most of its
    // bounds empty): walk the table once; the sort below makes the visiting order irrelevant.
    cells_visited_ += table_.size();
    for (const Slot& cell : table_) {
      if (!cell.used()) continue;
      const std::array<std::int32_t, 3> ijk = unpack(cell.key);
      if (ijk[0] < lo[0] || ijk[0] > hi[0] || ijk[1] < lo[1] || ijk[1] > hi[1] || ijk[2] < lo[2] || ijk[2] > hi[2]) continue;
      collect<kCapsule>(mesh, cell, tool, gap_to_cell(c_lo, c_hi, cell.key), out);
    }
  } else {
    cells_visited_ += box_cells;
    // A cell's gap to the axis's box, summed axis by axis as the loops go (the bits gap_to_cell()
    // gives): a cell, a row or a slab farther than the radius plus the largest sphere ever indexed
    // holds no tet that can meet the tool, and is passed over before any hash lookup. collect()
    // would pass over each such cell anyway (its own sphere is no larger), only later.
    const double reach = tool.radius + reach_;
    for (std::int32_t i = lo[0]; i <= hi[0]; ++i) {
      const double gx = axis_gap(i, c_lo.x, c_hi.x), x2 = gx * gx;
      if (std::sqrt(x2) > reach) continue;
      for (std::int32_t j = lo[1]; j <= hi[1]; ++j) {
        const double gy = axis_gap(j, c_lo.y, c_hi.y), xy2 = x2 + gy * gy;
        if (std::sqrt(xy2) > reach) continue;
        for (std::int32_t k = lo[2]; k <= hi[2]; ++k) {
          const double gz = axis_gap(k, c_lo.z, c_hi.z), gap = std::sqrt(xy2 + gz * gz);
          if (gap > reach) continue;
          if (const std::size_t s = find_slot(pack(i, j, k)); s != kNoSlot) collect<kCapsule>(mesh, table_[s], tool, gap, out);
        }
      }
    }
  }
}

// Appends the tets of one cell that meet the tool; `gap` is the cell's distance to the axis's
// box (a ball's centre).
template <bool kCapsule>
void SpatialIndex::collect(const TetMesh& mesh, const Slot& cell, const Tool& tool, double gap,
                           std::vector<TetId>& out) const {
  if (cell.head == kNone || gap > tool.radius + cell.reach) return;
  // A pre-filter in single precision over the whole block, which the compiler turns into a few
  // vector instructions: an entry it rejects is farther than the outer sphere allows by a wide
  // margin, so the double-precision test below, which alone decides, would reject it too. The
  // margin: 2^-14 of the reach, far above the float rounding of the differences, squares and sums
  // (a few 2^-24), and 2^-16 of the axis's coordinates, above the rounding of its box to float
  // (2^-24 each). A NaN or an infinity is never rejected here. For a capsule the distance is the
  // centroid's to the axis's box, no more than to the axis.
  const Vec3& c = tool.a;
  const float cx = static_cast<float>(c.x), cy = static_cast<float>(c.y), cz = static_cast<float>(c.z),
              rf = static_cast<float>(tool.radius);
  float lox = cx, loy = cy, loz = cz, hix = cx, hiy = cy, hiz = cz;
  double magnitude = std::abs(c.x) + std::abs(c.y) + std::abs(c.z);
  if constexpr (kCapsule) {
    const float hx = static_cast<float>(tool.b.x), hy = static_cast<float>(tool.b.y), hz = static_cast<float>(tool.b.z);
    lox = std::min(cx, hx), loy = std::min(cy, hy), loz = std::min(cz, hz);
    hix = std::max(cx, hx), hiy = std::max(cy, hy), hiz = std::max(cz, hz);
    magnitude = std::max(std::abs(c.x), std::abs(tool.b.x)) + std::max(std::abs(c.y), std::abs(tool.b.y)) +
                std::max(std::abs(c.z), std::abs(tool.b.z));
  }
  const float slack = static_cast<float>(0x1p-16 * magnitude);
  for (std::uint32_t b = cell.head; b != kNone; b = blocks_[b].next) {
    const Block& block = blocks_[b];
    std::uint32_t near[kBlockEntries];
    for (std::uint32_t e = 0; e < kBlockEntries; ++e) {
      float dx, dy, dz;
      if constexpr (kCapsule) {
        dx = std::max(std::max(lox - block.x[e], block.x[e] - hix), 0.0f);
        dy = std::max(std::max(loy - block.y[e], block.y[e] - hiy), 0.0f);
        dz = std::max(std::max(loz - block.z[e], block.z[e] - hiz), 0.0f);
      } else {
        dx = block.x[e] - cx, dy = block.y[e] - cy, dz = block.z[e] - cz;
      }
      const float reach = (rf + block.outer[e]) * (1.0f + 0x1p-14f) + slack;
      near[e] = (dx * dx + dy * dy + dz * dz > reach * reach) ? 0u : 1u;
    }
    for (std::uint32_t e = 0; e < block.count; ++e) {
      if (near[e] == 0) continue;
      double d2;
      if constexpr (kCapsule) {
        d2 = squared_distance_to_axis(tool, Vec3{block.x[e], block.y[e], block.z[e]});
      } else {
        const double dx = block.x[e] - c.x, dy = block.y[e] - c.y, dz = block.z[e] - c.z;
        d2 = dx * dx + dy * dy + dz * dz;
      }
      const double outer = tool.radius + block.outer[e];
      if (d2 > outer * outer) continue;
      const TetId t{block.tet[e]};
      if (!mesh.is_live(t)) continue;
      if (tet_meets_tool(mesh, t, tool)) out.push_back(t);
    }
  }
}

void scan_tets_meeting(const TetMesh& mesh, const Tool& tool, std::vector<TetId>& out) {
  out.clear();
  for (std::uint32_t i = 0; i < mesh.tet_capacity(); ++i)
    if (mesh.is_live(TetId{i}) && tet_meets_tool(mesh, TetId{i}, tool)) out.push_back(TetId{i});
}

}  // namespace tetcut
