// A loose uniform grid over tets, updated incrementally as tets are created and removed, so that
// finding those a tool touches never scans the mesh: a query visits the cells near the tool, and
// an update touches one cell per changed tet. The walking locator keeps the mesh's boundary tets
// in one (walking_locator.hpp): the seeds of its walk (paper 3.1).
//
// Each tet is listed once, in the cell that holds its centroid, with the sphere about the
// centroid that holds the tet. Each cell remembers the largest sphere it ever held, and the
// index the largest of all. A query looks at the cells within the ball's radius plus that
// largest sphere, skips a cell whose box is farther from the centre than the radius plus the
// cell's own largest sphere, rejects a tet whose sphere misses the ball without reading the
// mesh, and runs the ball-tet test (tool.hpp) on the rest. An inner sphere, one the tet holds,
// used to accept tets without that test; it spared few on the gated sweep and cost a fifth of
// each insert and 4 of an entry's 24 bytes. (Listing a tet in every cell its box overlaps instead
// would meet each tet in several cells, most of them far from the ball.) A cell keeps its
// entries contiguously, in a chain of fixed-size blocks from a pool, so that a query reads each
// cell in a few cache lines rather than chasing one line per tet; erasing moves the cell's last
// entry into the hole. Cells live in an open-addressing table keyed by their integer
// coordinates; query results are sorted by tet id, so the order in which cells and entries are
// visited never shows.
//
// A query costs what the index holds, not what the ball's box spans: the box is clamped to the
// bounds of the cells that ever held a tet (grown on insert, never shrunk: conservative), and
// when the clamped box still has more cells than the table, the table's occupied cells are
// walked instead. A ball engulfing the mesh costs O(#entries) once, whatever its diameter.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "core/tool.hpp"
#include "tetcut/change_log.hpp"
#include "tetcut/mesh.hpp"

namespace tetcut {

class SpatialIndex {
 public:
  // `cell_size` > 0: a good choice is about the mean edge length of the mesh.
  explicit SpatialIndex(double cell_size = 1.0) : cell_size_(cell_size) {}

  // Indexes every live tet: O(#T), once. Leaves room for half as many tets again, so that the
  // operations that follow do not grow the index's arrays. Rebuilding reuses them.
  // With `keep`, only the live tets it accepts (the walking locator's boundary tets).
  using Keep = bool (*)(const TetMesh&, TetId);
  void build(const TetMesh& mesh, Keep keep = nullptr);
  // The same with another cell size (a Cutter reset onto a mesh of another scale).
  void build(const TetMesh& mesh, double cell_size, Keep keep = nullptr) {
    cell_size_ = cell_size;
    build(mesh, keep);
  }

  void insert(const TetMesh& mesh, TetId t);
  void erase(TetId t);
  // Replays what an operation did: erases the removed tets, inserts the created ones that are
  // still live, in the log's order.
  void apply(const TetMesh& mesh, const ChangeLog& log, std::size_t removed_from = 0, std::size_t created_from = 0);

  // The live tets that share a point with the ball (exact closest-point test), sorted by id.
  // A capsule is queried as a ball whose centre is the axis's box: cells and entries are passed
  // over by their gap to that box (a lower bound of their distance to the axis), and an entry is
  // decided by its centroid's distance to the axis itself. For a ball the box is its centre, and
  // every gap is computed as it was for the ball alone.
  void query(const TetMesh& mesh, const Tool& tool, std::vector<TetId>& out);

  // The key of the cell of side `cell_size` that holds p: what the index files a centroid under,
  // and the walking locator's coarse grid.
  [[nodiscard]] static std::uint64_t key_of(const Vec3& p, double cell_size) {
    return pack(cell_coordinate(p.x, cell_size), cell_coordinate(p.y, cell_size), cell_coordinate(p.z, cell_size));
  }
  [[nodiscard]] bool holds(TetId t) const { return t.value < where_.size() && where_[t.value].indexed(); }
  [[nodiscard]] double cell_size() const { return cell_size_; }
  [[nodiscard]] std::size_t entries() const { return entries_; }
  // Cells a query looked at (by key lookup or by walking the table), over the index's life: what
  // a test reads to see that a query's cost does not grow with the ball.
  [[nodiscard]] std::uint64_t cells_visited() const { return cells_visited_; }

