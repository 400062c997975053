#include "tetcut/stats/cautery_run.hpp"

#include "tetcut/io.hpp"
#include "tetcut/mesh_builder.hpp"

namespace tetcut::stats {

namespace {

// The mesh the scenario starts from (its first `mesh` line), for the "before" figures.
std::optional<TetMesh> initial_mesh(const scenario::Scenario& s, std::string& error) {
  for (const scenario::Op& op : s.ops) {
    if (op.kind != scenario::OpKind::kMesh) continue;
    const std::string path = op.text.front() == '/' ? op.text : s.base_dir + "/" + op.text;
    ReadResult read = read_mesh(path);
    if (!read.mesh) {
      error = read.error ? read.error->message() : "cannot read " + path;
      return std::nullopt;
    }
    BuildResult built = build_mesh(*read.mesh);
    if (!built.ok()) {
      error = s.name + ":" + std::to_string(op.line) + ": " + path + ": not a valid manifold mesh: " +
              built.problems.front().message;
      return std::nullopt;
    }
    return std::move(*built.mesh);
  }
  error = s.name + ": no mesh line";
  return std::nullopt;
}

}  // namespace

CauteryResult run_cautery(const std::string& scenario_path, const CauteryOptions& options, const std::string& name) {
  CauteryResult out;
  scenario::ParseResult parsed = scenario::parse_file(scenario_path, name);
  if (!parsed.scenario) {
    out.error = parsed.error;
    return out;
  }
  // No offset leaves the scenario as written, bit for bit (adding 0.0 would turn a -0.0 into 0.0).
  const bool offset = options.offset.x != 0.0 || options.offset.y != 0.0 || options.offset.z != 0.0;
  for (scenario::Op& op : parsed.scenario->ops)
    if (offset &&
        (op.kind == scenario::OpKind::kCut || op.kind == scenario::OpKind::kSweep || op.kind == scenario::OpKind::kRemove)) {
      op.a = op.a + options.offset;
      op.b = op.b + options.offset;
    }
  std::optional<TetMesh> before = initial_mesh(*parsed.scenario, out.error);
  if (!before) return out;

  CauteryRun run;
  run.scenario = parsed.scenario->name;
  run.strategy = options.strategy;
  run.split = options.split;
  run.tets_before = before->num_tets();
  run.quality_before = invariants::check_mesh(before->raw_view()).quality;

  CutParams params;
  params.strategy = options.strategy;
  params.split_method = options.split;
  params.order = options.order;
  params.neighbour_set = options.neighbour_set;
  params.improve = options.improve;
  params.refinement = options.refinement;
  scenario::RunOptions run_options;
  run_options.check = options.check_every_cut ? scenario::CheckMode::kEvery : scenario::CheckMode::kEnd;
  run_options.initial_params = params;
  run_options.max_tets = static_cast<std::uint64_t>(options.max_growth) * run.tets_before;
  TetMesh after;
  run.result = scenario::run(*parsed.scenario, run_options, &after);
  if (run.result.exit_code == 2) {  // unusable input, not a finding
    out.error = run.result.error;
    return out;
  }
  run.cut_us.reserve(run.result.cuts.size());
  for (const scenario::CutRecord& c : run.result.cuts) run.cut_us.push_back(c.report.time.total_us);
  // A run that stopped early leaves its mesh as it was then: "after" is at the stop.
  run.quality_after = invariants::check_mesh(after.raw_view()).quality;
  if (options.keep_meshes) {
    run.mesh_before = std::move(before);
    run.mesh_after = std::move(after);
  }
  out.run = std::move(run);
  return out;
}

}  // namespace tetcut::stats
