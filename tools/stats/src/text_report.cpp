#include "tetcut/stats/text_report.hpp"

#include <cmath>
#include <algorithm>
#include <cstdio>
#include <string_view>
#include <vector>

#include "tetcut/percentile.hpp"
#include "tetcut/stats/fisher_exact.hpp"

namespace tetcut::stats {

std::string fixed(double value, int decimals) {
  if (std::isnan(value)) return "-";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, value);
  return buf;
}

std::string significant(double value, int digits) {
  if (std::isnan(value)) return "-";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits, value);
  return buf;
}

std::string difference(double ours, double paper, int decimals) {
  if (std::isnan(ours) || std::isnan(paper)) return "-";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%+.*f", decimals, ours - paper);
  return buf;
}

// "[91.6, 93.1]", or "-" when the interval has nothing to estimate from.
std::string interval_text(const CellEstimate& e, int decimals) {
  if (std::isnan(e.ci.lo)) return "-";
  char buf[96];
  std::snprintf(buf, sizeof buf, "[%.*f, %.*f]", decimals, e.ci.lo, decimals, e.ci.hi);
  return buf;
}
// "4127/4466": events of trials, or tets of sets.
std::string count_text(const CellEstimate& e) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%llu/%llu", static_cast<unsigned long long>(e.count),
                static_cast<unsigned long long>(e.of));
  return buf;
}

std::string fisher_text(const CellEstimate& ours, const PaperCount& paper) {
  const double p = fisher_vs_paper(ours, paper);
  return std::isnan(p) ? "-" : significant(p, 2) + (p < 0.05 ? "*" : "");
}

std::string created_worst(const invariants::QualityStats& q) {
  return q.tets == 0 ? "-" : significant(q.min_radius_ratio, 3);
}
std::string created_dihedral(const invariants::QualityStats& q) {
  return q.tets == 0 ? "-" : fixed(q.min_dihedral_deg, 1);
}

namespace {

// Columns padded to their widest cell; the first column left-aligned, the others right.
class TextTable {
 public:
  void row(std::vector<std::string> cells) { rows_.push_back(std::move(cells)); }
  std::string str() const {
    std::vector<std::size_t> width;
    for (const auto& r : rows_)
      for (std::size_t i = 0; i < r.size(); ++i) {
        if (width.size() <= i) width.push_back(0);
        width[i] = std::max(width[i], r[i].size());
      }
    std::string out;
    for (const auto& r : rows_) {
      std::string line;
      for (std::size_t i = 0; i < r.size(); ++i) {
        const std::string pad(width[i] - r[i].size(), ' ');
        line += i == 0 ? r[i] + pad : "  " + pad + r[i];
      }
      while (!line.empty() && line.back() == ' ') line.pop_back();
      out += line + "\n";
    }
    return out;
  }

 private:
  std::vector<std::vector<std::string>> rows_;
};


}  // namespace

