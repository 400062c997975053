// I10, the tissue rule, recomputed from the raw tets and the tool alone (design: invariants).
// After an operation that cut with a ball tool (centre, radius) at a length D_ref:
//   - no live cuttable tet that meets the tool's open ball has an edge longer than D_ref (the
//     refinement's promise: paper 3.2 refines what the tool meets down to D_ref);
//   - no live cuttable tet whose centroid lies in the tool and whose edges are within D_ref (what
//     paper 3.3 selects) remains, but those the operation reports as left in the tool;
//   - each tet it reports as left is live, cuttable and such a tet;
//   - uncuttable tissue is neither removed nor grown: the uncuttable tets an operation made fill
//     exactly the volume of the uncuttable tets it replaced.
// Cuttable or not is the checker's own record: the tets the caller named uncuttable
// (LocalChecker::set_uncuttable), and every tet an operation made whose centroid lies in an
// uncuttable tet it replaced (a split's child lies in its parent; a flip among uncuttable tets
// keeps their union).
//
// Decisions within a relative 1e-9 of the tool's radius or of D_ref are not judged: the engine's
// rounding there is its own, and a borderline tet is a matter of the last bit, not of the rule.
//
// Which tets meet the tool comes from the checker's own grid over the tets' bounding boxes
// (TetGrid), kept up to date from each operation's removed and created tets: never a scan, and
// never the engine's spatial index.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <unordered_map>
#include <vector>

#include "report_builder.hpp"
#include "tetcut/invariants/check.hpp"
#include "tetcut/vec3.hpp"
#include "vertex_link.hpp"

namespace tetcut::invariants::detail {

// A uniform grid of cells, each listing the tets whose bounding box meets it. A tet whose box
// spans more than kMaxCellsPerTet cells is kept in a list of its own, which every query returns.
class TetGrid {
 public:
  static constexpr std::int64_t kMaxCellsPerTet = 512;

  [[nodiscard]] bool built() const { return built_; }
  // Every live tet of `tets`; the cell is their mean edge length.
  void build(std::span<const RawTet> tets, std::span<const Vec3> positions);
  void insert(std::uint32_t t, const RawTet& q, std::span<const Vec3> positions);
  void erase(std::uint32_t t);
  // The tets whose box may meet the ball, sorted and distinct (a superset: the caller tests).
  void candidates(const Vec3& centre, double radius, std::vector<std::uint32_t>& out);

 private:
  using Box = std::array<std::int64_t, 6>;  // lo x, y, z, hi x, y, z, in cells
  [[nodiscard]] std::int64_t cell_of(double x) const;
  [[nodiscard]] static std::uint64_t key(std::int64_t x, std::int64_t y, std::int64_t z);
  [[nodiscard]] static std::int64_t cells_in(const Box& box);

  bool built_ = false;
  double cell_ = 1.0;
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> cells_;
  std::vector<std::uint32_t> oversized_;
  std::vector<Box> box_;           // by tet id, where it was put
  std::vector<std::uint8_t> in_;   // by tet id: 0 not in the grid, 1 in cells, 2 oversized
  std::vector<std::uint32_t> seen_;
  std::uint32_t stamp_ = 0;
};

// The distance from p to the closed tet (a, b, c, d): 0 inside. The checker's own: the plane
// projection with barycentric coordinates per face, else the nearest edge.
double distance_to_tet(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

// The distance from p to the tool's axis: its centre, or the segment centre-end of a capsule.
double distance_to_axis(const ToolRule& tool, const Vec3& p);
// The distance from the tool's axis to the closed tet (a, b, c, d): distance_to_tet() from the
// centre for a ball. For a capsule, the least distance_to_tet() along the segment, a convex
// function of the position on it, found by golden-section search (the engine clips the segment
// and measures it against the faces: the checker owes it nothing).
double distance_from_axis_to_tet(const ToolRule& tool, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

// Whether p lies in the closed tet, up to a relative 1e-12 of its volume.
bool tet_contains(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

// I10's tet rules over `candidates` (live tets near the tool): see the header.
void check_tissue_rule(const ToolRule& rule, std::span<const std::uint32_t> candidates, std::span<const RawTet> tets,
                       std::span<const Vec3> positions, std::span<const std::uint8_t> uncuttable,
                       ReportBuilder& report);

}  // namespace tetcut::invariants::detail