 private:
  static constexpr std::uint32_t kNone = 0xFFFFFFFFu;
  // A block holds a cell's entries field by field. An entry is a tet's centroid and the radius of
  // a sphere about it that holds the tet (rounded up), in single precision: 16 bytes, and the tet.
  // The bound absorbs the rounding of the centroid, so the test stays conservative. Field by
  // field, so that collect() can reject a block's far entries with one vector of four before it
  // looks at any entry one by one. Four, not twelve: a cell holds a few tets, and blocks of twelve
  // were mostly empty (a session's peak, bench/session_memory.cpp: 193.0 bytes per tet with
  // twelve, 163.6 with four; the gated sweep's instructions per cut differ by a few hundred).
  static constexpr std::uint32_t kBlockEntries = 4;
  // No link back to the previous block: erase() finds the tail's predecessor from the head, in a
  // chain of a few blocks, and a link would be 4 of a block's 92 bytes.
  struct Block {
    std::uint32_t count = 0;
    std::uint32_t next = kNone;  // in the cell's chain
    std::uint32_t slot = kNone;  // the cell's slot in table_ (kept when the table grows)
    float x[kBlockEntries]{}, y[kBlockEntries]{}, z[kBlockEntries]{};
    float outer[kBlockEntries]{};
    std::uint32_t tet[kBlockEntries]{};
  };
  // 24 bytes: the reach in single precision loses nothing (every bound it takes the largest of is
  // a float), and an unused slot is told by a key pack() never makes (it fills 63 bits).
  static constexpr std::uint64_t kUnusedKey = ~std::uint64_t{0};
  struct Slot {
    std::uint64_t key = kUnusedKey;
    std::uint32_t head = kNone, tail = kNone;  // the cell's chain of blocks (tail: the one with room)
    float reach = 0.0f;                        // largest bounding sphere the cell ever held
    [[nodiscard]] bool used() const { return key != kUnusedKey; }
  };
  // Where a tet's entry is: block and index in it, packed into one word (block * kBlockEntries +
  // index; kNone: not indexed). One word, not two: the array is one per tet id with half as many
  // again of headroom, and its second word was 6 of a session's 163.6 peak bytes per tet. A mesh
  // would need 2^30 blocks, four billion tets, to reach the sentinel.
  struct Location {
    std::uint32_t packed = kNone;
    Location() = default;
    Location(std::uint32_t block, std::uint32_t index) : packed(block * kBlockEntries + index) {}
    [[nodiscard]] bool indexed() const { return packed != kNone; }
    [[nodiscard]] std::uint32_t block() const { return packed / kBlockEntries; }
    [[nodiscard]] std::uint32_t index() const { return packed % kBlockEntries; }
  };

  [[nodiscard]] static std::int32_t cell_coordinate(double x, double cell_size);
  [[nodiscard]] std::int32_t cell_of(double x) const { return cell_coordinate(x, cell_size_); }
  [[nodiscard]] static std::uint64_t pack(std::int32_t i, std::int32_t j, std::int32_t k);
  [[nodiscard]] static std::array<std::int32_t, 3> unpack(std::uint64_t key);
  template <bool kCapsule>
  void query_cells(const TetMesh& mesh, const Tool& tool, std::vector<TetId>& out);
  template <bool kCapsule>
  void collect(const TetMesh& mesh, const Slot& cell, const Tool& tool, double gap, std::vector<TetId>& out) const;
  // Distance from the interval [q_lo, q_hi] to slab i of cells along one axis (0 when they meet).
  [[nodiscard]] double axis_gap(std::int32_t i, double q_lo, double q_hi) const;
  // Distance from the box [lo, hi] to the box of cell `key`.
  [[nodiscard]] double gap_to_cell(const Vec3& lo, const Vec3& hi, std::uint64_t key) const;
  static constexpr std::size_t kNoSlot = ~std::size_t{0};
  [[nodiscard]] std::size_t find_slot(std::uint64_t key) const;
  std::size_t cell_for(std::uint64_t key);  // the slot, made if new
  std::uint32_t new_block();
  void grow_table();

  double cell_size_;
  std::vector<Slot> table_;
  std::size_t used_slots_ = 0;
  std::vector<Block> blocks_;
  std::uint32_t free_block_ = kNone;     // free list through Block::next
  std::vector<Location> where_;          // by tet id
  std::size_t entries_ = 0;
  double reach_ = 0.0;  // largest bounding sphere ever indexed
  std::array<std::int32_t, 3> occupied_lo_{1, 1, 1}, occupied_hi_{0, 0, 0};  // lo > hi: empty
  std::uint64_t cells_visited_ = 0;
};

// Every live tet meeting the ball, in id order, by a scan of the whole mesh (O(#T)): the
// reference the index is tested against and the query of one-off commands, never a cut's.
void scan_tets_meeting(const TetMesh& mesh, const Tool& ball, std::vector<TetId>& out);

}  // namespace tetcut
