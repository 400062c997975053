// A uniform grid over the tets, updated incrementally as tets are created and removed, so that
// finding the tets a tool touches (paper 3.1) never scans the mesh: a query visits the cells
// the tool's bounding box covers, and an update touches the cells of the changed tets.
//
// Each tet is listed in every cell its bounding box overlaps; the index remembers each tet's
// cell range, so a tet can be erased after the mesh has already forgotten it (replace_tets()).
// Cells live in an open-addressing table keyed by their integer coordinates; query results are
// sorted by tet id, so the order in which cells are visited never shows.
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

  // Indexes every live tet: O(#T), once.
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
  struct CellRange {
    std::uint32_t first_node = kNone;  // kNone: not indexed
  };
  struct Slot {
    std::uint64_t key = 0;
    std::uint32_t sentinel = kNone;  // the cell's list head node
    bool used = false;
  };
  // Cell lists are doubly linked through one node pool with a free list, each starting at a
  // sentinel node, and a tet's own nodes are chained too: erasing a tet unlinks its nodes in
  // O(1) each, and inserting or erasing never allocates once the pool has grown.
  struct Node {
    std::uint32_t tet;
    std::uint32_t next, prev;  // in the cell's list
    std::uint32_t next_of_tet;
  };
  static constexpr std::uint32_t kNone = 0xFFFFFFFFu;

  [[nodiscard]] static bool meets(const TetMesh& mesh, TetId t, const Ball& ball);
  [[nodiscard]] std::int32_t cell_of(double x) const;
  [[nodiscard]] static std::uint64_t pack(std::int32_t i, std::int32_t j, std::int32_t k);
  [[nodiscard]] static std::array<std::int32_t, 3> unpack(std::uint64_t key);
  void collect(const TetMesh& mesh, const Slot& cell, const Ball& ball, std::vector<TetId>& out);
  [[nodiscard]] const Slot* find_cell(std::uint64_t key) const;
  Slot& cell_for(std::uint64_t key);
  std::uint32_t new_node();
  void grow_table();

  double cell_size_;
  std::vector<Slot> table_;
  std::size_t used_slots_ = 0;
  std::vector<Node> nodes_;
  std::uint32_t free_node_ = kNone;
  std::vector<CellRange> ranges_;      // by tet id
  std::vector<std::uint32_t> stamps_;  // by tet id: dedup during a query
  std::uint32_t stamp_ = 0;
  std::size_t entries_ = 0;
  // Bounds (inclusive) of every cell a tet was ever inserted into; empty when lo > hi.
  std::array<std::int32_t, 3> occupied_lo_{1, 1, 1}, occupied_hi_{0, 0, 0};
  std::uint64_t cells_visited_ = 0;
};

}  // namespace tetcut
