#include "tetcut/stats/paper_stats.hpp"

#include <algorithm>
#include <random>
#include <utility>

#include "tetcut/percentile.hpp"

namespace tetcut::stats {

const std::vector<PaperMesh>& paper_meshes() {
  static const std::vector<PaperMesh> meshes{
      // Jitter: step 0.15 along x, passes 0.25 apart in y, tool 0.4 across the plane z = 2.
      {1, "cylinder", "a simple cylinder", "scenarios/paper/cylinder.scn", {0.075, 0.125, 0.2}},
      // Grooves along x and along y (step 0.12, 2 to 4 apart): 0.2 either way in the sheet's
      // plane; depth 0.05 either way, so a groove is 0.15 to 0.25 deep of the 0.5 sheet.
      {2, "sheet", "a thin sheet, two tets thick, cut into (sheet.scn cuts through)", "scenarios/paper/sheet-into.scn",
       {0.2, 0.2, 0.05}},
      // The livers: tool 8 across the plane x = 95, step 4 along y, passes 5 apart in z.
      {3, "liver-coarse", "a rough liver (paper: 3,970 tets)", "scenarios/paper/liver-coarse.scn", {4.0, 2.0, 2.5}},
      {4, "liver-refined", "a finer liver (paper: 8,454 tets)", "scenarios/paper/liver-refined.scn", {4.0, 2.0, 2.5}},
      {5, "liver-local", "a liver locally refined by edge splitting (paper: 9,933 tets)",
       "scenarios/paper/liver-local.scn", {4.0, 2.0, 2.5}},
  };
  return meshes;
}

std::string mesh_label(const PaperMesh& mesh) { return std::to_string(mesh.number) + " " + mesh.name; }

Vec3 sweep_offset(const PaperMesh& mesh, int k) {
  if (k == 0) return {};
  std::mt19937_64 rng(static_cast<std::uint64_t>(k));
  auto draw = [&](double half_width) {
    const double u = static_cast<double>(rng() >> 11) * 0x1.0p-53;  // [0, 1), 53 bits
    return half_width * (2.0 * u - 1.0);
  };
  const double x = draw(mesh.jitter.x);  // in this order: arguments' order is unspecified
  const double y = draw(mesh.jitter.y);
  const double z = draw(mesh.jitter.z);
  return {x, y, z};
}

namespace {

// The strategy comparison stops a run whose mesh grows past this many times its initial size
// (no sweep of `tetcut stats` may do more): the basic strategy (paper 3.4) refines at every
// singularity, its set is often not removable as the paper claims (docs/removal-proof.md), and
// the cuts then meet the small tets it made and refine them again. Its row says where it stopped.
constexpr std::uint32_t kComparisonMaxGrowth = 2;

// One mesh's sweeps (runs[k] at sweep_offset(mesh, k)), pooled.
MeshStats mesh_stats(const PaperMesh& mesh, const std::vector<CauteryRun>& runs) {
  MeshStats s;
  s.mesh = mesh;
  s.tets_before = runs.front().tets_before;
  s.tets_after = runs.front().result.tets;
  std::vector<double> cut_us;
  for (std::size_t k = 0; k < runs.size(); ++k) {
    const CauteryRun& run = runs[k];
    s.cuts += run.result.cuts.size();
    s.removal += run.result.removal;
    s.sweeps.push_back(run.result.removal);
    s.offsets.push_back(sweep_offset(mesh, static_cast<int>(k)));
    cut_us.insert(cut_us.end(), run.cut_us.begin(), run.cut_us.end());
    if (s.ok && !run.result.ok) {
      s.ok = false;
      s.error = run.result.error + (k == 0 ? "" : " (sweep " + std::to_string(k) + ")");
    }
  }
  s.table1 = table1_row(s.removal);
  s.table2 = table2_row(s.removal);
  s.table1_ci = table1_intervals(s.sweeps);
  s.table2_ci = table2_intervals(s.sweeps);
  s.p50_us = percentile(cut_us, 0.5);
  s.p99_us = percentile(cut_us, 0.99);
  return s;
}

StrategyRow strategy_row(const std::string& name, const CauteryRun& run) {
  StrategyRow row;
  row.name = name;
  row.strategy = run.strategy;
  row.split = run.split;
  row.cuts = run.result.cuts.size();
  const RemovalReport& r = run.result.removal;
  row.requests = r.requested;
  for (const scenario::CutRecord& c : run.result.cuts) {
    row.tets_created += c.report.tets_created;
    row.tets_removed += c.report.tets_removed;
    row.worst_created_radius_ratio = std::min(row.worst_created_radius_ratio, c.report.min_radius_ratio);
  }
  row.removed_per_request = average(row.tets_removed, row.requests);
  row.unresolved = r.unresolved;
  row.fallback_refused = r.fallback_refused;
  row.tets_after = run.result.tets;
  row.created = run.result.created_quality;
  if (row.created.tets > 0) row.worst_created_min_dihedral_deg = row.created.min_dihedral_deg;
  row.worst_radius_ratio = run.quality_after.min_radius_ratio;
  row.mean_radius_ratio = run.quality_after.mean_radius_ratio;
  row.p50_us = percentile(run.cut_us, 0.5);
  row.p99_us = percentile(run.cut_us, 0.99);
  row.ok = run.result.ok;
  row.error = run.result.error;
  return row;
}

QualityRow quality_row(const PaperMesh& mesh, const char* strategy, const CauteryRun& with, const CauteryRun& without) {
  QualityRow row;
  row.mesh = mesh;
  row.strategy = strategy;
  row.input_worst_radius_ratio = with.quality_before.min_radius_ratio;
  // The pass's goal: min(0.1, the input's worst), half that for basic.
  row.goal = std::min(0.1, row.input_worst_radius_ratio) * (with.strategy == RemovalStrategy::kBasic ? 0.5 : 1.0);
  row.created = with.result.created_quality;
  row.created_without_improvement = without.result.created_quality;
  row.ok = with.result.ok;
  row.error = with.result.error;
  row.ok_without_improvement = without.result.ok;
  row.error_without_improvement = without.result.error;
  return row;
}

}  // namespace

StatsResult compute_stats(const StatsOptions& options) {
  StatsResult out;
  StatsReport report;
  // Read from corpus_dir, named through corpus_label: the reports and their errors read the same
  // wherever the corpus was found.
  auto run_scenario = [&](const std::string& relative, const CauteryOptions& o) {
    return run_cautery(options.corpus_dir + "/" + relative, o, options.corpus_label + "/" + relative);
  };
  const PaperMesh* comparison = nullptr;
  for (const PaperMesh& m : paper_meshes())
    if (options.comparison_mesh == m.name) comparison = &m;
  if (!comparison) {
    out.error = "unknown comparison mesh '" + options.comparison_mesh + "' (one of cylinder, sheet, liver-coarse, "
                "liver-refined, liver-local)";
    return out;
  }

  CauteryOptions run_options;
  run_options.check_every_cut = options.check_every_cut;
  run_options.improve = options.improve;
  report.improve = options.improve;
  report.sweeps = options.sweeps;
  if (options.sweeps < 1) {
    out.error = "sweeps must be at least 1";
    return out;
  }
  CauteryOptions wide_options = run_options;
  wide_options.strategy = RemovalStrategy::kWide;
  CauteryOptions paper_order_options = run_options;
  paper_order_options.order = RemovalOrder::kSurfaceFirstById;
  CauteryOptions revisit_options = run_options;
  revisit_options.order = RemovalOrder::kRevisit;
  CauteryOptions first_set_options = run_options;
  first_set_options.neighbour_set = NeighbourSetChoice::kFirst;
  // Each scenario with combined (Tables 1 and 2), then with the wide search (its Table 2 rows),
  // then with combined in the surface-first-by-id and the revisit orders, then with 3.5 stopping
  // at its first removable set (Tables 1 and 2 again, each).
  const std::pair<const CauteryOptions*, std::vector<MeshStats>*> runs[] = {
      {&run_options, &report.meshes},
      {&wide_options, &report.wide_meshes},
      {&paper_order_options, &report.paper_order_meshes},
      {&revisit_options, &report.revisit_meshes},
      {&first_set_options, &report.first_set_meshes}};
  for (const PaperMesh& m : paper_meshes())
    for (const auto& [o, into] : runs) {
      std::vector<CauteryRun> sweeps;
      for (int k = 0; k < options.sweeps; ++k) {
        CauteryOptions swept = *o;
        swept.offset = sweep_offset(m, k);
        CauteryResult r = run_scenario(m.scenario, swept);
        if (!r.run) {
          out.error = r.error;
          return out;
        }
        sweeps.push_back(std::move(*r.run));
      }
      into->push_back(mesh_stats(m, sweeps));
    }

  // The paper's three strategies, and our templates against sequential bisection.
  report.comparison_mesh = comparison->name;
  struct Variant {
    const char* name;
    RemovalStrategy strategy;
    SplitMethod split;
  };
  constexpr Variant kVariants[] = {
      {"basic", RemovalStrategy::kBasic, SplitMethod::kTemplates},
      {"neighbours", RemovalStrategy::kNeighbours, SplitMethod::kTemplates},
      {"combined", RemovalStrategy::kCombined, SplitMethod::kTemplates},
      {"wide (ours)", RemovalStrategy::kWide, SplitMethod::kTemplates},
      {"basic, bisection", RemovalStrategy::kBasic, SplitMethod::kBisection},
      {"neighbours, bisection", RemovalStrategy::kNeighbours, SplitMethod::kBisection},
      {"combined, bisection", RemovalStrategy::kCombined, SplitMethod::kBisection},
  };
  for (const Variant& v : kVariants) {
    CauteryOptions o = run_options;
    o.max_growth = kComparisonMaxGrowth;
    o.strategy = v.strategy;
    o.split = v.split;
    CauteryResult r = run_scenario(comparison->scenario, o);
    o.improve = false;
    CauteryResult without = run_scenario(comparison->scenario, o);
    if (!r.run || !without.run) {
      out.error = r.run ? without.error : r.error;
      return out;
    }
    StrategyRow row = strategy_row(v.name, *r.run);
    row.created_without_improvement = without.run->result.created_quality;
    row.ok_without_improvement = without.run->result.ok;
    report.strategies.push_back(std::move(row));
  }

  if (options.quality) {
    constexpr std::pair<const char*, RemovalStrategy> kQualityStrategies[] = {
        {"basic", RemovalStrategy::kBasic},
        {"neighbours", RemovalStrategy::kNeighbours},
        {"combined", RemovalStrategy::kCombined},
        {"wide", RemovalStrategy::kWide}};
    for (const PaperMesh& m : paper_meshes())
      for (const auto& [name, strategy] : kQualityStrategies) {
        CauteryOptions o = run_options;
        o.improve = true;  // with the pass, then without
        // The engine's default refinement (auto): the shape of what a cut makes as users get it.
        o.refinement = RefinementRule::kAuto;
        // Only basic refines without bound; the others run their scenario to its end, as Table 1.
        o.max_growth = strategy == RemovalStrategy::kBasic ? kComparisonMaxGrowth : 0;
        o.strategy = strategy;
        CauteryResult with = run_scenario(m.scenario, o);
        o.improve = false;
        CauteryResult without = run_scenario(m.scenario, o);
        if (!with.run || !without.run) {
          out.error = with.run ? without.error : with.error;
          return out;
        }
        report.quality.push_back(quality_row(m, name, *with.run, *without.run));
      }
  }

  if (options.resection) {
    CauteryOptions o = run_options;
    o.keep_meshes = true;
    o.improve = true;  // the resection's own expectations (min_quality) hold with the pass
    o.refinement = RefinementRule::kAuto;  // as `tetcut run` runs it
    CauteryResult r = run_scenario("scenarios/liver-resection.scn", o);
    if (!r.run) {
      out.error = r.error;
      return out;
    }
    std::string name = r.run->scenario;
    report.resection = ResectionStats{std::move(name), std::move(*r.run)};
  }
  out.report = std::move(report);
  return out;
}

}  // namespace tetcut::stats
