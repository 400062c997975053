// One cautery scenario run with a chosen removal strategy and split method, and what the
// statistics need from it: the paper's counts, per-cut times, quality before and after, and
// (when asked) the meshes before and after for pictures.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "tetcut/cut.hpp"
#include "tetcut/invariants/check.hpp"
#include "tetcut/mesh.hpp"
#include "tetcut/scenario/scenario.hpp"

namespace tetcut::stats {

struct CauteryRun {
  std::string scenario;                // the file, as named
  RemovalStrategy strategy = RemovalStrategy::kCombined;
  SplitMethod split = SplitMethod::kTemplates;
  scenario::RunResult result;          // ok == false: it stopped early (result.error says why)
  std::uint32_t tets_before = 0;
  invariants::QualityStats quality_before, quality_after;  // after: at the stop if it stopped
  std::vector<double> cut_us;          // each cut's total time, in scenario order
  std::optional<TetMesh> mesh_before, mesh_after;  // when keep_meshes
};

struct CauteryOptions {
  RemovalStrategy strategy = RemovalStrategy::kCombined;
  SplitMethod split = SplitMethod::kTemplates;
  RemovalOrder order = RemovalOrder::kDirectFirst;  // CutParams::order; a scenario's own line wins
  NeighbourSetChoice neighbour_set = NeighbourSetChoice::kSmallest;  // CutParams::neighbour_set
  // The paper's refinement loop for its tables (CutParams::refinement; a scenario's line wins).
  RefinementRule refinement = RefinementRule::kPaper;
  // Run the local checker after every cut (the scenario runner's default). The statistics do
  // not depend on it; `tetcut stats --check end` skips it for speed and checks the end only.
  bool check_every_cut = true;
  bool keep_meshes = false;
  // When non-zero, the run stops once the mesh holds more than this many times its initial
  // tets (the basic strategy refines without bound over a sweep).
  std::uint32_t max_growth = 0;
  // The improvement pass that ends each cut (CutParams::improve); a scenario's own `improve`
  // line still wins.
  bool improve = true;
  // Added to every tool position of the scenario (its cut, sweep and remove lines): one of the
  // seeded sweeps of `tetcut stats` (paper_stats.hpp, sweep_offset).
  Vec3 offset{};
};

struct CauteryResult {
  std::optional<CauteryRun> run;
  std::string error;                   // unusable scenario or mesh: "FILE:LINE: reason"
};

// Runs the scenario file with the strategy and split method set before its own settings (so a
// scenario that sets none is run as asked). A scenario that fails part-way still gives a run,
// with result.ok false and the statistics up to the failure; only unusable input is an error.
// `name` is what the run and its errors call the scenario (default: the path).
CauteryResult run_cautery(const std::string& scenario_path, const CauteryOptions& options,
                          const std::string& name = "");

}  // namespace tetcut::stats
