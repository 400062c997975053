#include "cut_report_json.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "json_writer.hpp"

namespace tetcut::cli {

double percentile_us(const std::vector<scenario::CutRecord>& cuts, double q) {
  if (cuts.empty()) return 0.0;
  std::vector<double> t;
  t.reserve(cuts.size());
  for (const auto& c : cuts) t.push_back(c.report.time.total_us);
  std::sort(t.begin(), t.end());
  const auto rank = static_cast<std::size_t>(std::ceil(q * static_cast<double>(t.size())));
  return t[std::min(t.size() - 1, rank == 0 ? 0 : rank - 1)];
}

std::string cut_report_json(const std::vector<scenario::CutRecord>& cuts, const std::string& hash, bool valid) {
  std::ostringstream out;
  JsonWriter w(out);
  std::uint64_t removed = 0, created = 0, unresolved = 0;
  double worst = 1.0;
  w.begin_object();
  w.key("cuts");
  w.begin_array();
  for (std::size_t i = 0; i < cuts.size(); ++i) {
    const CutReport& r = cuts[i].report;
    removed += r.tets_removed;
    created += r.tets_created;
    unresolved += r.unresolved;
    worst = std::min(worst, r.min_radius_ratio);
    w.begin_object();
    w.field("index", static_cast<std::uint64_t>(i));
    w.field("line", cuts[i].line);
    w.key("centre");
    w.begin_array();
    w.value(cuts[i].centre.x);
    w.value(cuts[i].centre.y);
    w.value(cuts[i].centre.z);
    w.end_array();
    w.field("ok", r.ok);
    w.field("time_us", r.time.total_us);
    w.field("locate_us", r.time.locate_us);
    w.field("refine_us", r.time.refine_us);
    w.field("select_us", r.time.select_us);
    w.field("remove_us", r.time.remove_us);
    w.field("tets_hit", r.tets_hit);
    w.field("refine_iterations", r.refine_iterations);
    w.field("edges_split", r.edges_split);
    w.field("requested", r.requested);
    w.field("requests", r.requests);
    w.field("tets_removed", r.tets_removed);
    w.field("tets_created", r.tets_created);
    w.field("direct", r.direct);
    w.field("vertex_singularities", r.vertex_singularities);
    w.field("edge_singularities", r.edge_singularities);
    w.field("resolved_by_neighbours", r.resolved_by_neighbours);
    w.field("resolved_by_refinement", r.resolved_by_refinement);
    w.field("resolved_by_fallback", r.resolved_by_fallback);
    w.field("unresolved", r.unresolved);
    w.field("min_radius_ratio", r.min_radius_ratio);
    w.end_object();
  }
  w.end_array();
  w.key("summary");
  w.begin_object();
  w.field("cuts", static_cast<std::uint64_t>(cuts.size()));
  // The first cut on its own (what a simulator feels when the tool first touches the tissue);
  // the percentiles are over every cut, the first included.
  w.field("first_us", cuts.empty() ? 0.0 : cuts.front().report.time.total_us);
  w.field("p50_us", percentile_us(cuts, 0.50));
  w.field("p90_us", percentile_us(cuts, 0.90));
  w.field("p99_us", percentile_us(cuts, 0.99));
  w.field("max_us", percentile_us(cuts, 1.0));
  w.field("tets_removed", removed);
  w.field("tets_created", created);
  w.field("unresolved", unresolved);
  w.field("min_radius_ratio", worst);
  w.field("valid", valid);
  w.field("hash", hash);
  w.end_object();
  w.end_object();
  w.finish();
  return out.str();
}

}  // namespace tetcut::cli
