#include "tetcut/stats/html_report.hpp"

#include "tetcut/stats/fisher_exact.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "tetcut/percentile.hpp"
#include "tetcut/render/svg_writer.hpp"
#include "tetcut/scenario/cut_totals.hpp"
#include "tetcut/stats/fisher_exact.hpp"
#include "tetcut/stats/report_pictures.hpp"
#include "tetcut/stats/text_report.hpp"

namespace tetcut::stats {

namespace {

constexpr const char* kStyle = R"(
body { font-family: sans-serif; margin: 2em auto; max-width: 1100px; color: #222; }
h1 { font-size: 1.5em; } h2 { font-size: 1.2em; margin-top: 2em; }
table { border-collapse: collapse; margin: 1em 0; font-size: 0.85em; }
th, td { border: 1px solid #ccc; padding: 0.25em 0.5em; text-align: right; }
th { background: #f0f0f0; } td:first-child, th:first-child { text-align: left; }
td.paper { color: #666; } td.diff { color: #666; font-style: italic; }
td.ci, td.count { color: #444; font-size: 0.9em; white-space: nowrap; }
td.differs { font-weight: bold; background: #fde; }
.wide { overflow-x: auto; max-width: 100%; }
.figures { display: flex; flex-wrap: wrap; gap: 1em; }
.figures figure { margin: 0; } figcaption { font-size: 0.85em; color: #444; max-width: 480px; }
code { background: #f4f4f4; padding: 0.1em 0.3em; }
.warning { color: #a00; }
)";

std::string cell(const std::string& text, const char* cls = nullptr) {
  return cls ? "<td class=\"" + std::string(cls) + "\">" + render::xml_escape(text) + "</td>"
             : "<td>" + render::xml_escape(text) + "</td>";
}

// Ours, its 95 % interval and raw counts, the paper's, the difference: five cells; for a rate,
// a sixth: Fisher's exact p of ours against the paper's rebuilt count (fisher_exact.hpp), the
// paper's figure in class "differs" too when p < 0.05.
std::string figure_cells(const CellEstimate& ours, double paper, int decimals, const PaperCount* counts = nullptr) {
  const double p = counts ? fisher_vs_paper(ours, *counts) : std::nan("");
  const bool differs = !std::isnan(p) && p < 0.05;
  std::string h = cell(fixed(ours.value, decimals)) + cell(interval_text(ours, decimals + 1), "ci") +
                  cell(count_text(ours), "count") + cell(fixed(paper, decimals), differs ? "paper differs" : "paper") +
                  cell(difference(ours.value, paper, decimals), "diff");
  if (counts) h += cell(significant(p, 2), "p");
  return h;
}

constexpr const char* kFigureHeads = "<th>ours</th><th>95 %</th><th>count</th><th>paper</th><th>diff</th>";
constexpr const char* kRateHeads = "<th>ours</th><th>95 %</th><th>count</th><th>paper</th><th>diff</th><th>p</th>";

std::string table1_html(const std::vector<MeshStats>& meshes, const char* id) {
  std::string h = "<table id=\"" + std::string(id) +
                  "\"><tr><th rowspan=\"2\">mesh</th><th rowspan=\"2\">tets</th>"
                  "<th rowspan=\"2\">sweeps</th><th rowspan=\"2\">cuts</th><th colspan=\"2\">operations</th>"
                  "<th colspan=\"6\">% removable</th><th colspan=\"6\">% due to vertices</th>"
                  "<th colspan=\"6\">% due to edges</th></tr><tr><th>ours</th><th>paper</th>";
  for (int i = 0; i < 3; ++i) h += kRateHeads;
  h += "</tr>\n";
  for (const MeshStats& m : meshes) {
    const PaperTable1Row& p = kPaperTable1[static_cast<std::size_t>(m.mesh.number - 1)];
    const Table1Intervals& c = m.table1_ci;
    const PaperTable1Counts& k = kPaperTable1Counts[static_cast<std::size_t>(m.mesh.number - 1)];
    h += "<tr>" + cell(mesh_label(m.mesh)) + cell(std::to_string(m.tets_before)) + cell(std::to_string(m.sweeps.size())) +
         cell(std::to_string(m.cuts)) + cell(std::to_string(m.table1.operations)) +
         cell(std::to_string(p.operations), "paper") + figure_cells(c.removable, p.removable_pct, 1, &k.removable) +
         figure_cells(c.vertex, p.vertex_pct, 1, &k.vertex) + figure_cells(c.edge, p.edge_pct, 1, &k.edge) + "</tr>\n";
  }
  return h + "</table>\n";
}

std::string table2_html(const std::vector<MeshStats>& meshes, const char* id) {
  std::string h = "<table id=\"" + std::string(id) +
                  "\"><tr><th rowspan=\"2\">mesh</th>"
                  "<th colspan=\"11\">vertex singularities</th><th colspan=\"11\">edge singularities</th>"
                  "<th colspan=\"11\">global (card. per operation, the paper's column)</th>"
                  "<th colspan=\"2\">card. per selected tet</th><th rowspan=\"2\">combined:<br>% unresolved</th></tr><tr>";
  for (int i = 0; i < 3; ++i) h += std::string(kRateHeads) + kFigureHeads;
  h += "<th>ours</th><th>95 %</th></tr>\n";
  for (const MeshStats& m : meshes) {
    const PaperTable2Row& p = kPaperTable2[static_cast<std::size_t>(m.mesh.number - 1)];
    const Table2Intervals& c = m.table2_ci;
    const PaperTable2Counts& k = kPaperTable2Counts[static_cast<std::size_t>(m.mesh.number - 1)];
    const CellEstimate& sel = c.global_cardinality_per_selected;
    h += "<tr>" + cell(mesh_label(m.mesh)) + figure_cells(c.vertex_unresolved, p.vertex_unresolved_pct, 1, &k.vertex_unresolved) +
         figure_cells(c.vertex_cardinality, p.vertex_cardinality, 1) +
         figure_cells(c.edge_unresolved, p.edge_unresolved_pct, 1, &k.edge_unresolved) + figure_cells(c.edge_cardinality, p.edge_cardinality, 1) +
         figure_cells(c.global_unresolved, p.global_unresolved_pct, 1, &k.global_unresolved) +
         figure_cells(c.global_cardinality, p.global_cardinality, 2) + cell(fixed(sel.value, 2)) +
         cell(interval_text(sel, 2), "ci") +
         cell(fixed(c.combined_unresolved.value, 1)) + "</tr>\n";
  }
  h += "</table>\n";
  for (const MeshStats& m : meshes)
    if (!m.ok)
      h += "<p class=\"warning\">" + render::xml_escape(mesh_label(m.mesh) + ": the scenario stopped early: " + m.error) + "</p>\n";
  return h;
}

// The configurations of the edge singularities 3.5 searched.
std::string edge_configurations_html(const std::vector<MeshStats>& meshes, const char* id) {
  std::vector<std::pair<std::uint64_t, int>> rows;
  for (int c = 0; c < EdgeSearchTally::kConfigurations; ++c) {
    std::uint64_t total = 0;
    for (const MeshStats& m : meshes) total += m.removal.edge_search.counts[static_cast<std::size_t>(c)];
    if (total != 0) rows.emplace_back(total, c);
  }
  std::stable_sort(rows.begin(), rows.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  std::string h = "<table id=\"" + std::string(id) + "\"><tr><th>left</th><th>right</th><th>whole</th>";
  for (const MeshStats& m : meshes) h += "<th>" + render::xml_escape(m.mesh.name) + "</th>";
  h += "<th>all</th></tr>\n";
  for (const auto& [total, c] : rows) {
    const auto config = static_cast<std::uint16_t>(c);
    h += "<tr>";
    for (int k = 0; k < 3; ++k) h += cell(to_string(EdgeSearchTally::verdict(config, k)));
    for (const MeshStats& m : meshes) h += cell(std::to_string(m.removal.edge_search.counts[static_cast<std::size_t>(c)]));
    h += cell(std::to_string(total)) + "</tr>\n";
  }
  return h + "</table>\n";
}

// Our wide search beside the paper's (3.5), per mesh: its own rows, no paper figures.
std::string table2_wide_html(const StatsReport& report) {
  std::string h = "<table id=\"table2-wide\"><tr><th rowspan=\"2\">mesh</th>"
                  "<th colspan=\"6\">vertex singularities</th><th colspan=\"6\">edge singularities</th>"
                  "<th colspan=\"3\">global card. / operation</th><th rowspan=\"2\">wide:<br>% unresolved</th></tr><tr>";
  for (int i = 0; i < 2; ++i) h += "<th>% unres.</th><th>95 %</th><th>3.5</th><th>card.</th><th>95 %</th><th>3.5</th>";
  h += "<th>wide</th><th>95 %</th><th>3.5</th></tr>\n";
  for (std::size_t i = 0; i < report.wide_meshes.size(); ++i) {
    const MeshStats& m = report.wide_meshes[i];
    const Table2Intervals& w = m.table2_ci;
    const Table2Row& o = report.meshes[i].table2;
    auto ours = [](const CellEstimate& e, int decimals) {
      return cell(fixed(e.value, decimals)) + cell(interval_text(e, decimals + 1), "ci");
    };
    h += "<tr>" + cell(mesh_label(m.mesh)) + ours(w.vertex_unresolved, 1) +
         cell(fixed(o.vertex_unresolved_pct, 1), "paper") + ours(w.vertex_cardinality, 1) +
         cell(fixed(o.vertex_cardinality, 1), "paper") + ours(w.edge_unresolved, 1) +
         cell(fixed(o.edge_unresolved_pct, 1), "paper") + ours(w.edge_cardinality, 1) +
         cell(fixed(o.edge_cardinality, 1), "paper") + ours(w.global_cardinality, 2) +
         cell(fixed(o.global_cardinality, 2), "paper") + cell(fixed(w.combined_unresolved.value, 1)) + "</tr>\n";
  }
  h += "</table>\n";
  for (const MeshStats& m : report.wide_meshes)
    if (!m.ok)
      h += "<p class=\"warning\">" + render::xml_escape(mesh_label(m.mesh) + ": the wide run stopped early: " + m.error) + "</p>\n";
  return h;
}

std::string strategies_html(const StatsReport& report) {
  std::string h = "<table id=\"strategies\"><tr><th>strategy</th><th>cuts</th><th>requests</th><th>tets created</th>"
                  "<th>tets removed</th><th>removed / request</th><th>unresolved</th><th>tets after</th>"
                  "<th>worst created</th><th>min dihedral</th><th>no pass: worst created</th><th>min dihedral</th>"
                  "<th>worst radius ratio</th><th>mean radius ratio</th><th>p50 &micro;s</th>"
                  "<th>p99 &micro;s</th></tr>\n";
  for (const StrategyRow& r : report.strategies) {
    h += "<tr>" + cell(r.name) + cell(std::to_string(r.cuts)) + cell(std::to_string(r.requests)) +
         cell(std::to_string(r.tets_created)) + cell(std::to_string(r.tets_removed)) +
         cell(fixed(r.removed_per_request, 2)) + cell(std::to_string(r.unresolved)) +
         cell(std::to_string(r.tets_after) + (r.ok ? "" : " *")) + cell(significant(r.worst_created_radius_ratio, 3)) +
         cell(fixed(r.worst_created_min_dihedral_deg, 1)) + cell(created_worst(r.created_without_improvement)) +
         cell(created_dihedral(r.created_without_improvement)) + cell(significant(r.worst_radius_ratio, 3)) +
         cell(fixed(r.mean_radius_ratio, 3)) + cell(fixed(r.p50_us, 1)) + cell(fixed(r.p99_us, 1)) +
         "</tr>\n";
  }
  h += "</table>\n";
  for (const StrategyRow& r : report.strategies)
    if (!r.ok) h += "<p class=\"warning\">" + render::xml_escape("* " + r.name + ": stopped early (figures at the stop): " + r.error) + "</p>\n";
  h += "<table id=\"created-histogram\"><tr><th>strategy</th>";
  for (std::size_t b = 0; b < invariants::kHistogramBins; ++b)
    h += "<th>" + fixed(0.1 * static_cast<double>(b), 1) + "&ndash;" + fixed(0.1 * static_cast<double>(b + 1), 1) + "</th>";
  h += "</tr>\n";
  for (const StrategyRow& r : report.strategies) {
    h += "<tr>" + cell(r.name);
    for (std::uint64_t n : r.created.radius_ratio_histogram) h += cell(std::to_string(n));
    h += "</tr>\n";
  }
  return h + "</table>\n";
}

std::string quality_html(const StatsReport& report) {
  std::string h = "<table id=\"quality\"><tr><th>mesh</th><th>strategy</th><th>input worst</th><th>goal</th>"
                  "<th>worst created</th><th>min dihedral</th><th>no pass: worst created</th><th>min dihedral</th>"
                  "<th>goal met</th></tr>\n";
  for (const QualityRow& r : report.quality)
    h += "<tr>" + cell(mesh_label(r.mesh)) + cell(r.strategy) + cell(significant(r.input_worst_radius_ratio, 3)) +
         cell(significant(r.goal, 3)) + cell(created_worst(r.created) + (r.ok ? "" : " *")) +
         cell(created_dihedral(r.created)) +
         cell(created_worst(r.created_without_improvement) + (r.ok_without_improvement ? "" : " *")) +
         cell(created_dihedral(r.created_without_improvement)) + cell(r.goal_met() ? "yes" : "no") + "</tr>\n";
  h += "</table>\n";
  for (const QualityRow& r : report.quality) {
    if (!r.ok) h += "<p class=\"warning\">" + render::xml_escape("* " + mesh_label(r.mesh) + ", " + r.strategy + ": stopped early: " + r.error) + "</p>\n";
    if (!r.ok_without_improvement)
      h += "<p class=\"warning\">" +
           render::xml_escape("* " + mesh_label(r.mesh) + ", " + r.strategy + ", no pass: stopped early: " + r.error_without_improvement) +
           "</p>\n";
  }
  return h;
}

// What the resection's cuts did beyond their counts: the tissue rule's figures, the improvement
// pass's operations and the pieces detached (scenario::cut_totals, as `tetcut run` prints them).
std::string cut_account_html(const std::vector<scenario::CutRecord>& cuts) {
  const scenario::CutTotals t = scenario::cut_totals(cuts);
  auto row = [](const std::string& what, const std::string& value) {
    return "<tr><td>" + render::xml_escape(what) + "</td><td>" + render::xml_escape(value) + "</td></tr>\n";
  };
  std::string refusals = std::to_string(t.refused);
  for (int k = 1; k < kCutRefusals; ++k)
    if (t.refusals[k]) refusals += " (" + std::to_string(t.refusals[k]) + " " + to_string(static_cast<CutRefusal>(k)) + ")";
  return "<table>\n<tr><th>what the cuts did</th><th></th></tr>\n" + row("cuts refused", refusals) +
         row("tets left in the tool", std::to_string(t.left_in_tool) + " by " + std::to_string(t.cuts_leaving_tissue) + " cuts") +
         row("volume left in the tool per cut (p50, p99)",
             significant(percentile(t.volume_left, 0.5), 3) + ", " + significant(percentile(t.volume_left, 0.99), 3)) +
         row("volume removed; beyond the tool", significant(t.volume_removed, 4) + "; " + significant(t.volume_removed_beyond_tool, 4)) +
         row("tets removed beyond the cut's reach", std::to_string(t.removed_beyond_reach)) +
         row("improvement: flips, collapses, moves, insertions, slivers removed",
             std::to_string(t.flips) + ", " + std::to_string(t.collapses) + ", " + std::to_string(t.moves) + ", " +
                 std::to_string(t.insertions) + ", " + std::to_string(t.removed_by_improvement)) +
         row("pieces detached; removed as debris (tets, volume)",
             std::to_string(t.fragments) + " by " + std::to_string(t.cuts_detaching) + " cuts; " +
                 std::to_string(t.debris_pieces) + " (" + std::to_string(t.debris_tets) + ", " +
                 significant(t.debris_volume, 4) + ")") +
         "</table>\n";
}

std::string resection_html(const ResectionStats& resection) {
  const CauteryRun& run = resection.run;
  std::string h = "<h2>The liver resection</h2>\n<p>" +
                  render::xml_escape(resection.scenario + ": " + std::to_string(run.result.cuts.size()) + " cuts, " +
                              std::to_string(run.tets_before) + " tets before, " + std::to_string(run.result.tets) +
                              " after; " + std::to_string(run.result.removal.requested) +
                              " removal operations, " + std::to_string(run.result.removal.unresolved) +
                              " unresolved.") +
                  "</p>\n" + cut_account_html(run.result.cuts) + "<div class=\"figures\">\n";
  for (const Picture& p : resection_pictures(resection))
    h += "<figure>" + p.svg + "<figcaption>" + render::xml_escape(p.caption) + "</figcaption></figure>\n";
  return h + "</div>\n";
}

}  // namespace

std::string html_report(const StatsReport& report, const std::string& command) {
  std::string h = "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
                  "<title>tetcut: does it match the paper?</title><style>";
  h += kStyle;
  h += "</style></head><body>\n<h1>tetcut: does it match the paper?</h1>\n"
       "<p>Forest, Delingette and Ayache (2002), section 3.6, measured how often removing a surface tet "
       "would make a vertex or an edge singular (Table 1) and how well removing neighbours resolves it "
       "(Table 2). Here are our figures on five meshes of the same kinds, each cut by the cautery "
       "scenario in <code>corpus/scenarios/paper/</code>, with the paper's beside them (grey) and the "
       "difference (italic). Reproduce with <code>" +
       render::xml_escape(command) + "</code>.</p>\n";
  const std::string sweeps = std::to_string(report.sweeps);
  h += "<p>Every cell pools " + sweeps +
       " runs of its mesh's scenario, the tool path shifted by a seeded offset each time (the first as "
       "written), and gives our estimate, its 95 % interval and the raw counts it rests on: the Wilson score "
       "interval of the pooled events for a rate, the percentile bootstrap of the pooled ratio over the runs "
       "(2000 resamples, seeded) for a mean set size. Beside a rate, p is Fisher's exact test (two-sided) of "
       "our pooled counts against the paper's, rebuilt from its percentages: it counts the paper's few "
       "events as well as ours; a paper figure with p &lt; 0.05 is in bold on pink (the sweeps cut one mesh "
       "along nearby paths, so our events are not independent and p is too small where they cluster). "
       "A mean set size has no test: the paper gives no spread.</p>\n";
  h += "<h2>Table 1. Singularities met when removing a surface tet (our order: direct first)</h2>\n<div class=\"wide\">" + table1_html(report.meshes, "table1") + "</div>\n";
  h += "<h2>Table 2. The neighbour strategy (our order: direct first)</h2>\n"
       "<p>% of singularities the neighbour search (paper 3.5) did not resolve, and the mean number of "
       "tets it removed when it did; global: over all operations, direct removals counting 1, the "
       "cardinality per operation resolved (the paper's column: its figures reconstruct so) and per "
       "selected tet taken (ours). Our runs use the combined strategy (3.7), whose optimized refinement "
       "and fallback resolved the rest: its own unresolved share is the last column.</p>\n<div class=\"wide\">" + table2_html(report.meshes, "table2") + "</div>\n";
  if (!report.paper_order_meshes.empty()) {
    h += "<h2>Table 1 in the surface-first-by-id order</h2>\n"
         "<p>The same scenarios with one reading of the paper's removal order (3.3: \"removing one-by-one all "
         "tetrahedra in T_removal\", which gives no order: the first pending selected tet with a face on the "
         "surface, by id, removable or not) in place of ours (every directly removable tet first).</p>\n<div class=\"wide\">" + table1_html(report.paper_order_meshes, "table1-paper-order") + "</div>\n";
    h += std::string("<h2>Table 2 in the surface-first-by-id order</h2>\n<div class=\"wide\">") + table2_html(report.paper_order_meshes, "table2-paper-order") + "</div>\n";
  }
  h += "<h2>Table 2, our wider search</h2>\n"
       "<p>The same scenarios with the strategy <code>wide</code> (not the paper's: whole vertex shells and "
       "rounds of repairs, smallest set first) in place of the paper's search; the paper's search (3.5, "
       "from Table 2) in grey beside it, each of ours with its 95 % interval. The last column is what the "
       "wide strategy left in place.</p>\n<div class=\"wide\">" +
       table2_wide_html(report) + "</div>\n";
  h += "<h2>Strategies on the " + render::xml_escape(report.comparison_mesh) + " scenario</h2>\n"
       "<p>basic (3.4), neighbours (3.5), combined (3.7), and our wider search (not the paper's); the "
       "refinement loop (3.2) splitting with the ten templates or by sequential bisection. Quality: radius "
       "ratio of the tets the cuts created (and its smallest dihedral angle), with the improvement pass and "
       "without it (no pass), and of the mesh after the scenario; below, how the created tets' radius ratios "
       "spread. A run stops when its mesh grows past twice its size.</p>\n" +
       strategies_html(report);
  if (!report.quality.empty())
    h += "<h2>Quality of the tets the cuts created</h2>\n"
         "<p>Per paper scenario and strategy, with the improvement pass that ends each cut (flips, collapses, "
         "smoothing of the cut's own vertices) and without it: the worst radius ratio and the smallest dihedral "
         "angle (degrees) of the tets the cuts created. Goal: the worst at least min(0.1, the input's worst), half "
         "that for basic. A run marked * stopped early (the growth guard, or a cut refused because the pass could "
         "not meet the floor).</p>\n" +
         quality_html(report);
  if (report.resection) h += resection_html(*report.resection);
  h += "<h2>Where 3.5 fails at an edge singularity</h2>\n"
       "<p>Each edge singularity the paper's search met (over every run, our order, then the paper's): T "
       "with the tets on one side of the singular edge e (left, then right), then with all of them "
       "(whole), and what each set test said: removable, not tested (skipped: a removable set no larger "
       "was found first), or the vertex or edge at which the set would be singular.</p>\n" +
       edge_configurations_html(report.meshes, "edge-search");
  if (!report.paper_order_meshes.empty())
    h += edge_configurations_html(report.paper_order_meshes, "edge-search-paper-order");
  // The paper's other readings last, below the pictures (which the report's Chromium test finds
  // by their place on the page).
  if (!report.revisit_meshes.empty()) {
    h += "<h2>Tables 1 and 2 in the revisit order</h2>\n"
         "<p>Another reading of the paper's order: surface first by id, but a tet neither removable nor "
         "taken by the neighbour search is put off and met again after the next removal, counted once by "
         "its first verdict.</p>\n<div class=\"wide\">" + table1_html(report.revisit_meshes, "table1-revisit") +
         table2_html(report.revisit_meshes, "table2-revisit") + "</div>\n";
  }
  if (!report.first_set_meshes.empty()) {
    h += "<h2>Tables 1 and 2 with 3.5's first removable set</h2>\n"
         "<p>The other reading of the neighbour search: it stops at the first removable candidate instead of "
         "going on for a smaller one (our order).</p>\n<div class=\"wide\">" +
         table1_html(report.first_set_meshes, "table1-first-set") + table2_html(report.first_set_meshes, "table2-first-set") +
         "</div>\n";
  }
  h += "</body></html>\n";
  return h;
}

}  // namespace tetcut::stats
