// Refinement graded to the tool (RefinementRule::kGraded): Rivara's longest-edge bisection driven
// by the longest-edge propagation path (LEPP), restricted to the tets the tool meets.
//
//   M.-C. Rivara, "Mesh refinement processes based on the generalized bisection of simplices",
//   SIAM J. Numer. Anal. 21(3), 1984: bisect a simplex across its longest edge. In the plane the
//   angles of every descendant stay above half the smallest initial one (Rosenberg, Stenger
//   1975); for tetrahedra no such bound is proved, so the tests measure the one this mesh meets.
//   M.-C. Rivara, "New longest-edge algorithms for the refinement and/or improvement of
//   unstructured triangulations", Int. J. Numer. Meth. Eng. 40, 1997 (and Rivara, Levin 1992 for
//   tetrahedra): to refine t, follow LEPP(t), from t to a tet around its longest edge that has a
//   longer longest edge, and so on, until an edge that is the longest edge of every tet around it
//   (the terminal edge); bisect that edge, halving every tet around it, and repeat until t is gone.
//   Ours relaxes "longest" at the path's end: an edge at least kNearlyLongest of the longest edge
//   around it is terminal too, which ends most paths at their first step (below).
//
// Halving every tet around the bisected edge keeps the mesh conforming without templates, and a
// tet is only ever cut across its own longest edge or one within 15 % of it (but for the path
// bound below), the cuts that keep its children's shape closest to its own. Sizes grade outward: a coarse neighbour is
// halved across its long edge once, instead of being split by the paper's templates at an edge
// of the tool's size into a large child with one small edge.
//
// Which tets: the targets are the given ones (the tets meeting the tool) and, of every target
// bisected, the children that meet the focus ball (all of them without one). The refinement goes
// on until no live target has an edge longer than D_ref: with the tool's ball as the focus,
// every live tet meeting the ball then has all its edges <= D_ref, the selection's bound (paper
// 3.3), judged at the same D_ref. The propagation halves tets beyond the targets (the paths go
// up to longer edges); those are not targets and are not refined further.
//
// Order and determinism: targets are taken first in, first out (the given ones in the order
// given, a cut's sorted by id; children in the order the split makes them); "longest" is a total
// order on edges (squared length, then the sorted vertex ids), so every path and its terminal edge
// follow from the ids and the coordinates alone.
//
// Bounds: each bisection makes at least one net tet, and the plan's children are counted against
// what is left of max_tets_created before it is applied (a bisection over it is refused,
// kOverBudget, as the paper's loop refuses a round); a path longer than kMaxPathSteps stops at
// the longest edge it has reached and bisects that one (conforming all the same; counted in
// RefineReport::paths_cut_short). max_iterations and p are the paper's loop's and are not used.
//
// Each bisection is EdgeSplitter::split on one edge: planned on the const mesh, checked by the
// exact predicate, then applied through replace_tets inside the caller's transaction (the journal
// records every child with its parent and the midpoint with its edge); a refused one leaves the
// mesh as the bisections before it left it, with the reason in RefineReport::refusal.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "refine/edge_split.hpp"
#include "tetcut/detail/stamped_property.hpp"
#include "tetcut/mesh.hpp"

namespace tetcut {

struct RefineParams;
struct RefineReport;

class LongestEdgeBisection {
 public:
  // Longer paths are rare (lengths strictly grow along one, and a mesh's sizes vary within a
  // bounded ratio between neighbours); the bound keeps a pathological mesh from walking far.
  static constexpr std::uint32_t kMaxPathSteps = 32;
  // An edge at least this fraction of the longest edge of every tet around it ends the path as
  // the longest would. Rivara's strict rule walks on to an edge a few percent longer and halves
  // its whole shell, and each such walk spreads the refinement outward. On tools of 0.05 to 0.3
  // median edges (tetcut_quality_sweeps --gate) the strict rule made 993-1,570 tets per cut at
  // p99; 0.85 makes 354-545, refuses nothing and keeps every tissue removal within the cut's
  // reach and theta at 15 degrees on every cut of the quality sweeps but one. Lower fractions
  // grade more steeply: 0.8 made 313-443 but its coarser neighbours put one fallback's pieces
  // beyond the reach (12 tets); 0.7 and below made slivers the pass could not lift, and refused
  // cuts. A tet is halved across its longest edge or one within 15 % of it.
  static constexpr double kNearlyLongest = 0.85;

  // Refines around `initial` (live tet ids) with `splitter` as the bisection's scratch. As
  // Refiner::refine: `region` gets the live tets among the initial ones and those made, sorted
  // by id.
  RefineReport refine(TetMesh& mesh, std::span<const TetId> initial, const RefineParams& params,
                      std::vector<TetId>& region, EdgeSplitter& splitter);

  // Room (allocated and touched) for meshes up to `tets` tet ids and a cut's working size.
  void reserve(std::uint32_t tets);

 private:
  // An edge as the order "longest" sees it.
  struct RankedEdge {
    double length2 = 0.0;
    std::uint32_t lo = 0, hi = 0;  // sorted vertex ids: the tie-break
    TetId tet;                     // a tet that has it
    int local = 0;                 // its local edge there
  };
  static bool longer(const RankedEdge& x, const RankedEdge& y);
  static RankedEdge longest_edge(const TetMesh& mesh, TetId t);
  // The terminal edge of LEPP(t), its shell left in shell_; `cut_short` when kMaxPathSteps ended
  // the walk first.
  RankedEdge terminal_edge(const TetMesh& mesh, TetId t, bool& cut_short);

  // Per tet of the bisected edge's shell, before the split: its two vertices off the edge (what
  // identifies it among its children) and whether it is a target.
  struct ShellTet {
    std::uint32_t c, d;  // sorted
    bool target;
  };
  std::vector<TetId> queue_, shell_, created_;
  std::vector<ShellTet> parents_;
  StampedSet<TetId> target_;
  // The live tets this call made: what the budget counts (net), as Refiner counts its own.
  StampedSet<TetId> born_;
};

}  // namespace tetcut
