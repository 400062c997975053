// `tetcut refine MESH (--uniform | --random-edges N --seed S | --ball X,Y,Z,R [--dref D] [--p P])
//  [--strategy templates|bisection] -o OUT [--report R.json]`: local refinement (paper 3.2) as a
// person runs it, with the full check of the result.
//
// A labelled mesh (RawMesh::labels) keeps its labels: the refinement runs inside one mesh
// transaction, whose commit derives the ChangeLog (mesh.hpp: the one record of what changed),
// and mechanics::TetLabels gives each child its parent's label from it, as after a cut. A mesh
// with one label everywhere (a Gmsh file's single volume, as every bundled mesh) or none is
// refined outside a transaction, as before: a transaction reuses no freed tet id, so a tracked
// mesh's tets come out numbered otherwise, the same mesh all the same (canonical hash).
#include <algorithm>
#include <optional>
#include <ostream>
#include <span>
#include <string>
#include <vector>

#include "command.hpp"
#include "command_parser.hpp"
#include "core/quality.hpp"
#include "core/random.hpp"
#include "cut/spatial_index.hpp"
#include "json_output.hpp"
#include "mesh_input.hpp"
#include "refine/refine.hpp"
#include "tetcut/canonical_hash.hpp"
#include "tetcut/change_log.hpp"
#include "tetcut/detail/local_tables.hpp"
#include "tetcut/invariants/check.hpp"
#include "tetcut/io.hpp"
#include "tetcut/mechanics/tet_labels.hpp"
#include "tetcut/mesh_builder.hpp"

