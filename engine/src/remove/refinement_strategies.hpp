// Paper 3.4 and 3.7: resolve a singularity by refining around it, then removing the small tets
// at the singularity together with T's children.
//
//   3.4 (basic)      as written: at every singularity T alone would leave (each singular vertex
//                    v and edge e of T, from the set test at each of T's vertices), split every
//                    edge at v (every edge from an end of e to the tets around e); the set is the
//                    children containing a singular v (containing e) and T's children. Where e has
//                    a singular end, that end's split cuts e: the children at the other end around
//                    e's ring go instead. No repair: a set that fails is rolled back (the
//                    dispatcher's fallback follows, counted apart).
//   3.7 (optimized)  split only the edges at v of T and of the tets on the shortest path from T
//                    to the border of v's shell (paper 3.5's path); for an edge, only those of
//                    the tets on one side of T around e (the smaller side first, then the
//                    other). The set is the children of those tets at v (at e) and T's children.
//                    Planned before it splits (our addition; docs/removal-proof.md, "3.7,
//                    planned"): the path is tested at v alone on the unchanged mesh, and when it
//                    fails there it is extended by the smallest piece it leaves at v that passes,
//                    as 3.5 extends its path. T goes whole, so each other vertex of T where T
//                    alone would leave a singularity gets a path of its own, planned the same
//                    way. A request whose plan fails splits nothing.
//
// Plan, then apply (style: Mmg's split_3d, our EdgeSplitter): a planning function reads the
// unchanged mesh and fills a RefinementPlan (the edges to split, and which children join T's);
// split_and_remove() takes that plan, splits (the splitter validates every child first) and
// tests the set.
//
// The paper says of 3.4 "we can formally prove that these set of tetrahedra can always be
// removed"; they cannot always (docs/removal-proof.md gives the configuration: a boundary edge
// from another surface vertex of T to v). 3.4's set that is not removable is rolled back to the
// savepoint taken before its split, and the caller uses the fallback. 3.7's is first repaired
// among the small tets by the wide search (wide_search.hpp: no further split; ours, not the
// paper's), then rolled back likewise. Where T has several planned vertices, the midpoint of T's edge between
// two of them is where their corner runs can pinch: the split's set is tested there alone and
// extended there before the full test, so that the repair search is rarely needed.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "remove/removability.hpp"
#include "remove/removal_context.hpp"
#include "remove/wide_search.hpp"

namespace tetcut::detail {

// What one 3.4 or 3.7 attempt does, decided on the unchanged mesh: the edges to split, and the
// corner groups whose children join T's in the set to remove.
struct RefinementPlan {
  // A range of `parents` whose children containing `at` (one vertex, or both ends of an edge)
  // join the set: their corners once the edges from `at` to the rest of each parent are split.
  struct CornerGroup {
    std::array<VertId, 2> at{};  // at[1] invalid for a vertex
    std::uint32_t begin = 0, size = 0;
    [[nodiscard]] std::span<const VertId> vertices() const { return {at.data(), at[1].valid() ? 2u : 1u}; }
  };

  std::vector<Edge> edges;         // to split, each with a tet that has it
  std::vector<TetId> parents;      // group after group, each group sorted (for binary search)
  std::vector<CornerGroup> groups;

  [[nodiscard]] std::span<const TetId> parents_of(const CornerGroup& g) const {
    return {parents.data() + g.begin, g.size};
  }
  // Whether x is a group's vertex (an end of a group's edge).
  [[nodiscard]] bool planned(VertId x) const;
};

class RefinementStrategies {
 public:
  // Working sizes, allocated and touched now (a larger request grows them once).
  void reserve();
  // Each returns the size of the set removed, 0 when the attempt failed (the mesh as before).
  std::uint32_t basic(RemovalContext& ctx, TetId t);
  // `searched_path`: T and its shortest path at the singular vertex, if 3.5 just found them on
  // this mesh (paper 3.7 stores the path of 3.5's search); empty: 3.7 finds it.
  std::uint32_t optimized(RemovalContext& ctx, TetId t, const Removability& first, const WideSearchLimits& repair,
                          std::span<const TetId> searched_path = {});

