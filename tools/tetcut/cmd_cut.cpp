// `tetcut cut MESH --diameter D --from X,Y,Z --to X,Y,Z --step S [--swept] [...]`: a cautery
// sweep, one cut every S along the segment, as the paper's electric lancet (3.6); with --swept
// the cut points are joined by capsules (Cutter::cut_segment), one cut from each to the next.
//
// Not a second runner: the sweep is the scenario `mesh MESH` + `sweep FROM TO STEP` with the
// command line's parameters, run by the scenario runner that `tetcut run` uses, and reported by
// the same code (run_report.hpp). `tetcut run` on the equivalent scenario file gives the same
// mesh, hash and report.
#include <cstdio>
#include <ostream>
#include <span>

#include "command.hpp"
#include "command_parser.hpp"
#include "run_report.hpp"
#include "tetcut/io.hpp"
#include "tetcut/scenario/scenario.hpp"

namespace tetcut::cli {

namespace {

// At most as many cuts as a scenario file's sweep may hold.
constexpr double kMaxCuts = 100000;

struct CutArgs {
  std::optional<std::string> mesh, frames;
  std::optional<double> diameter, step, dref_factor, p, debris_volume;
  opt::Improvement improvement;
  bool swept = false, ids_along_curve = false;
  std::optional<Vec3> from, to;
  std::optional<std::uint64_t> depth, max_tets_created;
  std::optional<RemovalStrategy> strategy;
  std::optional<RemovalOrder> order;
  std::optional<NeighbourSetChoice> neighbour_set;
  std::optional<SplitMethod> split;
  std::optional<RefinementRule> refinement;
  std::optional<scenario::CheckMode> check;
  std::vector<std::uint32_t> uncuttable_labels;
  RunOutputs outputs;
};

void add_options(CLI::App& app, CutArgs& a) {
  opt::text(app, "MESH", a.mesh, "the mesh file", "")->required();
  opt::number(app, "--diameter", a.diameter, "the tool's diameter", "D")->required();
  opt::point(app, "--from", a.from, "where the sweep starts")->required();
  opt::point(app, "--to", a.to, "where it ends (included when a whole number of steps away)")->required();
  opt::number(app, "--step", a.step, "the distance between two cuts (> 0)", "S")->required();
  opt::flag(app, "--swept", a.swept,
            "join the cut points by capsules: one cut from each point to the next by every point within the "
            "tool's radius of that segment, so no tissue stays between two points whatever the step (a sweep of "
            "one point is one ball)");
  opt::flag(app, "--ids-along-curve", a.ids_along_curve,
            "number the mesh's tets and vertices along a space-filling curve before the first cut (the scenario "
            "line `compact` after `mesh`), so that tets near each other in space are near each other in memory; "
            "without it the ids are the file's order");
  opt::strategy(app, "--strategy", a.strategy, "removal strategy (default combined)");
  opt::order(app, "--order", a.order,
             "which selected tet a cut requests next (default direct-first; docs/paper.md: the paper's three "
             "readings)");
  opt::neighbour_set(app, "--neighbour-set", a.neighbour_set,
                     "which removable set the neighbour search (paper 3.5) keeps: the smallest (default) or the first "
                     "it finds");
  opt::split_method(app, "--split", a.split, "how the paper's refinement splits edges (default templates)");
  opt::refinement(app, a.refinement,
                  "which tets the refinement splits: the paper's loop (3.2; the default) or longest-edge "
                  "bisection graded to the tool");
  opt::number(app, "--dref-factor", a.dref_factor, "D_ref = F x diameter (paper 3.2; default 1.5)", "F");
  opt::number(app, "--p", a.p, "shell edge ratio of the refinement loop (paper 3.2; default 1.5)", "P");
  opt::count(app, "--depth", a.depth, "neighbour search depth (paper 3.5; default 10, at most 64)");
  opt::count(app, "--max-tets-created", a.max_tets_created,
             "the per-cut tet budget: net tets a cut may make (default 20000); a cut past it is refused", "N");
  opt::improvement(app, a.improvement, "cut");
  opt::debris_volume(app, a.debris_volume);
  opt::labels(app, "--keep-label", a.uncuttable_labels,
              "tets with this label (the mesh file's) are tissue no cut takes, as the paper's Fig. 7 keeps the "
              "portal vein (repeatable)");
  opt::check_mode(app, a.check, "the local check after every cut (default), the full one at the end, or none");
  opt::text(app, "--out", a.outputs.mesh_path, "the final mesh", "M");
  opt::text(app, "--report", a.outputs.report_path,
            "`cuts` (time in microseconds and counts per cut, the pieces it detached) and `summary` (cuts, "
            "first_us, p50_us, p90_us, p99_us, max_us over all cuts, tets_removed, tets_created, unresolved, "
            "min_radius_ratio, valid, hash, fragments, debris_pieces_removed)",
            "R.json");
  opt::text(app, "--frames", a.frames, "a .vtu snapshot after every cut, for ParaView (DIR must exist)", "DIR");
}

// The command line's parameters as the scenario runner's initial ones; a message if refused.
std::optional<std::string> cut_params(const CutArgs& a, CutParams& params) {
  params.tool_diameter = *a.diameter;
  if (a.strategy) params.strategy = *a.strategy;
  if (a.order) params.order = *a.order;
  if (a.neighbour_set) params.neighbour_set = *a.neighbour_set;
  if (a.split) params.split_method = *a.split;
  if (a.refinement) params.refinement = *a.refinement;
  if (a.dref_factor) params.d_ref_factor = *a.dref_factor;
  if (a.p) params.p = *a.p;
  opt::improvement_params(a.improvement, params);
  if (a.debris_volume) params.debris_volume = *a.debris_volume;
  if (a.depth) {
    if (*a.depth > 64) return "--depth: at most 64";
    params.search_depth = static_cast<std::uint32_t>(*a.depth);
  }
  if (a.max_tets_created) {
    if (*a.max_tets_created < 1 || *a.max_tets_created > 0xFFFFFFFFull) return "--max-tets-created: a positive integer";
    params.max_tets_created = static_cast<std::uint32_t>(*a.max_tets_created);
  }
  if (*a.step <= 0) return "--step: must be positive";
  if (norm(*a.to - *a.from) / *a.step > kMaxCuts) return "more than 100000 cuts: increase --step";
  return validate(params);
}

}  // namespace

int cmd_cut(Args args, std::ostream& out, std::ostream& err) {
  CutArgs a;
  CommandParser parser(
      "cut",
      "tetcut cut MESH --diameter D --from X,Y,Z --to X,Y,Z --step S [--swept] [--ids-along-curve] [--strategy S] [--order O] "
      "[--neighbour-set smallest|first] [--split M] [--max-tets-created N] "
      "[--refinement auto|paper|graded] [--no-improve] [--quality-floor F] [--min-dihedral DEG] [--debris-volume V] "
      "[--keep-label L ...] "
      "[--check every|end|none] [--out M] [--report R.json] [--frames DIR]",
      "A cautery sweep: one cut every STEP from --from to --to with a tool of the given diameter,\n"
      "each cut refined then removed without breaking the manifold (paper 3.1-3.7). --swept joins\n"
      "the cut points by capsules, one cut from each point to the next. The sweep is the scenario\n"
      "`mesh MESH` + `sweep FROM TO STEP` (`... STEP swept`), run as `tetcut run` runs it.\n",
      "exit: 0, 1 an invariant broke or a cut was refused, 2 bad input or usage");
  add_options(parser.app(), a);
  if (const auto code = parser.parse(args, out, err)) return *code;
  scenario::RunOptions options;
  options.initial_params.emplace();
  if (const auto bad = cut_params(a, *options.initial_params)) return parser.usage_error(*bad, err);
  options.check = a.check.value_or(scenario::CheckMode::kEvery);
  options.uncuttable_labels = a.uncuttable_labels;
  if (a.frames) {
    options.after_cut = [dir = *a.frames](const TetMesh& mesh, std::size_t k,
                                          std::span<const std::uint32_t> labels) -> std::optional<std::string> {
      char name[32];
      std::snprintf(name, sizeof name, "/frame_%05zu.vtu", k);
      // With the file's labels as they are after this cut, as the final mesh gets them.
      const WriteResult w = labels.empty() ? write_mesh(dir + name, mesh) : write_mesh(dir + name, mesh, labels);
      return w.ok ? std::nullopt : std::optional<std::string>(w.error);
    };
  }

  scenario::Scenario sweep{"tetcut cut", ".", {}};
  sweep.ops.push_back({.kind = scenario::OpKind::kMesh, .line = 1, .text = *a.mesh});
  if (a.ids_along_curve) sweep.ops.push_back({.kind = scenario::OpKind::kCompact, .line = 1});
  sweep.ops.push_back(
      {.kind = scenario::OpKind::kSweep, .line = 2, .a = *a.from, .b = *a.to, .step = *a.step, .swept = a.swept});
  TetMesh mesh;
  const scenario::RunResult r = scenario::run(sweep, options, &mesh);
  if (!r.ok) {
    if (r.failed_line == 1) err << "tetcut: " << r.reason << "\n";  // the mesh: the reader's FILE:LINE: reason
    else if (r.failed_line == 2) err << "tetcut cut: cut " << r.cuts.size() - 1 << ": " << r.reason << "\n";
    else err << "tetcut cut: " << r.reason << "\n";
  }
  return report_run(r, mesh, a.outputs, out, err);
}

}  // namespace tetcut::cli