namespace tetcut::cli {
namespace {

struct RefineArgs {
  std::optional<std::string> mesh, output, report, ball;
  bool uniform = false;
  std::optional<std::uint64_t> random_edges, seed, max_iterations;
  std::optional<double> dref, p;
  std::optional<SplitMethod> method;
};

void add_options(CLI::App& app, RefineArgs& a) {
  opt::text(app, "MESH", a.mesh, "the mesh file", "")->required();
  opt::flag(app, "--uniform", a.uniform, "split every edge once (8 times the tets)");
  opt::count(app, "--random-edges", a.random_edges, "split N edges picked at random (with --seed)");
  opt::count(app, "--seed", a.seed, "the seed of --random-edges", "S");
  opt::text(app, "--ball", a.ball, "the paper's loop around a tool of radius R", "X,Y,Z,R");
  opt::number(app, "--dref", a.dref, "with --ball: split edges longer than D (default 1.5 x tool diameter)", "D");
  opt::number(app, "--p", a.p, "with --ball: also split shell edges longer than P x |e| (default 1.5)", "P");
  opt::count(app, "--max-iterations", a.max_iterations, "with --ball: bound on the loop (default 8, at most 1000)");
  opt::split_method(app, "--strategy", a.method, "the 10 split configurations (default), or sequential bisection");
  opt::text(app, "-o", a.output, "the refined mesh", "OUT")->required();
  opt::text(app, "--report", a.report,
            "summary: iterations, edges_split, tets_created, tets_removed, tets, min_radius_ratio, converged, "
            "valid, hash",
            "R.json");
}

// "X,Y,Z,R" with R > 0.
std::optional<Tool> parse_ball(const std::string& text) {
  const auto comma = text.rfind(',');
  if (comma == std::string::npos) return std::nullopt;
  const auto centre = scenario::parse_vec3(text.substr(0, comma));
  const auto radius = scenario::parse_double(text.substr(comma + 1));
  if (!centre || !radius || *radius <= 0) return std::nullopt;
  return Tool::ball(*centre, *radius);
}

std::vector<Edge> all_edges(const TetMesh& mesh) {
  std::vector<Edge> edges;
  for (std::uint32_t t = 0; t < mesh.tet_capacity(); ++t)
    if (mesh.is_live(TetId{t}))
      for (int e = 0; e < 6; ++e) edges.push_back({mesh.vertex(TetId{t}, kEdgeVerts[e][0]), mesh.vertex(TetId{t}, kEdgeVerts[e][1])});
  return edges;
}

std::vector<Edge> random_edges(const TetMesh& mesh, std::uint64_t count, std::uint64_t seed) {
  SplitMix64 rng(seed);
  std::vector<TetId> live;
  for (std::uint32_t t = 0; t < mesh.tet_capacity(); ++t)
    if (mesh.is_live(TetId{t})) live.push_back(TetId{t});
  std::vector<Edge> edges;
  for (std::uint64_t i = 0; i < count && !live.empty(); ++i) {
    const TetId t = live[rng.below(static_cast<std::uint32_t>(live.size()))];
    const int e = static_cast<int>(rng.below(6));
    edges.push_back({mesh.vertex(t, kEdgeVerts[e][0]), mesh.vertex(t, kEdgeVerts[e][1])});
  }
  return edges;
}

}  // namespace

int cmd_refine(Args args, std::ostream& out, std::ostream& err) {
  RefineArgs a;
  CommandParser parser("refine",
                       "tetcut refine MESH (--uniform | --random-edges N --seed S | --ball X,Y,Z,R [--dref D] [--p P]) "
                       "[--strategy templates|bisection] -o OUT [--report R.json]",
                       "Refines a mesh locally by edge splitting (paper 3.2) and checks the result.\n",
                       "exit: 0, 1 the result violates an invariant or a split was refused, 2 bad input or usage");
  add_options(parser.app(), a);
  if (const auto code = parser.parse(args, out, err)) return *code;
  const int modes = int{a.uniform} + int{a.random_edges.has_value()} + int{a.ball.has_value()};
  if (modes != 1) return parser.usage_error("give exactly one of --uniform, --random-edges, --ball", err);
  std::optional<Tool> ball;
  if (a.ball && !(ball = parse_ball(*a.ball))) return parser.usage_error("--ball: expects X,Y,Z,R with R > 0", err);
  if (a.max_iterations && *a.max_iterations > 1000) return parser.usage_error("--max-iterations: at most 1000", err);
  const SplitMethod method = a.method.value_or(SplitMethod::kTemplates);
  const std::string& path = *a.mesh;

  const std::optional<RawMesh> raw = load_mesh(path, err);
  if (!raw) return 2;
  BuildResult built = build_mesh(*raw);
  if (!built.ok()) {
    err << "tetcut: " << path << ": not a valid manifold mesh: " << built.problems.front().message
        << " (" << built.problems.size() << " problem(s); see tetcut check)\n";
    return 2;
  }
  TetMesh& mesh = *built.mesh;
  const double volume = mesh.total_volume();
  const std::uint32_t tets_before = mesh.num_tets();

  const std::vector<std::uint32_t>& file_labels = raw->labels;
  const bool one_label = raw->labelled() && std::all_of(file_labels.begin(), file_labels.end(),
                                                        [&](std::uint32_t l) { return l == file_labels[0]; });
  const bool tracked = raw->labelled() && !one_label;
  mechanics::TetLabels labels;
  if (tracked) {
    labels = mechanics::TetLabels(mesh, file_labels);  // the builder keeps the file's tet order
    mesh.begin_transaction();
  }

  RefineReport report;
  if (ball) {
    RefineParams params;
    params.method = method;
    params.focus = *ball;
    params.d_ref = 1.5 * 2.0 * ball->radius;  // paper 3.2: D_ref = 1.5 x tool diameter
    if (a.dref) params.d_ref = *a.dref;
    if (a.p) params.p = *a.p;
    if (a.max_iterations) params.max_iterations = static_cast<std::uint32_t>(*a.max_iterations);
    if (const auto invalid = validate(params)) return parser.usage_error(*invalid, err);
    // The tool query of a person's one-off command: a scan is fine here, not on the cut path.
    std::vector<TetId> hit, region;
    scan_tets_meeting(mesh, *params.focus, hit);
    Refiner refiner;
    report = refiner.refine(mesh, hit, params, region);
  } else {
    std::vector<Edge> edges;
    edges = a.uniform ? all_edges(mesh) : random_edges(mesh, *a.random_edges, a.seed.value_or(0));
    EdgeSplitter splitter;
    std::vector<TetId> created;
    const SplitResult r = splitter.split(mesh, edges, method, &created);
    report.iterations = r.ok() ? 1 : 0;
    report.edges_split = r.edges_split;
    report.tets_created = r.tets_created;
    report.tets_removed = r.tets_removed;
    report.min_radius_ratio = min_radius_ratio(mesh, created);
    report.refusal = r.refusal;
  }
  if (report.refusal != SplitRefusal::kNone) {
    err << "tetcut refine: split refused: " << to_string(report.refusal) << "; nothing written\n";
    return 1;
  }
  if (tracked) {
    ChangeLog log;
    mesh.commit(&log);
    labels.apply(mesh, log);
  }

  invariants::CheckOptions check;
  check.expected_volume = volume;
  const invariants::CheckReport verdict = invariants::check_mesh(mesh.raw_view(), check);
  const std::string hash = hash_to_hex(canonical_hash(mesh));
  out << "refined: " << report.iterations << " iteration(s), " << report.edges_split << " edges split, "
      << report.tets_created << " tets created, " << tets_before << " -> " << mesh.num_tets()
      << " tets, worst new radius ratio " << report.min_radius_ratio << (report.converged ? "" : " (iteration bound hit)")
      << "\nhash " << hash << "\n";
  for (const invariants::Violation& v : verdict.violations)
    out << "violated " << invariants::id_string(v.id) << " (" << invariants::description(v.id) << "): " << v.detail << "\n";

  const Json summary = {{"iterations", report.iterations},
                        {"edges_split", report.edges_split},
                        {"tets_created", report.tets_created},
                        {"tets_removed", report.tets_removed},
                        {"tets", mesh.num_tets()},
                        {"min_radius_ratio", report.min_radius_ratio},
                        {"converged", report.converged},
                        {"valid", verdict.ok()},
                        {"hash", hash}};
  std::vector<std::uint32_t> spelt_out;
  if (one_label) spelt_out.assign(mesh.tet_capacity(), file_labels[0]);
  const std::span<const std::uint32_t> by_tet = tracked ? labels.by_tet() : std::span<const std::uint32_t>(spelt_out);
  const bool saved = save_mesh_and_report(*a.output, mesh, a.report, Json{{"summary", summary}}, err, by_tet);
  if (!saved) return 2;
  return verdict.ok() ? 0 : 1;
}

}  // namespace tetcut::cli
