#include "stats_json.hpp"

#include <array>
#include <span>
#include <tuple>

#include "tetcut/percentile.hpp"
#include "tetcut/scenario/values.hpp"
#include "tetcut/stats/fisher_exact.hpp"

namespace tetcut::cli {

namespace {

Json removal_counts(const RemovalReport& r) {
  return Json{{"requested", r.requested},
              {"direct", r.direct},
              {"vertex_singularities", r.vertex_singularities},
              {"edge_singularities", r.edge_singularities},
              {"vertex_resolved_by_neighbours", r.vertex_resolved_by_neighbours},
              {"edge_resolved_by_neighbours", r.edge_resolved_by_neighbours},
              {"vertex_neighbour_set_tets", r.vertex_neighbour_set_tets},
              {"edge_neighbour_set_tets", r.edge_neighbour_set_tets},
              {"resolved_by_refinement", r.resolved_by_refinement},
              {"resolved_by_optimized_refinement", r.resolved_by_optimized_refinement},
              {"resolved_by_fallback", r.resolved_by_fallback},
              {"selected_in_sets", r.selected_in_sets},
              {"attempts_undone", r.attempts_undone},
              {"fallback_refused", r.fallback_refused},
              {"unresolved", r.unresolved},
              {"surface_requested", r.surface_requested},
              {"surface_direct", r.surface_direct},
              {"surface_vertex_singularities", r.surface_vertex_singularities},
              {"surface_edge_singularities", r.surface_edge_singularities},
              {"tets_removed", r.tets_removed},
              {"tets_created", r.tets_created}};
}

// One figure of a table row: ours, the paper's, and whether the difference is meaningful (a
// count is written as an integer and has no difference).
struct Figure {
  const char* key;
  double ours, paper;
  bool diff = true;
};

Json figure_value(const Figure& f, double v) { return f.diff ? Json(v) : Json(static_cast<std::uint64_t>(v)); }

// Our figures as members of `row`, then objects "paper" (the paper's) and "diff" (ours minus
// the paper's).
void ours_paper_diff(Json& row, std::span<const Figure> figures) {
  Json paper = Json::object(), diff = Json::object();
  for (const Figure& f : figures) {
    row[f.key] = figure_value(f, f.ours);
    paper[f.key] = figure_value(f, f.paper);
    if (f.diff) diff[f.key] = f.ours - f.paper;
  }
  row["paper"] = std::move(paper);
  row["diff"] = std::move(diff);
}

// A cell's 95 % interval and raw counts: "ci95" [lo, hi] in the cell's unit
// (null bounds when it has nothing to estimate from), "count" [events, trials] for a rate or
// [tets, sets] for a mean size.
void intervals(Json& row, std::span<const std::pair<const char*, const stats::CellEstimate*>> cells) {
  Json ci = Json::object(), count = Json::object();
  for (const auto& [key, e] : cells) {
    ci[key] = Json::array({e->ci.lo, e->ci.hi});
    count[key] = Json::array({e->count, e->of});
  }
  row["ci95"] = std::move(ci);
  row["count"] = std::move(count);
}

// Fisher's exact test of each rate cell against the paper's (fisher_exact.hpp): "fisher_p" (the
// two-sided p, the largest over the counts the paper's figures admit; null without trials) and
// "paper_count" ([[k_lo, k_hi], [n_lo, n_hi]]: the paper's events and trials, rebuilt from its
// percentages), keyed like the cells.
void fisher(Json& row, std::span<const std::tuple<const char*, const stats::CellEstimate*, const stats::PaperCount*>> cells) {
  Json p = Json::object(), count = Json::object();
  for (const auto& [key, e, c] : cells) {
    p[key] = stats::fisher_vs_paper(*e, *c);
    count[key] = Json::array({Json::array({c->k_lo, c->k_hi}), Json::array({c->n_lo, c->n_hi})});
  }
  row["fisher_p"] = std::move(p);
  row["paper_count"] = std::move(count);
}

// How the row's sweeps were run: their number and offsets (paper_stats.hpp, sweep_offset).
void sweeps(Json& row, const stats::MeshStats& m) {
  row["sweeps"] = m.sweeps.size();
  Json offsets = Json::array();
  for (const Vec3& o : m.offsets) offsets.push_back(Json::array({o.x, o.y, o.z}));
  row["offsets"] = std::move(offsets);
  Json counts = Json::array();
  for (const RemovalReport& r : m.sweeps) counts.push_back(removal_counts(r));
  row["sweep_counts"] = std::move(counts);  // each sweep's, in order; "counts" (Table 2) sums them
}

// Every configuration of verdicts (left, right, whole) 3.5's edge search met,
// with its count; only those met.
Json edge_search(const EdgeSearchTally& tally) {
  Json out = Json::array();
  for (int c = 0; c < EdgeSearchTally::kConfigurations; ++c) {
    const std::uint64_t n = tally.counts[static_cast<std::size_t>(c)];
    if (n == 0) continue;
    const auto config = static_cast<std::uint16_t>(c);
    out.push_back(Json{{"left", to_string(EdgeSearchTally::verdict(config, 0))},
                       {"right", to_string(EdgeSearchTally::verdict(config, 1))},
                       {"whole", to_string(EdgeSearchTally::verdict(config, 2))},
                       {"count", n}});
  }
  return out;
}

Json quality(const invariants::QualityStats& q) {
  return Json{{"tets", q.tets},
              {"min_radius_ratio", q.min_radius_ratio},
              {"mean_radius_ratio", q.mean_radius_ratio},
              {"min_dihedral_deg", q.min_dihedral_deg},
              {"mean_min_dihedral_deg", q.mean_min_dihedral_deg},
              {"radius_ratio_histogram", q.radius_ratio_histogram},
              {"min_dihedral_histogram", q.min_dihedral_histogram}};
}

Json table1_row(const stats::MeshStats& m) {
  const stats::PaperTable1Row& p = stats::kPaperTable1[static_cast<std::size_t>(m.mesh.number - 1)];
  Json row = {{"mesh", m.mesh.name},
              {"paper_mesh", m.mesh.number},
              {"scenario", m.mesh.scenario},
              {"tets", m.tets_before},
              {"cuts", m.cuts}};
  const Figure figures[] = {{"operations", static_cast<double>(m.table1.operations), static_cast<double>(p.operations), false},
                            {"removable_pct", m.table1.removable_pct, p.removable_pct},
                            {"vertex_pct", m.table1.vertex_pct, p.vertex_pct},
                            {"edge_pct", m.table1.edge_pct, p.edge_pct}};
  ours_paper_diff(row, figures);
  const std::pair<const char*, const stats::CellEstimate*> cells[] = {
      {"removable_pct", &m.table1_ci.removable}, {"vertex_pct", &m.table1_ci.vertex}, {"edge_pct", &m.table1_ci.edge}};
  intervals(row, cells);
  const stats::PaperTable1Counts& k = stats::kPaperTable1Counts[static_cast<std::size_t>(m.mesh.number - 1)];
  const std::tuple<const char*, const stats::CellEstimate*, const stats::PaperCount*> rates[] = {
      {"removable_pct", &m.table1_ci.removable, &k.removable},
      {"vertex_pct", &m.table1_ci.vertex, &k.vertex},
      {"edge_pct", &m.table1_ci.edge, &k.edge}};
  fisher(row, rates);
  sweeps(row, m);
  row["all_operations"] = m.table1.all_operations;  // interior tets included
  row["ok"] = m.ok;
  if (!m.ok) row["error"] = m.error;
  return row;
}

// Table 2's figures of one run with the paper's beside them: the keys of table2 and table2_wide.
std::array<Figure, 6> table2_figures(const stats::MeshStats& m) {
  const stats::PaperTable2Row& p = stats::kPaperTable2[static_cast<std::size_t>(m.mesh.number - 1)];
  const stats::Table2Row& o = m.table2;
  return {{{"vertex_unresolved_pct", o.vertex_unresolved_pct, p.vertex_unresolved_pct},
           {"vertex_cardinality", o.vertex_cardinality, p.vertex_cardinality},
           {"edge_unresolved_pct", o.edge_unresolved_pct, p.edge_unresolved_pct},
           {"edge_cardinality", o.edge_cardinality, p.edge_cardinality},
           {"global_unresolved_pct", o.global_unresolved_pct, p.global_unresolved_pct},
           {"global_cardinality_per_operation", o.global_cardinality, p.global_cardinality}}};
}

// Table 2's cells with their intervals and counts: the keys of table2 and table2_wide.
// `unresolved_key` names what the whole strategy left: combined_unresolved_pct, or the wide row's
// wide_unresolved_pct.
void table2_intervals(Json& row, const stats::MeshStats& m, const char* unresolved_key = "combined_unresolved_pct") {
  const stats::Table2Intervals& t = m.table2_ci;
  const std::pair<const char*, const stats::CellEstimate*> cells[] = {
      {"vertex_unresolved_pct", &t.vertex_unresolved},
      {"vertex_cardinality", &t.vertex_cardinality},
      {"edge_unresolved_pct", &t.edge_unresolved},
      {"edge_cardinality", &t.edge_cardinality},
      {"global_unresolved_pct", &t.global_unresolved},
      {"global_cardinality_per_operation", &t.global_cardinality},
      {"global_cardinality_per_selected", &t.global_cardinality_per_selected},
      {unresolved_key, &t.combined_unresolved}};
  intervals(row, cells);
  const stats::PaperTable2Counts& k = stats::kPaperTable2Counts[static_cast<std::size_t>(m.mesh.number - 1)];
  const std::tuple<const char*, const stats::CellEstimate*, const stats::PaperCount*> rates[] = {
      {"vertex_unresolved_pct", &t.vertex_unresolved, &k.vertex_unresolved},
      {"edge_unresolved_pct", &t.edge_unresolved, &k.edge_unresolved},
      {"global_unresolved_pct", &t.global_unresolved, &k.global_unresolved}};
  fisher(row, rates);
  sweeps(row, m);
}

Json table2_row(const stats::MeshStats& m) {
  Json row = {{"mesh", m.mesh.name}, {"paper_mesh", m.mesh.number}};
  ours_paper_diff(row, table2_figures(m));
  table2_intervals(row, m);
  row["edge_search"] = edge_search(m.removal.edge_search);
  // The paper's global cardinality reconstructs as tets removed per resolved operation (mesh 2:
  // 1.623 / 0.929 = 1.75, printed 1.8); per selected tet is ours, beside it.
  row["global_cardinality_per_selected"] = m.table2.global_cardinality_per_selected;
  row["paper_global_cardinality_is"] = "per_operation";
  row["combined_unresolved_pct"] = m.table2.combined_unresolved_pct;
  row["counts"] = removal_counts(m.removal);
  return row;
}

// Our wide search's Table 2 row: the same figures without the paper's (it has no such search).
Json table2_wide_row(const stats::MeshStats& m) {
  Json row = {{"mesh", m.mesh.name}, {"paper_mesh", m.mesh.number}};
  for (const Figure& f : table2_figures(m)) row[f.key] = f.ours;
  table2_intervals(row, m, "wide_unresolved_pct");
  row["global_cardinality_per_selected"] = m.table2.global_cardinality_per_selected;
  row["wide_unresolved_pct"] = m.table2.combined_unresolved_pct;
  row["ok"] = m.ok;
  if (!m.ok) row["error"] = m.error;
  row["counts"] = removal_counts(m.removal);
  return row;
}

Json strategy_row(const stats::StrategyRow& r, const std::string& mesh) {
  Json row = {{"name", r.name},
              {"strategy", to_string(r.strategy)},
              {"split", tetcut::to_string(r.split)},
              {"mesh", mesh},
              {"cuts", r.cuts},
              {"requests", r.requests},
              {"tets_created", r.tets_created},
              {"tets_removed", r.tets_removed},
              {"removed_per_request", r.removed_per_request},
              {"unresolved", r.unresolved},
              {"fallback_refused", r.fallback_refused},
              {"ok", r.ok}};
  if (!r.ok) row["error"] = r.error;
  row["tets_after"] = r.tets_after;  // at the stop when !ok
  row["worst_radius_ratio"] = r.worst_radius_ratio;
  row["worst_created_radius_ratio"] = r.worst_created_radius_ratio;
  row["worst_created_min_dihedral_deg"] = r.worst_created_min_dihedral_deg;
  row["created"] = quality(r.created);
  row["created_without_improvement"] = quality(r.created_without_improvement);
  row["ok_without_improvement"] = r.ok_without_improvement;
  row["mean_radius_ratio"] = r.mean_radius_ratio;
  row["p50_us"] = r.p50_us;
  row["p99_us"] = r.p99_us;
  return row;
}

Json quality_row(const stats::QualityRow& r) {
  Json row = {{"mesh", r.mesh.name},
              {"paper_mesh", r.mesh.number},
              {"strategy", r.strategy},
              {"input_worst_radius_ratio", r.input_worst_radius_ratio},
              {"goal", r.goal},
              {"goal_met", r.goal_met()},
              {"created", quality(r.created)},
              {"created_without_improvement", quality(r.created_without_improvement)},
              {"ok", r.ok},
              {"ok_without_improvement", r.ok_without_improvement}};
  if (!r.ok) row["error"] = r.error;
  if (!r.ok_without_improvement) row["error_without_improvement"] = r.error_without_improvement;
  return row;
}

Json resection(const stats::ResectionStats& resection) {
  const stats::CauteryRun& run = resection.run;
  return Json{{"scenario", resection.scenario},
              {"ok", run.result.ok},
              {"cuts", run.result.cuts.size()},
              {"tets_before", run.tets_before},
              {"tets_after", run.result.tets},
              {"hash", run.result.hash},
              {"counts", removal_counts(run.result.removal)},
              {"quality_before", quality(run.quality_before)},
              {"quality_after", quality(run.quality_after)},
              {"p50_us", percentile(run.cut_us, 0.5)},
              {"p99_us", percentile(run.cut_us, 0.99)},
              {"cut_us", run.cut_us}};
}

}  // namespace

Json stats_json(const stats::StatsReport& report) {
  Json table1 = Json::array(), table2 = Json::array(), table2_wide = Json::array(), strategies = Json::array();
  for (const stats::MeshStats& m : report.meshes) {
    table1.push_back(table1_row(m));
    table2.push_back(table2_row(m));
  }
  for (const stats::MeshStats& m : report.wide_meshes) table2_wide.push_back(table2_wide_row(m));
  // The same Tables with the paper's order (one by one, CutParams::order), for the ablation.
  Json table1_paper_order = Json::array(), table2_paper_order = Json::array();
  for (const stats::MeshStats& m : report.paper_order_meshes) {
    table1_paper_order.push_back(table1_row(m));
    table2_paper_order.push_back(table2_row(m));
  }
  // The paper's other readings: the revisit order, and 3.5 stopping at its first removable set.
  Json table1_revisit = Json::array(), table2_revisit = Json::array(), table1_first_set = Json::array(),
       table2_first_set = Json::array();
  for (const stats::MeshStats& m : report.revisit_meshes) {
    table1_revisit.push_back(table1_row(m));
    table2_revisit.push_back(table2_row(m));
  }
  for (const stats::MeshStats& m : report.first_set_meshes) {
    table1_first_set.push_back(table1_row(m));
    table2_first_set.push_back(table2_row(m));
  }
  for (const stats::StrategyRow& r : report.strategies) strategies.push_back(strategy_row(r, report.comparison_mesh));
  Json quality_rows = Json::array();
  for (const stats::QualityRow& r : report.quality) quality_rows.push_back(quality_row(r));
  Json out = {{"table1", std::move(table1)},
              {"table2", std::move(table2)},
              {"table2_wide", std::move(table2_wide)},
              {"table1_paper_order", std::move(table1_paper_order)},
              {"table2_paper_order", std::move(table2_paper_order)},
              {"table1_revisit", std::move(table1_revisit)},
              {"table2_revisit", std::move(table2_revisit)},
              {"table1_first_set", std::move(table1_first_set)},
              {"table2_first_set", std::move(table2_first_set)},
              {"improve", report.improve},
              {"sweeps", report.sweeps},
              {"strategies", std::move(strategies)},
              {"quality", std::move(quality_rows)}};
  if (report.resection) out["resection"] = resection(*report.resection);
  return out;
}

}  // namespace tetcut::cli
