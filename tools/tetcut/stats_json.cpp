#include "stats_json.hpp"

#include <initializer_list>
#include <sstream>

#include "json_writer.hpp"

namespace tetcut::cli {

namespace {

void removal_counts(JsonWriter& w, const RemovalReport& r) {
  w.key("counts");
  w.begin_object();
  w.field("requested", r.requested);
  w.field("direct", r.direct);
  w.field("vertex_singularities", r.vertex_singularities);
  w.field("edge_singularities", r.edge_singularities);
  w.field("vertex_resolved_by_neighbours", r.vertex_resolved_by_neighbours);
  w.field("edge_resolved_by_neighbours", r.edge_resolved_by_neighbours);
  w.field("vertex_neighbour_set_tets", r.vertex_neighbour_set_tets);
  w.field("edge_neighbour_set_tets", r.edge_neighbour_set_tets);
  w.field("resolved_by_refinement", r.resolved_by_refinement);
  w.field("resolved_by_optimized_refinement", r.resolved_by_optimized_refinement);
  w.field("resolved_by_fallback", r.resolved_by_fallback);
  w.field("selected_in_sets", r.selected_in_sets);
  w.field("attempts_undone", r.attempts_undone);
  w.field("unresolved", r.unresolved);
  w.field("tets_removed", r.tets_removed);
  w.field("tets_created", r.tets_created);
  w.end_object();
}

// One figure of a table row: ours, the paper's, and whether the difference is meaningful.
struct Figure {
  const char* key;
  double ours, paper;
  bool diff = true;
};

// Our figures as fields, then objects "paper" (the paper's) and "diff" (ours minus the paper's).
void ours_paper_diff(JsonWriter& w, std::initializer_list<Figure> figures) {
  for (const Figure& f : figures) {
    if (f.diff) w.field(f.key, f.ours);
    else w.field(f.key, static_cast<std::uint64_t>(f.ours));
  }
  w.key("paper");
  w.begin_object();
  for (const Figure& f : figures) {
    if (f.diff) w.field(f.key, f.paper);
    else w.field(f.key, static_cast<std::uint64_t>(f.paper));
  }
  w.end_object();
  w.key("diff");
  w.begin_object();
  for (const Figure& f : figures)
    if (f.diff) w.field(f.key, f.ours - f.paper);
  w.end_object();
}

void quality(JsonWriter& w, const char* key, const invariants::QualityStats& q) {
  w.key(key);
  w.begin_object();
  w.field("tets", q.tets);
  w.field("min_radius_ratio", q.min_radius_ratio);
  w.field("mean_radius_ratio", q.mean_radius_ratio);
  w.key("radius_ratio_histogram");
  w.begin_array();
  for (std::uint64_t n : q.radius_ratio_histogram) w.value(n);
  w.end_array();
  w.end_object();
}

}  // namespace

std::string stats_json(const stats::StatsReport& report) {
  std::ostringstream out;
  JsonWriter w(out);
  w.begin_object();

  w.key("table1");
  w.begin_array();
  for (const stats::MeshStats& m : report.meshes) {
    const stats::PaperTable1Row& p = stats::kPaperTable1[static_cast<std::size_t>(m.mesh.number - 1)];
    w.begin_object();
    w.field("mesh", m.mesh.name);
    w.field("paper_mesh", m.mesh.number);
    w.field("scenario", m.mesh.scenario);
    w.field("tets", m.tets_before);
    w.field("cuts", m.cuts);
    ours_paper_diff(w, {{"operations", static_cast<double>(m.table1.operations), static_cast<double>(p.operations), false},
                        {"removable_pct", m.table1.removable_pct, p.removable_pct},
                        {"vertex_pct", m.table1.vertex_pct, p.vertex_pct},
                        {"edge_pct", m.table1.edge_pct, p.edge_pct}});
    w.field("ok", m.ok);
    if (!m.ok) w.field("error", m.error);
    w.end_object();
  }
  w.end_array();

  w.key("table2");
  w.begin_array();
  for (const stats::MeshStats& m : report.meshes) {
    const stats::PaperTable2Row& p = stats::kPaperTable2[static_cast<std::size_t>(m.mesh.number - 1)];
    const stats::Table2Row& o = m.table2;
    w.begin_object();
    w.field("mesh", m.mesh.name);
    w.field("paper_mesh", m.mesh.number);
    ours_paper_diff(w, {{"vertex_unresolved_pct", o.vertex_unresolved_pct, p.vertex_unresolved_pct},
                        {"vertex_cardinality", o.vertex_cardinality, p.vertex_cardinality},
                        {"edge_unresolved_pct", o.edge_unresolved_pct, p.edge_unresolved_pct},
                        {"edge_cardinality", o.edge_cardinality, p.edge_cardinality},
                        {"global_unresolved_pct", o.global_unresolved_pct, p.global_unresolved_pct},
                        {"global_cardinality_per_selected", o.global_cardinality, p.global_cardinality}});
    // The paper's global cardinality is per selected tet (3.6: "removed when a single
    // tetrahedron should be removed"); per request is ours, for comparison.
    w.field("global_cardinality_per_request", o.global_cardinality_per_request);
    w.field("paper_global_cardinality_is", "per_selected");
    w.field("combined_unresolved_pct", o.combined_unresolved_pct);
    removal_counts(w, m.removal);
    w.end_object();
  }
  w.end_array();

  w.key("strategies");
  w.begin_array();
  for (const stats::StrategyRow& r : report.strategies) {
    w.begin_object();
    w.field("name", r.name);
    w.field("strategy", to_string(r.strategy));
    w.field("split", r.split == SplitMethod::kTemplates ? "templates" : "bisection");
    w.field("mesh", report.comparison_mesh);
    w.field("cuts", r.cuts);
    w.field("requests", r.requests);
    w.field("tets_created", r.tets_created);
    w.field("tets_removed", r.tets_removed);
    w.field("removed_per_request", r.removed_per_request);
    w.field("unresolved", r.unresolved);
    w.field("ok", r.ok);
    if (!r.ok) w.field("error", r.error);
    w.field("tets_after", r.tets_after);  // at the stop when !ok
    w.field("worst_radius_ratio", r.worst_radius_ratio);
    w.field("worst_created_radius_ratio", r.worst_created_radius_ratio);
    w.field("mean_radius_ratio", r.mean_radius_ratio);
    w.field("p50_us", r.p50_us);
    w.field("p99_us", r.p99_us);
    w.end_object();
  }
  w.end_array();

  if (report.resection) {
    const stats::CauteryRun& run = report.resection->run;
    w.key("resection");
    w.begin_object();
    w.field("scenario", report.resection->scenario);
    w.field("ok", run.result.ok);
    w.field("cuts", static_cast<std::uint64_t>(run.result.cuts.size()));
    w.field("tets_before", run.tets_before);
    w.field("tets_after", run.result.tets);
    w.field("hash", run.result.hash);
    removal_counts(w, run.result.removal);
    quality(w, "quality_before", run.quality_before);
    quality(w, "quality_after", run.quality_after);
    w.field("p50_us", stats::percentile(run.cut_us, 0.5));
    w.field("p99_us", stats::percentile(run.cut_us, 0.99));
    w.key("cut_us");
    w.begin_array();
    for (double us : run.cut_us) w.value(us);
    w.end_array();
    w.end_object();
  }
  w.end_object();
  w.finish();
  return out.str();
}

}  // namespace tetcut::cli
