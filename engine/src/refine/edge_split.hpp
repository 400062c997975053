// Splitting a set of edges at their midpoints (paper 3.2): one new vertex per edge, shared by
// every tet around it, and every affected tet replaced by its template (split_templates.hpp).
// Also the baseline the templates are measured against: sequential bisection, one edge at a
// time across its whole shell.
//
// Both plan first and apply second (style: Mmg's split_3d): if any child would be inverted or
// flat by the exact predicate, the split is refused with a reason and the mesh is untouched.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "refine/split_templates.hpp"  // FaceRule
#include "tetcut/cut_strategies.hpp"  // SplitMethod
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
  SplitResult split(TetMesh& mesh, std::span<const Edge> edges, SplitMethod method,
                    std::vector<TetId>* created = nullptr, std::uint64_t max_created = UINT64_MAX);

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
    VertId midpoint;
    TetId hint;
  };
  struct AffectedTet {
    TetId tet;
    std::uint8_t mask;
  };

  SplitResult plan_and_apply(TetMesh& mesh, SplitMethod method, std::vector<TetId>* created,
                             std::uint64_t max_created);
  [[nodiscard]] int find_edge(std::uint32_t lo, std::uint32_t hi) const;
  bool collect_shell(const TetMesh& mesh, const PlannedEdge& e);

  FaceRule face_rule_ = FaceRule::kLongerEdge;
  std::vector<PlannedEdge> edges_;
  std::vector<AffectedTet> affected_;
  std::vector<std::uint32_t> affected_slot_;  // per tet id: index into affected_ + 1, or 0
  std::vector<TetId> shell_;
  std::vector<TetId> parents_;
  std::vector<std::array<std::uint8_t, 4>> labels_;      // one tet's children, local labels
  std::vector<std::array<std::uint8_t, 4>> all_labels_;  // every planned child
  std::vector<TetMesh::TetVerts> children_;
  std::vector<TetId> child_parent_;  // per child: the affected tet it comes from
  std::vector<std::uint8_t> children_per_parent_;
};

}  // namespace tetcut
