#include "tetcut/spatial_index.hpp"

#include <algorithm>
#include <cmath>

#include "tetcut/random.hpp"

namespace tetcut {

std::int32_t SpatialIndex::cell_of(double x) const {
  // Clamped to 21 bits of signed range: a mesh a million cells wide is already absurd.
  const double c = std::floor(x / cell_size_);
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

const SpatialIndex::Slot* SpatialIndex::find_cell(std::uint64_t key) const {
  if (table_.empty()) return nullptr;
  const std::size_t mask = table_.size() - 1;
  for (std::size_t s = mix64(key) & mask;; s = (s + 1) & mask) {
    if (!table_[s].used) return nullptr;
    if (table_[s].key == key) return &table_[s];
  }
}

void SpatialIndex::grow_table() {
  std::vector<Slot> old;
  old.swap(table_);
  table_.assign(old.empty() ? 1024 : old.size() * 2, Slot{});
  const std::size_t mask = table_.size() - 1;
  for (const Slot& o : old) {
    if (!o.used) continue;
    std::size_t s = mix64(o.key) & mask;
    while (table_[s].used) s = (s + 1) & mask;
    table_[s] = o;
  }
}

SpatialIndex::Slot& SpatialIndex::cell_for(std::uint64_t key) {
  if ((used_slots_ + 1) * 2 > table_.size()) grow_table();
  const std::size_t mask = table_.size() - 1;
  std::size_t s = mix64(key) & mask;
  for (; table_[s].used; s = (s + 1) & mask)
    if (table_[s].key == key) return table_[s];
  // Cells are never deleted: an emptied cell keeps its slot for the next tets there.
  const std::uint32_t sentinel = new_node();  // may grow nodes_, not table_
  nodes_[sentinel] = {kNone, sentinel, sentinel, kNone};
  table_[s] = {key, sentinel, true};
  ++used_slots_;
  return table_[s];
}

std::uint32_t SpatialIndex::new_node() {
  if (free_node_ != kNone) {
    const std::uint32_t n = free_node_;
    free_node_ = nodes_[n].next;
    return n;
  }
  nodes_.push_back({});
  return static_cast<std::uint32_t>(nodes_.size() - 1);
}

void SpatialIndex::build(const TetMesh& mesh) {
  table_.clear();
  used_slots_ = 0;
  nodes_.clear();
  free_node_ = kNone;
  ranges_.assign(mesh.tet_capacity(), CellRange{});
  entries_ = 0;
  occupied_lo_ = {1, 1, 1};
  occupied_hi_ = {0, 0, 0};
  for (std::uint32_t t = 0; t < mesh.tet_capacity(); ++t)
    if (mesh.is_live(TetId{t})) insert(mesh, TetId{t});
  // Headroom, so that the cuts that follow find nodes and slots without growing anything.
  nodes_.reserve(nodes_.size() + nodes_.size() / 2 + 1024);
  ranges_.reserve(ranges_.size() + ranges_.size() / 2 + 1024);
  stamps_.reserve(ranges_.capacity());
  while ((used_slots_ + used_slots_ / 2 + 1) * 2 > table_.size()) grow_table();
}

void SpatialIndex::insert(const TetMesh& mesh, TetId t) {
  if (ranges_.size() <= t.value) ranges_.resize(std::max<std::size_t>(t.value + 1, ranges_.size() * 3 / 2));
  if (ranges_[t.value].first_node != kNone) erase(t);
  const auto v = mesh.tet(t);
  Vec3 lo = mesh.position(v[0]), hi = lo;
  for (int i = 1; i < 4; ++i) {
    const Vec3& p = mesh.position(v[i]);
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  const std::int32_t i0 = cell_of(lo.x), i1 = cell_of(hi.x), j0 = cell_of(lo.y), j1 = cell_of(hi.y), k0 = cell_of(lo.z),
                     k1 = cell_of(hi.z);
  if (occupied_lo_[0] > occupied_hi_[0]) {
    occupied_lo_ = {i0, j0, k0};
    occupied_hi_ = {i1, j1, k1};
  } else {
    occupied_lo_ = {std::min(occupied_lo_[0], i0), std::min(occupied_lo_[1], j0), std::min(occupied_lo_[2], k0)};
    occupied_hi_ = {std::max(occupied_hi_[0], i1), std::max(occupied_hi_[1], j1), std::max(occupied_hi_[2], k1)};
  }
  std::uint32_t first = kNone;
  for (std::int32_t i = i0; i <= i1; ++i)
    for (std::int32_t j = j0; j <= j1; ++j)
      for (std::int32_t k = k0; k <= k1; ++k) {
        const std::uint32_t sentinel = cell_for(pack(i, j, k)).sentinel;
        const std::uint32_t n = new_node();
        const std::uint32_t after = nodes_[sentinel].next;
        nodes_[n] = {t.value, after, sentinel, first};
        nodes_[after].prev = n;
        nodes_[sentinel].next = n;
        first = n;
        ++entries_;
      }
  ranges_[t.value].first_node = first;
}

void SpatialIndex::erase(TetId t) {
  if (t.value >= ranges_.size()) return;
  for (std::uint32_t n = ranges_[t.value].first_node; n != kNone;) {
    Node& node = nodes_[n];
    nodes_[node.prev].next = node.next;
    nodes_[node.next].prev = node.prev;
    const std::uint32_t next = node.next_of_tet;
    node.next = free_node_;
    free_node_ = n;
    --entries_;
    n = next;
  }
  ranges_[t.value].first_node = kNone;
}

void SpatialIndex::apply(const TetMesh& mesh, const ChangeLog& log, std::size_t removed_from, std::size_t created_from) {
  for (std::size_t i = removed_from; i < log.removed.size(); ++i) erase(log.removed[i]);
  for (std::size_t i = created_from; i < log.created.size(); ++i) {
    const TetId t = log.created[i].tet;
    // A tet created and removed again within the log is gone; a reused id is re-indexed.
    if (mesh.is_live(t)) insert(mesh, t);
  }
}

void SpatialIndex::query(const TetMesh& mesh, const Ball& ball, std::vector<TetId>& out) {
  out.clear();
  if (stamps_.size() < mesh.tet_capacity()) stamps_.resize(mesh.tet_capacity(), 0);
  if (++stamp_ == 0) {
    std::fill(stamps_.begin(), stamps_.end(), 0);
    stamp_ = 1;
  }
  if (occupied_lo_[0] > occupied_hi_[0]) return;  // nothing was ever indexed
  const Vec3 c = ball.centre;
  const double r = ball.radius;
  // The ball's box, clamped to the occupied bounds: beyond them every cell is empty, and a
  // tool a thousand times the mesh's size must not pay for the cells around the mesh.
  std::array<std::int32_t, 3> lo = {cell_of(c.x - r), cell_of(c.y - r), cell_of(c.z - r)};
  std::array<std::int32_t, 3> hi = {cell_of(c.x + r), cell_of(c.y + r), cell_of(c.z + r)};
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
      if (!cell.used) continue;
      const std::array<std::int32_t, 3> ijk = unpack(cell.key);
      if (ijk[0] < lo[0] || ijk[0] > hi[0] || ijk[1] < lo[1] || ijk[1] > hi[1] || ijk[2] < lo[2] || ijk[2] > hi[2]) continue;
      collect(mesh, cell, ball, out);
    }
  } else {
    cells_visited_ += box_cells;
    for (std::int32_t i = lo[0]; i <= hi[0]; ++i)
      for (std::int32_t j = lo[1]; j <= hi[1]; ++j)
        for (std::int32_t k = lo[2]; k <= hi[2]; ++k)
          if (const Slot* cell = find_cell(pack(i, j, k))) collect(mesh, *cell, ball, out);
  }
  std::sort(out.begin(), out.end());
}

// Appends the live tets of one cell that meet the ball and were not seen yet in this query.
void SpatialIndex::collect(const TetMesh& mesh, const Slot& cell, const Ball& ball, std::vector<TetId>& out) {
  for (std::uint32_t n = nodes_[cell.sentinel].next; n != cell.sentinel; n = nodes_[n].next) {
    const std::uint32_t t = nodes_[n].tet;
    if (t >= stamps_.size() || stamps_[t] == stamp_) continue;
    stamps_[t] = stamp_;
    if (!mesh.is_live(TetId{t})) continue;
    if (meets(mesh, TetId{t}, ball)) out.push_back(TetId{t});
  }
}

bool SpatialIndex::meets(const TetMesh& mesh, TetId t, const Ball& ball) {
  const auto v = mesh.tet(t);
  return intersects(ball, mesh.position(v[0]), mesh.position(v[1]), mesh.position(v[2]), mesh.position(v[3]));
}

}  // namespace tetcut
