// The refinement loop of paper 3.2: refine the tets hit by the tool until they are small enough
// for the cavity to have the tool's size, without elongated children. RefineParams::rule chooses
// it (kPaper, below) or the refinement graded to the tool (kGraded: Rivara's longest-edge
// bisection, longest_edge_bisection.hpp), which the Refiner runs in the same scratch.
//
// Given the tets T hit by the tool:
//   E_split = edges of T longer than D_ref (paper: D_ref = 1.5 x tool diameter);
//   for every edge e in E_split (including those added here), every edge of the shell of e
//   (the edge opposite e in each tet around e) longer than p x |e| joins E_split (paper: p =
//   1.5; close to 1 gives many well-shaped tets, 2 or more gives few, poorly shaped ones);
//   split E_split (templates by default), T := the new tets, and repeat until E_split is empty.
// The paper observes at most 3 iterations with p = 1.5; we bound them (max_iterations).
// With a focus ball (the tool), T := the new tets that meet the ball: without it, the children
// of shell edges far from the tool would keep the loop spreading through a coarse mesh (paper
// Figure 3 refines "at the vicinity of the tool").
//
// A budget bounds the work, not only the result: before each round the plan's
// children are counted against what is left of max_tets_created, and a round that would pass it
// is not applied, so a refused loop costs about its budget. The count is net (the tets the loop
// made that are still live: a child split again in a later round counts only through its own
// children), so a loop whose result fits is never refused.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/edge_key_set.hpp"
#include "core/tool.hpp"
#include "refine/edge_split.hpp"
#include "refine/longest_edge_bisection.hpp"
#include "tetcut/cut_strategies.hpp"  // RefinementRule
#include "tetcut/detail/stamped_property.hpp"
#include "tetcut/mesh.hpp"

namespace tetcut {

struct RefineParams {
  // kGraded uses d_ref, focus, max_tets_created. kAuto is the Cutter's to resolve (it knows the
  // mesh's scale): here it runs the paper's loop.
  RefinementRule rule = RefinementRule::kPaper;
  double d_ref = 0.0;               // edges longer than this are split; must be positive
  double p = 1.5;                   // shell edges longer than p x |e| are split too; must be > 1
  std::uint32_t max_iterations = 8;
  SplitMethod method = SplitMethod::kTemplates;
  std::optional<Tool> focus;        // when set, only new tets meeting it are refined further
  std::uint32_t max_tets_created = UINT32_MAX;  // net tets the loop may make; must be positive
  // RefineReport::min_radius_ratio over every child made. The cut leaves it off: it reports the
  // worst of its net new tets instead, and measuring every intermediate child is work on the
  // per-cut path that nobody reads.
  bool measure_quality = true;
};

// A message when a parameter is not finite, not positive, or p <= 1; nullopt when valid.
std::optional<std::string> validate(const RefineParams& params);

// The mesh's length and volume scales, as the refinement loop meets them: O(#T), once (the
// Cutter's constructor).
struct MeshScale {
  double shortest_edge = 0.0;  // over live tets; 0 for an empty mesh
  double mean_edge = 0.0;      // the mean over the tets' edges (an edge counted once per tet)
  double volume = 0.0;
};
MeshScale measure_scale(const TetMesh& mesh);

// The fewest tets the loop must create to serve a tool of `tool_diameter` with this D_ref when
// D_ref is below the mesh's shortest edge, 0 otherwise. Every tet the tool meets then has all
// its edges longer than D_ref, so the loop ends only once the part of the ball inside the mesh
// is covered by new tets with no edge over D_ref, none larger than the regular tet of edge
// D_ref (volume D_ref^3 / (6 sqrt 2)): at least min(ball, mesh volume) / that. A tool reaching
// the surface covers less of the mesh; a parameter set is judged by a tool inside it.
double min_tets_to_refine(const MeshScale& scale, double tool_diameter, double d_ref);

// A message naming the parameter (d_ref_factor) when min_tets_to_refine() exceeds the per-cut
// budget: such a cut can only be refused, after doing a budget's worth of work. nullopt when
// the parameters can be served (or are invalid: validate() names those).
std::optional<std::string> check_scale(const MeshScale& scale, double tool_diameter, double d_ref_factor,
                                       std::uint32_t max_tets_created);

struct RefineReport {
  std::uint32_t iterations = 0;      // split rounds performed (kGraded: bisections)
  std::uint32_t edges_split = 0;
  std::uint32_t tets_created = 0;    // children made, including children later split again
  std::uint32_t tets_removed = 0;    // parents replaced
  std::uint32_t net_tets_created = 0;  // children still live: what max_tets_created bounds
  double min_radius_ratio = 1.0;     // worst child created (1 when none or not measured)
  bool converged = true;             // false when max_iterations stopped the loop
  // A split refused for degeneracy stops the loop; so does the budget (kOverBudget: the round
  // that would have passed it was planned, not applied).
  SplitRefusal refusal = SplitRefusal::kNone;
  // kGraded: bisections whose propagation path reached LongestEdgeBisection::kMaxPathSteps and
  // bisected the longest edge it had reached instead of a terminal one.
  std::uint32_t paths_cut_short = 0;
};

// What both rules share (refine.cpp, longest_edge_bisection.cpp):
// the children a split may plan when `net` tets this call made are live and `born_parents` of the
// split's parents are among them, so that net + children - born_parents stays within the budget;
std::uint64_t children_allowed(const RefineParams& params, std::uint64_t net, std::uint32_t born_parents);
// an applied split in the report, `net` the tets this call made still live after it;
void count_split(RefineReport& report, const SplitResult& split, std::uint64_t net);
// the region as Refiner::refine returns it: live, distinct, sorted by id.
void finish_region(const TetMesh& mesh, std::vector<TetId>& region);

class Refiner {
 public:
  // Refines around `initial` (live tet ids). Afterwards `region` holds the live tets among the
  // initial ones and those created, sorted by id: the candidates for removal. Inside a
  // transaction the mesh's journal records what was made (TetMesh::tets_made_since).
  RefineReport refine(TetMesh& mesh, std::span<const TetId> initial, const RefineParams& params,
                      std::vector<TetId>& region);

  // Room (allocated and touched) for meshes up to `tets` tet ids and the working size of one
  // loop; a larger loop grows its lists once.
  void reserve(std::uint32_t tets);

 private:
  void collect_long_edges(const TetMesh& mesh, double d_ref);
  // Returns how many of the tets around the edges (the round's parents) this loop made.
  std::uint32_t add_shell_edges(const TetMesh& mesh, double p);

  EdgeSplitter splitter_;
  LongestEdgeBisection graded_;  // RefinementRule::kGraded, bisecting with splitter_
  std::vector<TetId> current_, created_, shell_;
  std::vector<Edge> edges_;
  EdgeKeySet seen_;
  // The live children of this call's loop. A parent found so is erased as it is counted, so each
  // is counted once per round.
  StampedSet<TetId> born_;
};

}  // namespace tetcut
