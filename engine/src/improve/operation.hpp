// One local operation of the improvement pass, in one shape whatever the operator: a Plan.
//
// After CGAL Tetrahedral_remeshing's Elementary_operation (what an operation touches, how it is
// executed, its name) and Mmg's simulate-then-apply (split_3d.c): an operator plans on the const
// mesh the tets it would remove and the tets it would add, as vertex quadruples, with the one
// vertex position it sets (a smoothing move's target, an inserted point), so that anyone, the
// pass or a caller's acceptance hook (plan_veto.hpp), measures the new tets before the mesh
// changes. Only an accepted plan is applied. A plan that cannot be made says why (Refusal, as
// CGAL's Sliver_removal_result does), and the mesh is untouched.
//
// The operators (Klingner and Shewchuk, "Aggressive tetrahedral mesh improvement", 2007, combine
// the same; Mmg's optimisation has the like):
//   edge removal, face removal  flips.hpp
//   collapse                    collapse.hpp
//   smoothing                   smoothing.hpp
//   insertion                   insertion.hpp
//   sliver removal              sliver_removal.hpp
// A new operator is a value of Operator, a planner that fills a Plan, and the case of apply()
// that carries it out; the pass offers its plans like any other (improver.cpp).
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "refine/edge_split.hpp"
#include "remove/tissue_removal.hpp"
#include "tetcut/ids.hpp"
#include "tetcut/mesh.hpp"
#include "tetcut/vec3.hpp"

namespace tetcut::detail {

enum class Operator : std::uint8_t {
  kEdgeRemoval,    // the tets around an edge retriangulated: 2-2, 3-2, 4-4 and larger rings
  kFaceRemoval,    // the 2-3 flip: two tets sharing a face made three around a new edge
  kCollapse,       // a vertex merged into a neighbour
  kSmoothing,      // one vertex moved, its star reshaped
  kInsertion,      // a new vertex at an edge's midpoint, every tet around the edge halved
  kSliverRemoval,  // a sliver at the cut's surface, gone with the tissue
};
inline constexpr std::size_t kOperatorCount = 6;
static_assert(static_cast<std::size_t>(Operator::kSliverRemoval) + 1 == kOperatorCount, "the last operator");

// Why a plan was not made, or not taken.
enum class Refusal : std::uint8_t {
  kNone,               // planned: may be applied
  kNotFlippable,       // no such flip here: a boundary face, a ring too large or open, a pair not convex
  kNotAnEdge,          // the two vertices of a collapse are not joined by an edge
  kExistingSimplex,    // a new edge or face exists elsewhere already (it would get two shells, I6)
  kLinkCondition,      // a collapse would change the topology (Dey, Edelsbrunner, Guha, Nekhayev)
  kInvertedChild,      // a new tet would be flat or inverted by the exact predicate
  kNotBetter,          // its worst new tet does not beat the worst one it replaces by the margin
  kSpreadsBadVolume,   // its new tets below theta would cover more volume than those it replaces
  kSurfaceConstraint,  // the organ's surface would change shape
  kNotMadeByCut,       // moves or removes a vertex the open transaction did not make
  kUncuttable,         // reshapes uncuttable tissue, or mixes it with cuttable tissue
  kOutOfReach,         // outside the cut's reach
  kNotRemovable,       // removing the tet alone would leave the mesh non-manifold (paper 3.3)
  kVetoed,             // the caller's acceptance hook said no
};
inline constexpr std::size_t kRefusalCount = 14;
static_assert(static_cast<std::size_t>(Refusal::kVetoed) + 1 == kRefusalCount, "the last refusal");

[[nodiscard]] std::string_view to_string(Operator op);
[[nodiscard]] std::string_view to_string(Refusal refusal);

// The id a plan gives the vertex it would create (an insertion's point): no vertex has it until
// the plan is applied.
inline constexpr VertId kPlannedVertex{0xFFFFFFFEu};

// Storage is the plan's own, reserved once (reserve()) and reused from plan to plan: two plans
// swap in O(1), which is how the pass keeps the best one so far.
struct Plan {
  Operator op = Operator::kEdgeRemoval;
  std::vector<TetId> removed;            // live tets the plan takes away
  std::vector<TetMesh::TetVerts> added;  // the tets it makes, positively oriented
  // The one vertex the plan places, if any, and where: a moved vertex, or kPlannedVertex for the
  // point an insertion creates. Every other vertex stays where it is.
  VertId placed = kNoVert;
  Vec3 placed_at{};
  double worst_before = 1.0;  // quality() of the worst tet it removes
  double worst_after = 1.0;   // and of the worst it adds (1 when it adds none)
  // An insertion's edge, and the splitter that carries it out (its scratch: the Inserter's).
  Edge split_edge{};
  EdgeSplitter* splitter = nullptr;
  // A sliver removal's way out: the transaction's removal path, which tallies what it took.
  TissueRemoval* tissue = nullptr;

  void reserve(std::size_t tets);
  // Empties the plan for `operation`: no tets, no vertex placed.
  void start(Operator operation);

  // "3-2 flip", "collapse", ...: the operator, and for edge removal the classic flip it is.
  [[nodiscard]] std::string_view name() const;
  [[nodiscard]] std::span<const TetId> removed_tets() const { return removed; }
  [[nodiscard]] std::span<const TetMesh::TetVerts> added_tets() const { return added; }
  // Where vertex v is once the plan is applied (v a vertex of an added tet).
  [[nodiscard]] Vec3 position(const TetMesh& mesh, VertId v) const { return v == placed ? placed_at : mesh.position(v); }
  // The corners of an added tet, where they are once the plan is applied.
  [[nodiscard]] std::array<Vec3, 4> corners(const TetMesh& mesh, const TetMesh::TetVerts& tet) const {
    return {position(mesh, tet[0]), position(mesh, tet[1]), position(mesh, tet[2]), position(mesh, tet[3])};
  }

  // Carries the plan out on the mesh it was planned on, unchanged since; the ids of the tets it
  // makes are appended to `created` (inside a transaction the journal records them with the
  // removed tets as parents, a split's children with their own).
  void apply(TetMesh& mesh, std::vector<TetId>& created) const;
};

}  // namespace tetcut::detail
