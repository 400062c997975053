// One cautery cut, as a simulator calls it many times a second (paper 3.1 to 3.7 together):
//
//   locate   T_hit = live tets meeting the tool ball (spatial index, never a mesh scan)
//   refine   the loop of paper 3.2 around T_hit with D_ref = d_ref_factor x diameter, following
//            the new tets that meet the ball
//   select   T_removal = the refined region's tets that are inside the tool and have no edge
//            longer than D_ref (paper 3.3). "Inside" means: the tet's centroid lies in the
//            closed ball. A tet that only grazes the ball stays; the cavity then has the
//            tool's size to within one small tet.
//   remove   one by one with the chosen strategy (removal.hpp), outside in: in rounds, the
//            selected tets on the surface now (increasing id), then any left (a tool inside)
//
// Atomic: the whole cut runs in a mesh transaction; if it cannot complete (a split refused
// for degeneracy, the per-cut tet budget exceeded) it is rolled back, the mesh is bit-identical
// to before, and the report says why. A tet left unresolved by the `neighbours` strategy is
// not a failure: the mesh is valid, the report counts it.
//
// Cost: local to the tool. Scratch memory lives in the Cutter; nothing allocates once warm
// (the mesh's arrays grow only when the free lists run dry).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "tetcut/change_log.hpp"
#include "tetcut/edge_split.hpp"
#include "tetcut/mesh.hpp"
#include "tetcut/refine.hpp"
#include "tetcut/removal.hpp"
#include "tetcut/spatial_index.hpp"
#include "tetcut/tool_ball.hpp"

namespace tetcut {

struct CutParams {
  double tool_diameter = 1.0;        // the ball's diameter (paper: the cautery tip)
  double d_ref_factor = 1.5;         // D_ref = d_ref_factor x tool_diameter (paper 3.2)
  double p = 1.5;                    // shell edge ratio of the refinement loop (paper 3.2)
  std::uint32_t search_depth = 10;   // neighbour search depth (paper 3.5)
  std::uint32_t max_refine_iterations = 8;
  std::uint32_t max_tets_created = 20000;  // tets a cut may create (refinement: net); more is refused, in < 50 ms on the liver
  RemovalStrategy strategy = RemovalStrategy::kCombined;
  SplitMethod split_method = SplitMethod::kTemplates;
};

// A message naming the parameter when one is non-finite, non-positive or out of range.
std::optional<std::string> validate(const CutParams& params);

struct CutTimings {
  double locate_us = 0, refine_us = 0, select_us = 0, remove_us = 0, total_us = 0;
};

struct CutReport {
  bool ok = true;
  std::string failure;               // why the cut was rolled back (when !ok)
  std::uint32_t tets_hit = 0;        // live tets meeting the ball before refinement
  std::uint32_t refine_iterations = 0;
  std::uint32_t edges_split = 0;     // by the refinement loop
  std::uint32_t tets_refined = 0;    // parents replaced by the refinement loop
  std::uint32_t requested = 0;       // |T_removal|
  std::uint32_t tets_removed = 0;    // all tets removed, neighbour sets included
  std::uint32_t tets_created = 0;    // by refinement and by refinement-based removal
  std::uint32_t direct = 0, vertex_singularities = 0, edge_singularities = 0;
  // unresolved: requests of this cut left in place (a tet left twice counts twice; the
  // Remover's report counts distinct tets, as the paper's tables do).
  std::uint32_t resolved_by_neighbours = 0, resolved_by_refinement = 0, resolved_by_flood = 0, unresolved = 0;
  double min_radius_ratio = 1.0;     // worst tet created (1 when none)
  CutTimings time;
};

class Cutter {
 public:
  // Indexes the mesh once (O(#T)); the grid's cell is the mesh's mean edge length. Reserves
  // room in the mesh for half as many tets again, so cuts do not reallocate its arrays.
  Cutter(TetMesh& mesh, const CutParams& params);

  // Fails (returns the message, keeps the old parameters) when validate() does.
  std::optional<std::string> set_params(const CutParams& params);
  [[nodiscard]] const CutParams& params() const { return params_; }

  // One cut with the tool centred at `centre`. Appends the net changes to `log` when given.
  CutReport cut(const Vec3& centre, ChangeLog* log = nullptr);

  // One removal request outside the cut pipeline (tetcut remove, scenarios): tet t with the
  // strategy, atomically, the index kept up to date. Reported like a cut with one request.
  CutReport remove(TetId t, ChangeLog* log = nullptr);

  // The live tet containing p (lowest id when several share it), or kNoTet: for scenarios that
  // address tets geometrically.
  TetId tet_containing(const Vec3& p);

  [[nodiscard]] const RemovalReport& removal_report() const { return remover_.report(); }
  [[nodiscard]] TetMesh& mesh() { return mesh_; }
  // The removals and creations of the last cut, net (what LocalChecker wants).
  [[nodiscard]] const std::vector<TetId>& last_removed() const { return net_removed_; }
  [[nodiscard]] const std::vector<TetId>& last_created() const { return net_created_; }

 private:
  // Removes the tets of removal_, those on the surface first (outside in), and fills the counts.
  void remove_selected(CutReport& report);
  void finish(CutReport& report, ChangeLog* log);

  TetMesh& mesh_;
  CutParams params_;
  MeshScale scale_;  // what the refinement can serve (check_scale), measured once
  SpatialIndex index_;
  Refiner refiner_;
  Remover remover_;
  ChangeLog log_;
  std::vector<TetId> hit_, region_, removal_, net_removed_, net_created_;
  std::vector<TetMesh::TetVerts> removal_verts_;  // per tet of removal_: its vertices when selected
  std::vector<std::uint8_t> tried_;  // per tet of removal_: already requested in this cut
};

}  // namespace tetcut