 private:
  // ---- planning, on the unchanged mesh ----
  // 3.4: a group per singularity of T: every edge at a singular vertex, or from a singular
  // edge's ends to its ring.
  void plan_basic(const TetMesh& mesh, SetRemovalWorkspace& ws, TetId t, RefinementPlan& plan);
  // 3.7 at a vertex singularity: a group at the singular vertex and at each other vertex of T
  // where T alone fails (plan_at_vertex), then the edges. False when a vertex has no plan.
  bool plan_optimized_vertex(const TetMesh& mesh, SetRemovalWorkspace& ws, TetId t, const Removability& first,
                             const WideSearchLimits& limits, std::span<const TetId> searched_path,
                             RefinementPlan& plan);
  // 3.7 at an edge singularity (a, b): T and the tets of one side of it around the edge.
  void plan_edge_side(const TetMesh& mesh, TetId t, std::span<const VertId, 2> ends, std::span<const TetId> side,
                      RefinementPlan& plan);
  // 3.7 at a vertex v of T: appends T, the shortest path from T to the border of v's shell and,
  // if those fail at v, the smallest piece they leave at v that passes, to the plan's parents as
  // one group. The split leaves v's link as it is (a link vertex w becomes the midpoint of
  // (v, w)) and the set's tets at v are the corners of the group, so the refined set passes at
  // v iff the group passes at v now. False when no candidate does.
  bool plan_at_vertex(const TetMesh& mesh, SetRemovalWorkspace& ws, TetId t, VertId v, const WideSearchLimits& limits,
                      std::span<const TetId> searched_path, RefinementPlan& plan);
  // Edges from `from` to the other vertices of `tets` (one hint each), into the plan.
  static void add_edges_from(const TetMesh& mesh, VertId from, std::span<const TetId> tets,
                             std::span<const VertId> skip, RefinementPlan& plan);
  // Every group's parents sorted, once its edges are chosen: what split_and_remove() searches.
  static void seal(RefinementPlan& plan);

  // 3.5's extension decided at one vertex: `set` from `begin` on failed check_at(v) with
  // `offence`; appends the smallest piece it leaves around v (or around the edge pinched at v)
  // with which it passes at v. False, `set` as it was, when none does within max_set_size.
  // Before a split (a plan's group) and after it (close_pinched_midpoints).
  bool extend_at(const TetMesh& mesh, SetRemovalWorkspace& ws, std::vector<TetId>& set, std::size_t begin, VertId v,
                 const Removability& offence, std::uint32_t max_set_size);

  // ---- applying a plan ----
  // Splits the plan's edges, then removes T's children and, for each group, the children of its
  // parents that contain the group's vertices, if removable; otherwise rolls back.
  // `repair` null: the set as planned, nothing of ours (3.4).
  std::uint32_t split_and_remove(RemovalContext& ctx, TetId t, const RefinementPlan& plan,
                                 const WideSearchLimits* repair);
  // After a split with several corner groups: the midpoint of an edge of T between two planned
  // vertices is where their corner runs can pinch (docs/removal-proof.md, "3.7, planned"). Each
  // such midpoint is tested alone and, where set_ fails there, set_ is extended by extend_at(),
  // so the full test that follows usually passes at once.
  void close_pinched_midpoints(RemovalContext& ctx, const RefinementPlan& plan,
                               std::span<const TetMesh::VertexBirth> midpoints, std::uint32_t max_set_size);
  // Removes `set` if removable, else its repair by the wide search if one is found; returns the
  // size removed, 0 for neither (the mesh untouched).
  std::uint32_t remove_or_repair(RemovalContext& ctx, const std::vector<TetId>& set, const WideSearchLimits* repair);

  WideSearch search_;
  RefinementPlan plan_;  // the attempt's plan: its memory reused from one request to the next
  std::vector<TetId> path_;               // plan_at_vertex(): 3.5's path
  std::vector<TetId> runs_;               // an edge's two sides (3.7 at an edge)
  std::vector<std::uint32_t> run_sizes_;
  std::vector<TetId> pieces_;             // extend_at(): what a failing set leaves at a vertex
  std::vector<std::uint32_t> piece_sizes_;
  std::vector<TetId> set_, larger_, repaired_;  // the applied set, with selected children, repaired
  std::vector<TetId> shell_;              // plan_basic(): a singularity's shell
};

}  // namespace tetcut::detail
