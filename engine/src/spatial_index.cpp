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
    // The cell's tets name their slot: move them along.
    for (std::uint32_t t = o.head; t != kNone; t = entries_by_tet_[t].next) entries_by_tet_[t].slot = static_cast<std::uint32_t>(s);
  }
}

std::uint32_t SpatialIndex::cell_for(std::uint64_t key) {
  if ((used_slots_ + 1) * 2 > table_.size()) grow_table();
  const std::size_t mask = table_.size() - 1;
  std::size_t s = mix64(key) & mask;
  for (; table_[s].used; s = (s + 1) & mask)
    if (table_[s].key == key) return static_cast<std::uint32_t>(s);
  // Cells are never deleted: an emptied cell keeps its slot for the next tets there.
  table_[s] = {key, kNone, true, 0.0};
  ++used_slots_;
  return static_cast<std::uint32_t>(s);
}

void SpatialIndex::build(const TetMesh& mesh) {
  table_.clear();
  used_slots_ = 0;
  entries_by_tet_.assign(mesh.tet_capacity(), Entry{});
  entries_ = 0;
  reach_ = 0.0;
  occupied_lo_ = {1, 1, 1};
  occupied_hi_ = {0, 0, 0};
  for (std::uint32_t t = 0; t < mesh.tet_capacity(); ++t)
    if (mesh.is_live(TetId{t})) insert(mesh, TetId{t});
  // Headroom, so that the cuts that follow find entries and slots without growing anything.
  entries_by_tet_.reserve(entries_by_tet_.size() + entries_by_tet_.size() / 2 + 1024);
  while ((used_slots_ + used_slots_ / 2 + 1) * 2 > table_.size()) grow_table();
}

void SpatialIndex::insert(const TetMesh& mesh, TetId t) {
  if (entries_by_tet_.size() <= t.value) entries_by_tet_.resize(std::max<std::size_t>(t.value + 1, entries_by_tet_.size() * 3 / 2));
  if (entries_by_tet_[t.value].radius >= 0.0) erase(t);
  const auto v = mesh.tet(t);
  const Vec3 c = 0.25 * (mesh.position(v[0]) + mesh.position(v[1]) + mesh.position(v[2]) + mesh.position(v[3]));
  double r2 = 0.0;
  for (VertId x : v) {
    const Vec3 d = mesh.position(x) - c;
    r2 = std::max(r2, dot(d, d));
  }
  // A hair larger than the rounded distance, so that the sphere surely holds the tet.
  const double radius = std::sqrt(r2) * (1.0 + 1e-12) + 1e-300;
  const std::int32_t i = cell_of(c.x), j = cell_of(c.y), k = cell_of(c.z);
  if (occupied_lo_[0] > occupied_hi_[0]) {
    occupied_lo_ = occupied_hi_ = {i, j, k};
  } else {
    occupied_lo_ = {std::min(occupied_lo_[0], i), std::min(occupied_lo_[1], j), std::min(occupied_lo_[2], k)};
    occupied_hi_ = {std::max(occupied_hi_[0], i), std::max(occupied_hi_[1], j), std::max(occupied_hi_[2], k)};
  }
  const std::uint32_t s = cell_for(pack(i, j, k));
  Slot& cell = table_[s];
  cell.reach = std::max(cell.reach, radius);
  reach_ = std::max(reach_, radius);
  Entry& e = entries_by_tet_[t.value];
  e = {c, radius, s, cell.head, kNone};
  if (cell.head != kNone) entries_by_tet_[cell.head].prev = t.value;
  cell.head = t.value;
  ++entries_;
}

void SpatialIndex::erase(TetId t) {
  if (t.value >= entries_by_tet_.size()) return;
  Entry& e = entries_by_tet_[t.value];
  if (e.radius < 0.0) return;
  if (e.prev != kNone) {
    entries_by_tet_[e.prev].next = e.next;
  } else {
    table_[e.slot].head = e.next;
  }
  if (e.next != kNone) entries_by_tet_[e.next].prev = e.prev;
  e = Entry{};
  --entries_;
}

void SpatialIndex::apply(const TetMesh& mesh, const ChangeLog& log, std::size_t removed_from, std::size_t created_from) {
  for (std::size_t i = removed_from; i < log.removed.size(); ++i) erase(log.removed[i]);
  for (std::size_t i = created_from; i < log.created.size(); ++i) {
    const TetId t = log.created[i].tet;
    // A tet created and removed again within the log is gone; a reused id is re-indexed.
    if (mesh.is_live(t)) insert(mesh, t);
  }
}

// Distance from p to the box of cell `key` (0 inside it).
double SpatialIndex::gap_to_cell(const Vec3& p, std::uint64_t key) const {
  const std::array<std::int32_t, 3> ijk = unpack(key);
  const double q[3] = {p.x, p.y, p.z};
  double g2 = 0.0;
  for (int a = 0; a < 3; ++a) {
    const double lo = ijk[a] * cell_size_, hi = lo + cell_size_;
    const double g = q[a] < lo ? lo - q[a] : q[a] > hi ? q[a] - hi : 0.0;
    g2 += g * g;
  }
  return std::sqrt(g2);
}

void SpatialIndex::query(const TetMesh& mesh, const Ball& ball, std::vector<TetId>& out) {
  out.clear();
  if (occupied_lo_[0] > occupied_hi_[0]) return;  // nothing was ever indexed
  const Vec3 c = ball.centre;
  // Centroids farther than r + reach from the centre belong to tets that cannot meet the ball.
  const double r = ball.radius + reach_;
  // The box, clamped to the occupied bounds: beyond them every cell is empty, and a tool a
  // thousand times the mesh's size must not pay for the cells around the mesh.
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

// Appends the tets of one cell that meet the ball.
void SpatialIndex::collect(const TetMesh& mesh, const Slot& cell, const Ball& ball, std::vector<TetId>& out) const {
  if (cell.head == kNone || gap_to_cell(ball.centre, cell.key) > ball.radius + cell.reach) return;
  for (std::uint32_t t = cell.head; t != kNone;) {
    const Entry& e = entries_by_tet_[t];
    const Vec3 d = e.centre - ball.centre;
    const double reach = ball.radius + e.radius;
    if (dot(d, d) <= reach * reach && mesh.is_live(TetId{t})) {
      const auto v = mesh.tet(TetId{t});
      if (intersects(ball, mesh.position(v[0]), mesh.position(v[1]), mesh.position(v[2]), mesh.position(v[3])))
        out.push_back(TetId{t});
    }
    t = e.next;
  }
}

}  // namespace tetcut
