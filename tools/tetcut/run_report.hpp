// What `tetcut run` and `tetcut cut` (a scenario of one sweep) say about a scenario run: the
// summary lines on stdout, the final mesh (--out) and the JSON report (--report): a `cuts` array
// (one record per cut: its time in microseconds per stage and its counts, every CutReport field,
// and for a refused cut its refusal and failure) and a `summary` with cuts, first_us, p50_us,
// p90_us, p99_us, max_us, tets_removed, tets_created, unresolved, refused and refusals (by
// reason), left_in_tool and cuts_leaving_tissue, volume_left_in_tool (p50, p99, max per cut),
// volume_removed, tets_removed_beyond_tool, volume_removed_beyond_tool (and its p50, p99, max
// per cut), tets_removed_beyond_reach, tets_removed_by_improvement, improvement (flips,
// collapses, moves, insertions), min_radius_ratio, valid and hash, then the detached pieces:
// fragments, cuts_detaching, debris_pieces_removed, debris_tets_removed, debris_volume_removed
// and fragment_searches_bounded (a cut's record has its pieces too, after its other keys).
// docs/usage.md says what each means.
#pragma once

#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "json_output.hpp"
#include "tetcut/scenario/scenario.hpp"

namespace tetcut::cli {

Json cut_report_json(const std::vector<scenario::CutRecord>& cuts, const std::string& hash, bool valid);

struct RunOutputs {
  std::optional<std::string> mesh_path;    // --out
  std::optional<std::string> report_path;  // --report
};

// Prints the summary of `r` (run on `mesh`, which holds the final mesh or the mesh where the run
// stopped) and, when the run passed or a check failed (exit 0 or 1), writes the outputs. The
// failure itself is the caller's to print. Returns the exit code: r's, or 2 if an output could
// not be written.
int report_run(const scenario::RunResult& r, const TetMesh& mesh, const RunOutputs& outputs, std::ostream& out,
               std::ostream& err);

}  // namespace tetcut::cli
