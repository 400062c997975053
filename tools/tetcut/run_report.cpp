#include "run_report.hpp"

#include <algorithm>
#include <array>
#include <ostream>

#include "tetcut/canonical_hash.hpp"
#include "tetcut/io.hpp"
#include "tetcut/percentile.hpp"
#include "tetcut/scenario/cut_totals.hpp"

namespace tetcut::cli {

namespace {

// Each cut's total time in microseconds, in scenario order: what the percentiles are taken of.
std::vector<double> cut_times_us(const std::vector<scenario::CutRecord>& cuts) {
  std::vector<double> t;
  t.reserve(cuts.size());
  for (const auto& c : cuts) t.push_back(c.report.time.total_us);
  return t;
}

// The pieces a cut detached, each its size and place: {"tets": count, "volume", "centroid",
// "removed"}. Not its tets' ids, which are the Cutter's to give (Cutter::last_fragments(),
// Python's report.detached).
Json pieces_json(const std::vector<scenario::DetachedPiece>& pieces) {
  Json out = Json::array();
  for (const scenario::DetachedPiece& p : pieces)
    out.push_back(Json{{"tets", p.tets},
                       {"volume", p.volume},
                       {"centroid", {p.centroid.x, p.centroid.y, p.centroid.z}},
                       {"removed", p.removed}});
  return out;
}

// A cut's tool and counts. "centre" is the ball's centre or the capsule's first end; a capsule
// (Cutter::cut_segment) adds its other end, "end", after it, and a ball's record is as it was.
// The pieces the cut detached come last (after a refused cut's refusal and failure), so that the
// keys before them keep their places: "pieces" only when it detached any.
Json cut_record_json(std::size_t index, const scenario::CutRecord& c) {
  const CutReport& r = c.report;
  Json record{{"index", index}, {"line", c.line}, {"centre", {c.centre.x, c.centre.y, c.centre.z}}};
  if (c.end) record["end"] = {c.end->x, c.end->y, c.end->z};
  record.update(Json{{"ok", r.ok},
              {"time_us", r.time.total_us},
              {"locate_us", r.time.locate_us},
              {"refine_us", r.time.refine_us},
              {"select_us", r.time.select_us},
              {"remove_us", r.time.remove_us},
              {"improve_us", r.time.improve_us},
              {"finish_us", r.time.finish_us},
              {"tets_hit", r.tets_hit},
              {"refine_iterations", r.refine_iterations},
              {"edges_split", r.edges_split},
              {"tets_refined", r.tets_refined},
              {"requested", r.requested},
              {"requests", r.requests},
              {"tets_removed", r.tets_removed},
              {"tets_created", r.tets_created},
              {"direct", r.direct},
              {"vertex_singularities", r.vertex_singularities},
              {"edge_singularities", r.edge_singularities},
              {"resolved_by_neighbours", r.resolved_by_neighbours},
              {"resolved_by_refinement", r.resolved_by_refinement},
              {"resolved_by_fallback", r.resolved_by_fallback},
              {"unresolved", r.unresolved},
              {"stopped_by_budget", r.stopped_by_budget},
              {"uncuttable_in_tool", r.uncuttable_in_tool},
              {"kept_pieces_requested", r.kept_pieces_requested},
              {"left_in_tool", r.left_in_tool},
              {"volume_left_in_tool", r.volume_left_in_tool},
              {"volume_removed", r.volume_removed},
              {"tets_removed_beyond_tool", r.tets_removed_beyond_tool},
              {"volume_removed_beyond_tool", r.volume_removed_beyond_tool},
              {"tets_removed_beyond_reach", r.tets_removed_beyond_reach},
              {"min_radius_ratio", r.min_radius_ratio},
              {"min_radius_ratio_before_improvement", r.min_radius_ratio_before_improvement},
              {"min_dihedral_deg", r.min_dihedral_deg},
              {"min_dihedral_deg_before_improvement", r.min_dihedral_deg_before_improvement},
              {"quality_floor", r.quality_floor},
              {"dihedral_floor_deg", r.dihedral_floor_deg},
              {"min_dihedral_held_deg", r.min_dihedral_held_deg},
              {"angle_retries", r.angle_retries},
              {"improvement_flips", r.improvement_flips},
              {"improvement_collapses", r.improvement_collapses},
              {"improvement_moves", r.improvement_moves},
              {"vertices_moved", r.vertices_moved},
              {"mesh_rule_retries", r.mesh_rule_retries},
              {"improvement_insertions", r.improvement_insertions},
              {"tets_removed_by_improvement", r.tets_removed_by_improvement},
              {"d_ref", r.d_ref},
              {"refinement", to_string(r.refinement)},
              {"retries", r.retries}});
  if (!r.ok) {
    record["refusal"] = to_string(r.refusal);
    record["failure"] = r.failure;
  }
  record.update(Json{{"pieces_us", r.time.pieces_us},
                     {"fragments", r.fragments},
                     {"fragment_tets_visited", r.fragment_tets_visited},
                     {"fragment_search_bounded", r.fragment_search_bounded},
                     {"debris_pieces_removed", r.debris_pieces_removed},
                     {"debris_tets_removed", r.debris_tets_removed},
                     {"debris_volume_removed", r.debris_volume_removed}});
  if (!c.pieces.empty()) record["pieces"] = pieces_json(c.pieces);
  return record;
}

Json spread(const std::vector<double>& values) {
  return Json{{"p50", percentile(values, 0.5)}, {"p99", percentile(values, 0.99)}, {"max", percentile(values, 1.0)}};
}

}  // namespace

Json cut_report_json(const std::vector<scenario::CutRecord>& cuts, const std::string& hash, bool valid) {
  Json records = Json::array();
  for (std::size_t i = 0; i < cuts.size(); ++i) records.push_back(cut_record_json(i, cuts[i]));
  const scenario::CutTotals t = scenario::cut_totals(cuts);
  const std::vector<double> times = cut_times_us(cuts);
  // The first cut on its own (what a simulator feels when the tool first touches the tissue);
  // the percentiles are over every cut, the first included.
  Json refusals = Json::object();
  for (int k = 1; k < kCutRefusals; ++k)
    if (t.refusals[k]) refusals[to_string(static_cast<CutRefusal>(k))] = t.refusals[k];
  Json summary = {{"cuts", cuts.size()},
                  {"first_us", cuts.empty() ? 0.0 : cuts.front().report.time.total_us},
                  {"p50_us", percentile(times, 0.50)},
                  {"p90_us", percentile(times, 0.90)},
                  {"p99_us", percentile(times, 0.99)},
                  {"max_us", percentile(times, 1.0)},
                  {"tets_removed", t.removed},
                  {"tets_created", t.created},
                  {"unresolved", t.unresolved},
                  {"refused", t.refused},
                  {"refusals", std::move(refusals)},
                  {"left_in_tool", t.left_in_tool},
                  {"cuts_leaving_tissue", t.cuts_leaving_tissue},
                  {"volume_left_in_tool", spread(t.volume_left)},
                  {"volume_removed", t.volume_removed},
                  {"tets_removed_beyond_tool", t.removed_beyond_tool},
                  {"volume_removed_beyond_tool", t.volume_removed_beyond_tool},
                  {"volume_removed_beyond_tool_per_cut", spread(t.volume_beyond)},
                  {"tets_removed_beyond_reach", t.removed_beyond_reach},
                  {"tets_removed_by_improvement", t.removed_by_improvement},
                  {"improvement", {{"flips", t.flips}, {"collapses", t.collapses}, {"moves", t.moves},
                                   {"insertions", t.insertions}, {"vertices_moved", t.vertices_moved},
                                   {"mesh_rule_retries", t.mesh_rule_retries}}},
                  {"min_radius_ratio", t.worst_created},
                  {"valid", valid},
                  {"hash", hash},
                  {"fragments", t.fragments},
                  {"cuts_detaching", t.cuts_detaching},
                  {"debris_pieces_removed", t.debris_pieces},
                  {"debris_tets_removed", t.debris_tets},
                  {"debris_volume_removed", t.debris_volume},
                  {"fragment_searches_bounded", t.fragment_searches_bounded}};
  return Json{{"cuts", std::move(records)}, {"summary", std::move(summary)}};
}

int report_run(const scenario::RunResult& r, const TetMesh& mesh, const RunOutputs& outputs, std::ostream& out,
               std::ostream& err) {
  const scenario::CutTotals t = scenario::cut_totals(r.cuts);
  out << r.cuts.size() << " cuts: " << r.removals << " tets removed, " << t.created << " created, " << r.unresolved
      << " unresolved, " << mesh.num_tets() << " tets left\n";
  if (!r.cuts.empty()) {
    out << "tissue: " << t.left_in_tool << " tets left in the tool by " << t.cuts_leaving_tissue
        << " cuts; volume left in the tool per cut p50 " << percentile(t.volume_left, 0.5) << ", p99 "
        << percentile(t.volume_left, 0.99) << "; removed " << t.volume_removed << ", of which " << t.volume_removed_beyond_tool
        << " beyond the tool (per cut p99 " << percentile(t.volume_beyond, 0.99) << "), " << t.removed_beyond_reach
        << " tets beyond its reach\n";
    out << "improvement: " << t.flips << " flips, " << t.collapses << " collapses, " << t.moves << " moves (" << t.vertices_moved
        << " of vertices there before), " << t.insertions << " insertions, " << t.removed_by_improvement
        << " slivers removed, " << t.mesh_rule_retries << " passes made again under the mesh rule; " << t.refused
        << " cuts refused";
    for (int k = 1; k < kCutRefusals; ++k)
      if (t.refusals[k]) out << " (" << t.refusals[k] << " " << to_string(static_cast<CutRefusal>(k)) << ")";
    out << "\n";
    out << "pieces: " << t.fragments << " detached by " << t.cuts_detaching << " cuts, " << t.debris_pieces
        << " removed as debris (" << t.debris_tets << " tets, volume " << t.debris_volume << ")";
    if (t.fragment_searches_bounded) out << "; " << t.fragment_searches_bounded << " searches bounded";
    out << "\n";
  }
  if (!r.cuts.empty()) {
    const std::vector<double> times = cut_times_us(r.cuts);
    out << "per cut (all cuts): p50 " << percentile(times, 0.5) << " us, p90 " << percentile(times, 0.9) << " us, p99 "
        << percentile(times, 0.99) << " us, max " << percentile(times, 1.0) << " us; first cut " << times.front()
        << " us\n";
  }
  if (r.exit_code == 2) return r.exit_code;  // unusable input: nothing worth writing
  // A stopped run leaves no hash in `r`: the mesh where it stopped has one all the same.
  const std::string hash = r.hash.empty() ? hash_to_hex(canonical_hash(mesh)) : r.hash;
  out << "hash " << hash << "\n";
  if (outputs.mesh_path) {
    // With the file's labels carried through the run (RunResult::labels), when it had any.
    const WriteResult w = r.labels.empty() ? write_mesh(*outputs.mesh_path, mesh)
                                           : write_mesh(*outputs.mesh_path, mesh, r.labels);
    if (!w.ok) {
      err << "tetcut: " << w.error << "\n";
      return 2;
    }
  }
  if (outputs.report_path && !write_json_file(*outputs.report_path, cut_report_json(r.cuts, hash, r.ok), err)) return 2;
  return r.exit_code;
}

}  // namespace tetcut::cli
