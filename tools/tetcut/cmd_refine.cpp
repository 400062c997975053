// `tetcut refine MESH (--uniform | --random-edges N --seed S | --ball X,Y,Z,R [--dref D] [--p P])
//  [--strategy templates|bisection] -o OUT [--report R.json]`: local refinement (paper 3.2) as a
// person runs it, with the full check of the result.
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "args.hpp"
#include "command.hpp"
#include "json_writer.hpp"
#include "mesh_input.hpp"
#include "tetcut/canonical_hash.hpp"
#include "tetcut/invariants/check.hpp"
#include "tetcut/io.hpp"
#include "detail/local_tables.hpp"
#include "tetcut/mesh_builder.hpp"
#include "detail/random.hpp"
#include "detail/refine.hpp"

namespace tetcut::cli {
namespace {

constexpr OptionSpec kSpecs[] = {
    {"--uniform", false}, {"--random-edges", true}, {"--seed", true},     {"--ball", true},
    {"--dref", true},     {"--p", true},            {"--strategy", true}, {"-o", true},
    {"--report", true},   {"--max-iterations", true},
};

int usage_error(std::ostream& err, const std::string& message) {
  err << "tetcut refine: " << message << "\n"
      << "usage: tetcut refine MESH (--uniform | --random-edges N --seed S | --ball X,Y,Z,R [--dref D] [--p P])\n"
         "                          [--strategy templates|bisection] -o OUT [--report R.json]\n";
  return 2;
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
  const ArgParseResult parsed = parse_args(args, kSpecs);
  if (!parsed.ok()) return usage_error(err, parsed.error);
  const ParsedArgs& a = parsed.args;
  if (a.positionals.size() != 1) return usage_error(err, "expected exactly one MESH");
  const auto output = a.value("-o");
  if (!output) return usage_error(err, "missing -o OUT");
  const int modes = a.has("--uniform") + a.has("--random-edges") + a.has("--ball");
  if (modes != 1) return usage_error(err, "give exactly one of --uniform, --random-edges, --ball");

  SplitMethod method = SplitMethod::kTemplates;
  if (const auto s = a.value("--strategy")) {
    if (*s == "templates") method = SplitMethod::kTemplates;
    else if (*s == "bisection") method = SplitMethod::kBisection;
    else return usage_error(err, "--strategy must be templates or bisection, not '" + *s + "'");
  }

  const std::optional<RawMesh> raw = load_mesh(a.positionals[0], err);
  if (!raw) return 2;
  BuildResult built = build_mesh(*raw);
  if (!built.ok()) {
    err << "tetcut: " << a.positionals[0] << ": not a valid manifold mesh: " << built.problems.front().message
        << " (" << built.problems.size() << " problem(s); see tetcut check)\n";
    return 2;
  }
  TetMesh& mesh = *built.mesh;
  const double volume = mesh.total_volume();
  const std::uint32_t tets_before = mesh.num_tets();

  RefineReport report;
  if (a.has("--ball")) {
    // X,Y,Z,R: parse the first three as the centre, the last as the radius.
    const std::string text = *a.value("--ball");
    const auto comma = text.rfind(',');
    const auto centre = comma == std::string::npos ? std::nullopt : parse_vec3(text.substr(0, comma));
    const auto radius = comma == std::string::npos ? std::nullopt : parse_double(text.substr(comma + 1));
    if (!centre || !radius || *radius <= 0) return usage_error(err, "--ball expects X,Y,Z,R with R > 0");
    RefineParams params;
    params.method = method;
    params.focus = Ball{*centre, *radius};
    params.d_ref = 1.5 * 2.0 * *radius;  // paper 3.2: D_ref = 1.5 x tool diameter
    if (const auto d = a.value("--dref")) {
      const auto v = parse_double(*d);
      if (!v) return usage_error(err, "--dref expects a number");
      params.d_ref = *v;
    }
    if (const auto p = a.value("--p")) {
      const auto v = parse_double(*p);
      if (!v) return usage_error(err, "--p expects a number");
      params.p = *v;
    }
    if (const auto m = a.value("--max-iterations")) {
      const auto v = parse_uint(*m);
      if (!v || *v > 1000) return usage_error(err, "--max-iterations expects an integer up to 1000");
      params.max_iterations = static_cast<std::uint32_t>(*v);
    }
    if (const auto invalid = validate(params)) return usage_error(err, *invalid);
    // The tool query of a person's one-off command: a scan is fine here, not on the cut path.
    std::vector<TetId> hit, region;
    for (std::uint32_t t = 0; t < mesh.tet_capacity(); ++t) {
      if (!mesh.is_live(TetId{t})) continue;
      const auto v = mesh.tet(TetId{t});
      if (intersects(*params.focus, mesh.position(v[0]), mesh.position(v[1]), mesh.position(v[2]), mesh.position(v[3])))
        hit.push_back(TetId{t});
    }
    Refiner refiner;
    report = refiner.refine(mesh, hit, params, region);
  } else {
    std::vector<Edge> edges;
    if (a.has("--uniform")) {
      edges = all_edges(mesh);
    } else {
      const auto n = parse_uint(a.value("--random-edges").value_or(""));
      const auto seed = parse_uint(a.value("--seed").value_or("0"));
      if (!n || !seed) return usage_error(err, "--random-edges N --seed S expect integers");
      edges = random_edges(mesh, *n, *seed);
    }
    EdgeSplitter splitter;
    const SplitResult r = splitter.split(mesh, edges, method);
    report.iterations = r.ok() ? 1 : 0;
    report.edges_split = r.edges_split;
    report.tets_created = r.tets_created;
    report.tets_removed = r.tets_removed;
    report.min_radius_ratio = r.min_radius_ratio;
    report.refusal = r.refusal;
  }
  if (report.refusal != SplitRefusal::kNone) {
    err << "tetcut refine: split refused: " << to_string(report.refusal) << "; nothing written\n";
    return 1;
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

  const bool saved = save_mesh_and_report(*output, mesh, a.value("--report"), [&](JsonWriter& w) {
    w.key("summary");
    w.begin_object();
    w.field("iterations", report.iterations);
    w.field("edges_split", report.edges_split);
    w.field("tets_created", report.tets_created);
    w.field("tets_removed", report.tets_removed);
    w.field("tets", mesh.num_tets());
    w.field("min_radius_ratio", report.min_radius_ratio);
    w.field("converged", report.converged);
    w.field("valid", verdict.ok());
    w.field("hash", hash);
    w.end_object();
  }, err);
  if (!saved) return 2;
  return verdict.ok() ? 0 : 1;
}

}  // namespace tetcut::cli
