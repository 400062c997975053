// Splitting a set of edges at their midpoints (paper 3.2): one new vertex per edge, shared by
// every tet around it, and every affected tet replaced by its template (split_templates.hpp).
// Also the baseline the templates are measured against: sequential bisection, one edge at a
// time across its whole shell.
//
// Both plan first and apply second (style: Mmg's split_3d): if any child would be inverted or
// flat by the exact predicate, the split is refused with a reason and the mesh is untouched.
//
// The split point need not be the midpoint: the templates' children are positive in exact
// arithmetic for any point inside each split edge (docs/removal-proof.md, "Any split point"), so
// a caller whose proof is combinatorial (the removal fallback) may ask the splitter to move the
// points of the edges around a tet whose midpoint children round flat or inverted
// (SplitPoint::kPositiveChildren).
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "refine/split_templates.hpp"  // FaceRule
#include "tetcut/cut_strategies.hpp"  // SplitMethod
#include "tetcut/detail/stamped_property.hpp"
#include "tetcut/ids.hpp"
#include "tetcut/mesh.hpp"

namespace tetcut {

struct Edge {
  VertId a, b;
  TetId hint = kNoTet;  // a tet known to contain the edge, if any: saves searching a shell
};

enum class SplitRefusal : std::uint8_t {
  kNone,
  kNotAnEdge,        // the two vertices are not joined by an edge of the mesh
  kDegenerateChild,  // a child would be inverted or flat (floating-point degeneracy)
  kOverBudget,       // the plan has more children than the caller allows
};

const char* to_string(SplitRefusal refusal);

// Where a split puts each new vertex on its edge.
enum class SplitPoint : std::uint8_t {
  kMidpoint,  // t = 1/2 on every edge (paper 3.2)
  // Midpoints when every child is positive, the split exactly as kMidpoint. Otherwise, the edges
  // of the tets with a flat or inverted child each move, one at a time in global edge order, to
  // the parameter of kSplitParameters whose shell has the best worst child (fewest non-positive
  // children, then the largest smallest radius ratio; ties to the earlier one, the midpoint first),
  // two passes; the split is refused only if a child is still not positive. The parameters are
  // dyadic and symmetric about 1/2, so 1 - t is exact and the point does not depend on which end
  // the edge is named from.
  kPositiveChildren,
};
inline constexpr std::array<double, 7> kSplitParameters = {0.5, 0.4375, 0.5625, 0.375, 0.625, 0.25, 0.75};
static_assert(kSplitParameters[0] == 0.5, "the midpoint first: ties keep it");
static_assert(
    [] {
      for (double t : kSplitParameters) {
        bool mirrored = false;
        for (double u : kSplitParameters) mirrored |= u == 1.0 - t;
        if (!(t > 0.0 && t < 1.0) || !mirrored) return false;
      }
      return true;
    }(),
    "inside (0, 1) and symmetric about 1/2, whichever end an edge is named from");

struct SplitResult {
  SplitRefusal refusal = SplitRefusal::kNone;
  Edge offending{};                 // the edge involved when refused
  std::uint32_t edges_split = 0;
  std::uint32_t tets_removed = 0;
  std::uint32_t tets_created = 0;
  // No quality figure: most callers (a cut's rounds, a removal's attempt) never read it, and
  // measuring every child would be work on every cut for nobody. A caller that wants the worst child
  // measures the tets in `created` (Refiner does, when RefineParams::measure_quality).

  [[nodiscard]] bool ok() const { return refusal == SplitRefusal::kNone; }
};

// Caller-owned scratch: reuse one across calls and nothing is allocated once it has grown.
class EdgeSplitter {
 public:
  // Splits every edge of `edges` (duplicates and either orientation allowed). Created tets are
  // appended to `created` (if given); inside a transaction the mesh's journal records each child
  // with its parent and each midpoint with its edge (TetMesh::tets_made_since). A plan with more
  // than `max_created` children is refused (kOverBudget) as soon as planning passes the bound,
  // before the mesh changes: a caller with a budget pays for at most that many planned children.
  // `point`: where the new vertices go (SplitPoint); each is made by
  // TetMesh::add_vertex_on_edge(lo, hi, t) with lo < hi, and the journal records its t.
  SplitResult split(TetMesh& mesh, std::span<const Edge> edges, SplitMethod method,
                    std::vector<TetId>* created = nullptr, std::uint64_t max_created = UINT64_MAX,
                    SplitPoint point = SplitPoint::kMidpoint);

  // Room for per-tet scratch up to this many tet ids (no reallocation of a mesh-sized array in
  // the middle of an operation).
  // And room for the plan of a split of up to kPlannedChildren children, the working size of a
  // cut: a larger one grows the buffers once, then they stay.
  void reserve(std::uint32_t tets);
  static constexpr std::size_t kPlannedChildren = 8192;

  // How the templates triangulate a face with two split edges (split_templates.hpp): by default
  // from the longer split edge's midpoint (kLongerEdge: the face's shorter diagonal); kVertexOrder
  // is the paper's rule, which ignores geometry. Either way every tet has a cone point.
  void set_face_rule(FaceRule rule) { face_rule_ = rule; }
  [[nodiscard]] FaceRule face_rule() const { return face_rule_; }

 private:
  struct PlannedEdge {
    std::uint32_t lo, hi;  // sorted vertex ids: the global order of the paper's rule
    VertId vertex;         // the new vertex, once applied
    TetId hint;
    double t = 0.5;        // the new vertex at (1 - t) * lo + t * hi
    bool free = false;     // SplitPoint::kPositiveChildren: t may move
  };
  struct AffectedTet {
    TetId tet;
    std::uint8_t mask;
  };

  SplitResult plan(const TetMesh& mesh, SplitMethod method, std::uint64_t max_created);
  void apply(TetMesh& mesh, std::vector<TetId>* created, SplitResult& result);
  // One tet's children into labels_, over its corners and split points `p`.
  void plan_tet(const AffectedTet& a, const std::array<std::uint32_t, 4>& ids, const Vec3 (&p)[10], SplitMethod method);
  // The corners and split points of a tet: midpoints while every t is 1/2 (the common case,
  // no lookup), otherwise each split edge's own point, computed from its sorted ends.
  void tet_points(const TetMesh& mesh, const AffectedTet& a, Vec3 (&p)[10]) const;
  // How good a tet's children are at the current points: minus the number of children that are
  // not positive, or the smallest radius ratio when all are.
  double children_score(const TetMesh& mesh, const AffectedTet& a, SplitMethod method);
  // SplitPoint::kPositiveChildren after the midpoints failed (see there).
  void choose_split_points(const TetMesh& mesh, SplitMethod method);
  [[nodiscard]] int find_edge(std::uint32_t lo, std::uint32_t hi) const;
  bool collect_shell(const TetMesh& mesh, const PlannedEdge& e);

  FaceRule face_rule_ = FaceRule::kLongerEdge;
  bool all_midpoints_ = true;  // every planned edge has t = 1/2
  std::vector<PlannedEdge> edges_;
  std::vector<AffectedTet> affected_;
  StampedMap<TetId, std::uint32_t> affected_slot_;  // an affected tet's index in affected_
  std::vector<TetId> shell_;
  std::vector<TetId> parents_;
  std::vector<std::array<std::uint8_t, 4>> labels_;      // one tet's children, local labels
  std::vector<std::array<std::uint8_t, 4>> all_labels_;  // every planned child
  std::vector<TetMesh::TetVerts> children_;
  std::vector<TetId> child_parent_;  // per child: the affected tet it comes from
  std::vector<std::uint8_t> children_per_parent_;
};

}  // namespace tetcut