namespace {

// Tables 1 and 2 of one set of runs (combined, in one removal order), ours beside the paper's.
std::string tables_1_and_2(const std::vector<MeshStats>& meshes, const std::string& order) {
  std::string out;
  out += "Table 1. Removing a tet on the surface (requested with a face on the surface, as the paper's\n"
         "title says): how often it is removable directly, or would make a vertex or an edge singular\n"
         "(paper 3.6, combined strategy, " + order + "), pooled over the seeded sweeps. ours, its 95 %\n"
         "interval, events/operations, the paper's, and p: Fisher's exact test (two-sided) of our counts\n"
         "against the paper's, rebuilt from its percentages (* p < 0.05); all ops: every distinct request,\n"
         "interior tets included\n\n";
  TextTable t1;
  t1.row({"mesh", "tets", "sweeps", "cuts", "operations", "paper", "all ops", "% removable", "95 %", "events", "paper",
          "p", "% vertex", "95 %", "events", "paper", "p", "% edge", "95 %", "events", "paper", "p"});
  for (const MeshStats& m : meshes) {
    const PaperTable1Row& p = kPaperTable1[static_cast<std::size_t>(m.mesh.number - 1)];
    const Table1Intervals& c = m.table1_ci;
    const PaperTable1Counts& k = kPaperTable1Counts[static_cast<std::size_t>(m.mesh.number - 1)];
    t1.row({mesh_label(m.mesh), std::to_string(m.tets_before), std::to_string(m.sweeps.size()), std::to_string(m.cuts),
            std::to_string(m.table1.operations), std::to_string(p.operations), std::to_string(m.table1.all_operations),
            fixed(c.removable.value, 1), interval_text(c.removable, 1), count_text(c.removable),
            fixed(p.removable_pct, 1), fisher_text(c.removable, k.removable), fixed(c.vertex.value, 1),
            interval_text(c.vertex, 1), count_text(c.vertex), fixed(p.vertex_pct, 1), fisher_text(c.vertex, k.vertex),
            fixed(c.edge.value, 1), interval_text(c.edge, 1), count_text(c.edge), fixed(p.edge_pct, 1),
            fisher_text(c.edge, k.edge)});
  }
  out += t1.str();

  out += "\nTable 2. The neighbour strategy (paper 3.5) inside the combined one (" + order + "): % of\n"
         "singularities it did not resolve and the mean size of the sets it removed, pooled over the sweeps:\n"
         "ours, its 95 % interval, the counts (unresolved/singularities, tets/sets), the paper's and, for a\n"
         "rate, Fisher's p against the paper's rebuilt counts (* p < 0.05; a mean size has no test: the paper\n"
         "gives no spread). The global cardinality is per operation resolved directly or by neighbours\n"
         "(card./op., the paper's column: its figures reconstruct so) and, beside it, per selected tet the\n"
         "sets took (card./sel.); the last column is what the combined strategy left in place (must be 0)\n\n";
  TextTable t2;
  t2.row({"mesh", "vertex % unres.", "95 %", "count", "paper", "p", "card.", "95 %", "count", "paper", "edge % unres.",
          "95 %", "count", "paper", "p", "card.", "95 %", "count", "paper", "global % unres.", "95 %", "paper", "p",
          "card./op.", "95 %", "paper", "card./sel.", "95 %", "combined % unres."});
  for (const MeshStats& m : meshes) {
    const PaperTable2Row& p = kPaperTable2[static_cast<std::size_t>(m.mesh.number - 1)];
    const Table2Intervals& c = m.table2_ci;
    const PaperTable2Counts& k = kPaperTable2Counts[static_cast<std::size_t>(m.mesh.number - 1)];
    t2.row({mesh_label(m.mesh), fixed(c.vertex_unresolved.value, 1), interval_text(c.vertex_unresolved, 1),
            count_text(c.vertex_unresolved), fixed(p.vertex_unresolved_pct, 1),
            fisher_text(c.vertex_unresolved, k.vertex_unresolved), fixed(c.vertex_cardinality.value, 1),
            interval_text(c.vertex_cardinality, 2), count_text(c.vertex_cardinality), fixed(p.vertex_cardinality, 1),
            fixed(c.edge_unresolved.value, 1), interval_text(c.edge_unresolved, 1), count_text(c.edge_unresolved),
            fixed(p.edge_unresolved_pct, 1), fisher_text(c.edge_unresolved, k.edge_unresolved),
            fixed(c.edge_cardinality.value, 1), interval_text(c.edge_cardinality, 2), count_text(c.edge_cardinality),
            fixed(p.edge_cardinality, 1), fixed(c.global_unresolved.value, 1), interval_text(c.global_unresolved, 1),
            fixed(p.global_unresolved_pct, 1), fisher_text(c.global_unresolved, k.global_unresolved),
            fixed(c.global_cardinality.value, 2), interval_text(c.global_cardinality, 2), fixed(p.global_cardinality, 1),
            fixed(c.global_cardinality_per_selected.value, 2),
            interval_text(c.global_cardinality_per_selected, 2),
            fixed(c.combined_unresolved.value, 1) + " (" + std::to_string(c.combined_unresolved.count) + ")"});
  }
  out += t2.str();
  out += "  95 %: rates, the Wilson score interval of the events pooled over the sweeps; mean sizes, the\n"
         "  percentile bootstrap of the pooled ratio over the sweeps (2000 resamples, seeded: docs/paper.md)\n";
  for (const MeshStats& m : meshes)
    if (!m.ok) out += "  " + mesh_label(m.mesh) + ": the scenario stopped early: " + m.error + "\n";
  return out;
}

// The configurations of the edge singularities 3.5 searched, one row per
// configuration met, most frequent first, per mesh and in all.
std::string edge_configurations(const std::vector<MeshStats>& meshes, const std::string& order) {
  std::vector<std::pair<std::uint64_t, int>> rows;  // (total, configuration)
  for (int c = 0; c < EdgeSearchTally::kConfigurations; ++c) {
    std::uint64_t total = 0;
    for (const MeshStats& m : meshes) total += m.removal.edge_search.counts[static_cast<std::size_t>(c)];
    if (total != 0) rows.emplace_back(total, c);
  }
  std::stable_sort(rows.begin(), rows.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  std::string out = "\nEdge singularities the paper's search (3.5) met, " + order +
                    " order, over the sweeps: T with the tets on one side of\n"
                    "the edge e (left, then right), then with all of them (whole), and where each set test failed\n\n";
  TextTable t;
  std::vector<std::string> header{"left", "right", "whole"};
  for (const MeshStats& m : meshes) header.push_back(m.mesh.name);
  header.push_back("all");
  t.row(header);
  for (const auto& [total, c] : rows) {
    const auto config = static_cast<std::uint16_t>(c);
    std::vector<std::string> cells{to_string(EdgeSearchTally::verdict(config, 0)),
                                   to_string(EdgeSearchTally::verdict(config, 1)),
                                   to_string(EdgeSearchTally::verdict(config, 2))};
    for (const MeshStats& m : meshes) cells.push_back(std::to_string(m.removal.edge_search.counts[static_cast<std::size_t>(c)]));
    cells.push_back(std::to_string(total));
    t.row(cells);
  }
  return out + t.str();
}

}  // namespace

std::string text_report(const StatsReport& report) {
  std::string out;
  out += std::string("Improvement pass: ") + (report.improve ? "on" : "off (--no-improve)") + "\n\n";
  out += tables_1_and_2(report.meshes, "direct-first order");
  out += "\nTable 2, our wider search (strategy wide, not the paper's: whole vertex shells and rounds of\n"
         "repairs, smallest set first) in place of 3.5 on the same scenarios: each figure of the wide\n"
         "search with its 95 % interval (and counts), then the paper's search's (3.5) from Table 2; the last\n"
         "column is what the wide strategy left in place (must be 0)\n\n";
  TextTable tw;
  tw.row({"mesh", "vertex % unres.", "95 %", "count", "3.5", "card.", "95 %", "3.5", "edge % unres.", "95 %", "count",
          "3.5", "card.", "95 %", "3.5", "card./op.", "95 %", "3.5", "wide % unres."});
  for (std::size_t i = 0; i < report.wide_meshes.size(); ++i) {
    const MeshStats& m = report.wide_meshes[i];
    const Table2Intervals& w = m.table2_ci;
    const Table2Row& o = report.meshes[i].table2;
    tw.row({mesh_label(m.mesh), fixed(w.vertex_unresolved.value, 1), interval_text(w.vertex_unresolved, 1),
            count_text(w.vertex_unresolved), fixed(o.vertex_unresolved_pct, 1), fixed(w.vertex_cardinality.value, 1),
            interval_text(w.vertex_cardinality, 2), fixed(o.vertex_cardinality, 1), fixed(w.edge_unresolved.value, 1),
            interval_text(w.edge_unresolved, 1), count_text(w.edge_unresolved), fixed(o.edge_unresolved_pct, 1),
            fixed(w.edge_cardinality.value, 1), interval_text(w.edge_cardinality, 2), fixed(o.edge_cardinality, 1),
            fixed(w.global_cardinality.value, 2), interval_text(w.global_cardinality, 2), fixed(o.global_cardinality, 2),
            fixed(w.combined_unresolved.value, 1)});
  }
  out += tw.str();
  for (const MeshStats& m : report.wide_meshes)
    if (!m.ok) out += "  " + mesh_label(m.mesh) + ": the wide run stopped early: " + m.error + "\n";

  if (!report.paper_order_meshes.empty()) {
    out += "\nThe same scenarios in the surface-first-by-id order (one reading of 3.3's \"removing one-by-one\n"
           "all tetrahedra in T_removal\", which gives no order: the first pending selected tet with a face on\n"
           "the surface, by id, removable or not), in place of ours (every directly removable tet first):\n\n";
    out += tables_1_and_2(report.paper_order_meshes, "surface-first-by-id order");
  }
  if (!report.revisit_meshes.empty()) {
    out += "\nThe same scenarios in the revisit order (another reading: surface first by id, but a tet neither\n"
           "removable nor taken by 3.5 is put off and met again after the next removal, counted once by its\n"
           "first verdict; only when every pending tet is put off does the first go to 3.7):\n\n";
    out += tables_1_and_2(report.revisit_meshes, "revisit order");
  }
  if (!report.first_set_meshes.empty()) {
    out += "\nThe same scenarios with 3.5 read the other way (neighbour_set first: it stops at the first\n"
           "removable candidate, shortest path first, instead of going on through further paths for a\n"
           "smaller one), in our order:\n\n";
    out += tables_1_and_2(report.first_set_meshes, "direct-first order, 3.5 stopping at its first removable set");
  }
  out += edge_configurations(report.meshes, "direct-first");
  if (!report.paper_order_meshes.empty()) out += edge_configurations(report.paper_order_meshes, "surface-first-by-id");

  out += "\nStrategies on the " + report.comparison_mesh +
         " scenario (split: the refinement loop's method, paper 3.2; quality: radius ratio of the mesh after)\n\n";
  TextTable s;
  s.row({"strategy", "cuts", "requests", "tets created", "tets removed", "removed/request", "unresolved",
         "fallback refused", "tets after",
         "worst created", "min dihedral", "no pass: worst", "min dihedral", "worst quality", "mean quality", "p50 us",
         "p99 us"});
  for (const StrategyRow& r : report.strategies)
    s.row({r.name, std::to_string(r.cuts), std::to_string(r.requests), std::to_string(r.tets_created),
           std::to_string(r.tets_removed), fixed(r.removed_per_request, 2), std::to_string(r.unresolved),
           std::to_string(r.fallback_refused), std::to_string(r.tets_after) + (r.ok ? "" : " *"), significant(r.worst_created_radius_ratio, 3),
           fixed(r.worst_created_min_dihedral_deg, 1), created_worst(r.created_without_improvement),
           created_dihedral(r.created_without_improvement), significant(r.worst_radius_ratio, 3),
           fixed(r.mean_radius_ratio, 3), fixed(r.p50_us, 1), fixed(r.p99_us, 1)});
  out += s.str();
  for (const StrategyRow& r : report.strategies)
    if (!r.ok) out += "  * " + r.name + ": stopped early (figures at the stop): " + r.error + "\n";
  out += "  worst created: the radius ratio of the worst tet the cuts created (min dihedral: its smallest\n"
         "  dihedral angle, degrees); no pass: the same scenario with the improvement pass off\n";

  out += "\nRadius ratio of the tets the cuts created on the " + report.comparison_mesh +
         " scenario, with the improvement pass: how many in each tenth\n\n";
  TextTable h;
  std::vector<std::string> header{"strategy"};
  for (std::size_t b = 0; b < invariants::kHistogramBins; ++b) header.push_back(fixed(0.1 * static_cast<double>(b), 1) + "-");
  h.row(header);
  for (const StrategyRow& r : report.strategies) {
    std::vector<std::string> cells{r.name};
    for (std::uint64_t n : r.created.radius_ratio_histogram) cells.push_back(std::to_string(n));
    h.row(cells);
  }
  out += h.str();
  out += "\nSmallest dihedral angle of the same tets, degrees: how many in each 5 degrees\n\n";
  TextTable d;
  std::vector<std::string> angles{"strategy"};
  for (std::size_t b = 0; b < invariants::kDihedralBins; ++b) angles.push_back(std::to_string(5 * b) + "-");
  d.row(angles);
  for (const StrategyRow& r : report.strategies) {
    std::vector<std::string> cells{r.name};
    for (std::uint64_t n : r.created.min_dihedral_histogram) cells.push_back(std::to_string(n));
    d.row(cells);
  }
  out += d.str();

  if (!report.quality.empty()) {
    out += "\nQuality of the tets the cuts created, per paper scenario and strategy, with the improvement\n"
           "pass and without it (radius ratio, smallest dihedral angle in degrees). Goal: the worst\n"
           "created radius ratio at least min(0.1, the input's worst), half that for basic\n\n";
    TextTable q;
    q.row({"mesh", "strategy", "input worst", "goal", "worst created", "min dihedral", "no pass: worst", "min dihedral",
           "goal met"});
    for (const QualityRow& r : report.quality)
      q.row({mesh_label(r.mesh), r.strategy, significant(r.input_worst_radius_ratio, 3), significant(r.goal, 3),
             created_worst(r.created) + (r.ok ? "" : " *"), created_dihedral(r.created),
             created_worst(r.created_without_improvement) + (r.ok_without_improvement ? "" : " *"),
             created_dihedral(r.created_without_improvement), r.goal_met() ? "yes" : "NO"});
    out += q.str();
    for (const QualityRow& r : report.quality) {
      if (!r.ok) out += "  * " + mesh_label(r.mesh) + ", " + r.strategy + ": stopped early: " + r.error + "\n";
      if (!r.ok_without_improvement)
        out += "  * " + mesh_label(r.mesh) + ", " + r.strategy + ", no pass: stopped early: " + r.error_without_improvement + "\n";
    }
  }

  if (report.resection) {
    const CauteryRun& run = report.resection->run;
    out += "\nResection of the bundled liver (" + report.resection->scenario + "): " +
           std::to_string(run.result.cuts.size()) + " cuts, " + std::to_string(run.tets_before) + " -> " +
           std::to_string(run.result.tets) + " tets, per cut p50 " + fixed(percentile(run.cut_us, 0.5), 1) +
           " us, p99 " + fixed(percentile(run.cut_us, 0.99), 1) + " us, radius ratio min " +
           fixed(run.quality_before.min_radius_ratio, 4) + " -> " + fixed(run.quality_after.min_radius_ratio, 4) +
           ", mean " + fixed(run.quality_before.mean_radius_ratio, 3) + " -> " +
           fixed(run.quality_after.mean_radius_ratio, 3) + "\n";
  }
  return out;
}

}  // namespace tetcut::stats
