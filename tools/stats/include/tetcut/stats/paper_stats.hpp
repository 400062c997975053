// `tetcut stats`: the paper's experiment (section 3.6) redone on our meshes.
//
// Five meshes of the paper's kinds, each cut by a documented cautery scenario in
// corpus/scenarios/paper/ (sweeps of the tool through the mesh, as the paper's electric lancet
// did), run with the combined strategy (paper 3.7) and templates: Tables 1 and 2 per mesh, with
// the paper's figures beside ours; the same scenarios again with our wider search (strategy wide,
// not the paper's) for its own Table 2 rows, the two searches side by side. Then the strategy
// comparison on one of those scenarios: basic
// (3.4), neighbours (3.5) and combined (3.7), with templates and with sequential bisection, each
// with and without the improvement pass. The quality of the tets the cuts created, per scenario
// and strategy, with and without the pass. And,
// for the pictures, the resection of the bundled liver (corpus/scenarios/liver-resection.scn).
//
// Everything but the per-cut times is deterministic: same corpus, same figures, same bits.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "tetcut/stats/cautery_run.hpp"
#include "tetcut/stats/paper_figures.hpp"
#include "tetcut/stats/removal_tables.hpp"

namespace tetcut::stats {

// One of the paper's five test meshes and our scenario for it.
struct PaperMesh {
  int number;               // the paper's mesh number, 1..5
  const char* name;         // our mesh: "cylinder", "sheet", "liver-coarse", ...
  const char* description;  // the paper's words
  const char* scenario;     // relative to the corpus folder
  // Half-widths of the box the seeded sweeps' offsets are drawn from (sweep_offset): half the
  // scenario's step along its passes, half the spacing of its passes, and across the cut plane
  // half the tool's diameter (the sheet: 0.05, so that its grooves stay cut into it).
  Vec3 jitter;
};

// The five, in the paper's order.
const std::vector<PaperMesh>& paper_meshes();

// The offset of sweep k of a mesh's scenario: sweep 0 is the scenario as
// written; sweep k >= 1 draws three numbers from std::mt19937_64 seeded with k (the standard
// fixes its output), each mapped to u in [0, 1) by its top 53 bits, and is jitter * (2u - 1)
// componentwise. The same k gives the same offset (relative to the jitter) on every mesh.
Vec3 sweep_offset(const PaperMesh& mesh, int k);

// "3 liver-coarse": the paper's number and our name, as the tables print a row.
std::string mesh_label(const PaperMesh& mesh);

// A mesh's scenario run once per seeded sweep (StatsOptions::sweeps); the figures pool them.
struct MeshStats {
  PaperMesh mesh;
  std::uint32_t tets_before = 0, tets_after = 0;  // after: sweep 0's (the scenario as written)
  std::uint64_t cuts = 0;                          // over every sweep
  RemovalReport removal;                           // the sweeps' reports summed
  std::vector<RemovalReport> sweeps;               // each sweep's
  std::vector<Vec3> offsets;                       // each sweep's offset
  Table1Row table1;                                // of `removal`
  Table2Row table2;
  Table1Intervals table1_ci;                       // the same cells with intervals and counts
  Table2Intervals table2_ci;
  double p50_us = 0, p99_us = 0;
  bool ok = true;           // the scenario ran to its end, its checks passing
  std::string error;
};

// One row of the strategy comparison.
struct StrategyRow {
  std::string name;         // "combined", "basic (bisection)", ...
  RemovalStrategy strategy = RemovalStrategy::kCombined;
  SplitMethod split = SplitMethod::kTemplates;
  std::uint64_t cuts = 0;
  std::uint64_t requests = 0;           // distinct tets requested
  std::uint64_t tets_created = 0;       // by the refinement loop and by removal
  std::uint64_t tets_removed = 0;
  double removed_per_request = 0;       // tets_removed / requests
  std::uint64_t unresolved = 0;         // distinct tets left in place at the end
  std::uint64_t fallback_refused = 0;   // fallbacks the splitter refused (RemovalReport)
  std::uint32_t tets_after = 0;         // these three: at the stop when !ok
  double worst_radius_ratio = 0, mean_radius_ratio = 0;  // of the mesh after the scenario
  double worst_created_radius_ratio = 1;                 // of the tets the cuts created
  double worst_created_min_dihedral_deg = 0;             // of the same tets (0: none created)
  // The created tets (radius ratio histogram, means), and the same run without the improvement
  // pass (CutParams::improve off): what the pass bought.
  invariants::QualityStats created, created_without_improvement;
  bool ok_without_improvement = true;
  double p50_us = 0, p99_us = 0;        // per cut
  bool ok = true;
  std::string error;                    // why the run stopped early
};

// The pass's figures: one paper scenario with one strategy, run with the improvement pass and
// without it. The goal is the worst created radius ratio at least min(0.1, the input's worst)
// (half that for basic, which may make small tets but not flat ones).
struct QualityRow {
  PaperMesh mesh;
  std::string strategy;                  // basic, neighbours, combined, wide
  double input_worst_radius_ratio = 0;   // of the scenario's mesh before its first cut
  double goal = 0;
  invariants::QualityStats created, created_without_improvement;
  bool ok = true, ok_without_improvement = true;  // ran to the end (a cut refused stops a run)
  std::string error, error_without_improvement;
  // Met: the run with the pass ran to its end (no cut refused, the growth guard not tripped) and
  // nothing it created is below the goal. A stopped run cannot meet it: what it would have
  // created after it stopped is not measured.
  [[nodiscard]] bool goal_met() const { return ok && (created.tets == 0 || created.min_radius_ratio >= goal); }
};

struct ResectionStats {
  std::string scenario;
  CauteryRun run;                       // with meshes before and after
};

struct StatsOptions {
  std::string corpus_dir = "corpus";   // where the scenarios are read from
  // What the reports call that folder (the resection's scenario is named through it): the
  // corpus_dir a user gave, or "corpus" when the command line found the bundled one itself.
  std::string corpus_label = "corpus";
  std::string comparison_mesh = "liver-refined";  // which paper mesh the strategies run on
  bool check_every_cut = true;
  bool resection = true;                // run the liver resection (needed for the pictures)
  bool quality = true;                  // the quality rows (40 runs: 5 scenarios, 4 strategies, pass on and off)
  // The improvement pass in the Tables' runs and the comparison: off by default, since the paper
  // has none and off measures its algorithm alone (with it, a cut whose tets the pass cannot lift
  // is refused and stops its run). The quality rows run both ways regardless.
  bool improve = false;
  // Runs of each paper scenario for Tables 1 and 2 (each order, and the wide search), at
  // sweep_offset(mesh, 0 .. sweeps - 1). The paper's experiment asks for at least 10.
  int sweeps = 10;
};

struct StatsReport {
  std::vector<MeshStats> meshes;
  // The same scenarios with the wide search in place of 3.5 (3.7 and the fallback behind it, as
  // in combined), one per entry of `meshes`: its own Table 2 rows (the paper has no such search).
  std::vector<MeshStats> wide_meshes;
  // The same scenarios with combined and the surface-first-by-id order (CutParams::order: one by
  // one, outside in; "the paper's order" in the JSON keys, one reading of it) in place of
  // direct-first: Tables 1 and 2 again, the ablation of the order.
  std::vector<MeshStats> paper_order_meshes;
  // The paper's other readings, Tables 1 and 2 again: the order that puts a non-removable tet
  // off and meets it again (RemovalOrder::kRevisit), and 3.5 stopping at the first removable
  // set (NeighbourSetChoice::kFirst) in our order.
  std::vector<MeshStats> revisit_meshes;
  std::vector<MeshStats> first_set_meshes;
  bool improve = true;                  // the runs' improvement pass (StatsOptions::improve)
  int sweeps = 1;                       // StatsOptions::sweeps
  std::string comparison_mesh;
  std::vector<StrategyRow> strategies;
  std::vector<QualityRow> quality;      // per paper scenario, per strategy
  std::optional<ResectionStats> resection;
};

struct StatsResult {
  std::optional<StatsReport> report;
  std::string error;                    // unusable corpus: names the file and the reason
};

StatsResult compute_stats(const StatsOptions& options);

}  // namespace tetcut::stats
