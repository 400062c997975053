// The refinement loop of paper 3.2: refine the tets hit by the tool until they are small enough
// for the cavity to have the tool's size, without elongated children.
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
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "tetcut/change_log.hpp"
#include "tetcut/edge_key_set.hpp"
#include "tetcut/edge_split.hpp"
#include "tetcut/mesh.hpp"
#include "tetcut/tool_ball.hpp"

namespace tetcut {

struct RefineParams {
  double d_ref = 0.0;               // edges longer than this are split; must be positive
  double p = 1.5;                   // shell edges longer than p x |e| are split too; must be > 1
  std::uint32_t max_iterations = 8;
  SplitMethod method = SplitMethod::kTemplates;
  std::optional<Ball> focus;        // when set, only new tets meeting it are refined further
};

// A message when a parameter is not finite, not positive, or p <= 1; nullopt when valid.
std::optional<std::string> validate(const RefineParams& params);

struct RefineReport {
  std::uint32_t iterations = 0;      // split rounds performed
  std::uint32_t edges_split = 0;
  std::uint32_t tets_created = 0;    // children made, including children later split again
  std::uint32_t tets_removed = 0;    // parents replaced
  double min_radius_ratio = 1.0;     // worst child created (1 when none)
  bool converged = true;             // false when max_iterations stopped the loop
  SplitRefusal refusal = SplitRefusal::kNone;  // a split refused for degeneracy stops the loop
};

class Refiner {
 public:
  // Refines around `initial` (live tet ids). Afterwards `region` holds the live tets among the
  // initial ones and those created, sorted by id: the candidates for removal.
  RefineReport refine(TetMesh& mesh, std::span<const TetId> initial, const RefineParams& params,
                      std::vector<TetId>& region, ChangeLog* log = nullptr);

  void reserve(std::uint32_t tets) { splitter_.reserve(tets); }

 private:
  void collect_long_edges(const TetMesh& mesh, double d_ref);
  void add_shell_edges(const TetMesh& mesh, double p);

  EdgeSplitter splitter_;
  std::vector<TetId> current_, created_, shell_;
  std::vector<Edge> edges_;
  EdgeKeySet seen_;
};

}  // namespace tetcut
