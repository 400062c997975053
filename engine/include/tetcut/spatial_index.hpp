// A loose uniform grid over the tets, updated incrementally as tets are created and removed, so
// that finding the tets a tool touches (paper 3.1) never scans the mesh: a query visits the
// cells near the tool, and an update touches one cell per changed tet.
//
// Each tet is listed once, in the cell that holds its centroid, with its bounding sphere (the
// centroid and the largest distance to a vertex). Each cell remembers the largest sphere it ever
// held, and the index the largest of all. A query looks at the cells within the ball's radius
// plus that largest sphere, skips a cell whose box is farther from the centre than the radius
// plus the cell's own largest sphere, rejects a tet whose sphere misses the ball without reading
// the mesh, and runs the exact test (tool_ball.hpp) on the rest. (A tet listed in every cell its
// box overlaps cost a dozen candidates per tet found: each tet was met in several cells, most
// far from the ball.) Cells live in an open-addressing table keyed by their integer coordinates;
// query results are sorted by tet id, so the order in which cells are visited never shows.
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

#include "tetcut/change_log.hpp"
#include "tetcut/mesh.hpp"
#include "tetcut/tool_ball.hpp"

namespace tetcut {

class SpatialIndex {
 public:
  // `cell_size` > 0: a good choice is about the mean edge length of the mesh.
  explicit SpatialIndex(double cell_size = 1.0) : cell_size_(cell_size) {}

  // Indexes every live tet: O(#T), once. Leaves room for half as many tets again, so that the
  // operations that follow do not grow the index's arrays.
  void build(const TetMesh& mesh);

  void insert(const TetMesh& mesh, TetId t);
  void erase(TetId t);
  // Replays what an operation did: erases the removed tets, inserts the created ones that are
  // still live, in the log's order.
  void apply(const TetMesh& mesh, const ChangeLog& log, std::size_t removed_from = 0, std::size_t created_from = 0);

  // The live tets that share a point with the ball (exact closest-point test), sorted by id.
  void query(const TetMesh& mesh, const Ball& ball, std::vector<TetId>& out);

  [[nodiscard]] double cell_size() const { return cell_size_; }
  [[nodiscard]] std::size_t entries() const { return entries_; }
  // Cells a query looked at (by key lookup or by walking the table), over the index's life: what
  // a test reads to see that a query's cost does not grow with the ball.
  [[nodiscard]] std::uint64_t cells_visited() const { return cells_visited_; }

 private:
  static constexpr std::uint32_t kNone = 0xFFFFFFFFu;
  struct Slot {
    std::uint64_t key = 0;
    std::uint32_t head = kNone;  // first tet of the cell's list
    bool used = false;
    double reach = 0.0;          // largest bounding sphere the cell ever held
  };
  // Per tet id.
  struct Entry {
    Vec3 centre{};
    double radius = -1.0;        // < 0: not indexed
    std::uint32_t slot = kNone;  // the cell's slot in table_ (stable: the table only grows by rehash)
    std::uint32_t next = kNone, prev = kNone;  // in the cell's list
  };

  [[nodiscard]] std::int32_t cell_of(double x) const;
  [[nodiscard]] static std::uint64_t pack(std::int32_t i, std::int32_t j, std::int32_t k);
  [[nodiscard]] static std::array<std::int32_t, 3> unpack(std::uint64_t key);
  void collect(const TetMesh& mesh, const Slot& cell, const Ball& ball, std::vector<TetId>& out) const;
  [[nodiscard]] double gap_to_cell(const Vec3& p, std::uint64_t key) const;
  [[nodiscard]] const Slot* find_cell(std::uint64_t key) const;
  std::uint32_t cell_for(std::uint64_t key);
  void grow_table();

  double cell_size_;
  std::vector<Slot> table_;
  std::size_t used_slots_ = 0;
  std::vector<Entry> entries_by_tet_;
  std::size_t entries_ = 0;
  double reach_ = 0.0;  // largest bounding sphere ever indexed
  std::array<std::int32_t, 3> occupied_lo_{1, 1, 1}, occupied_hi_{0, 0, 0};  // lo > hi: empty
  std::uint64_t cells_visited_ = 0;
};

}  // namespace tetcut
