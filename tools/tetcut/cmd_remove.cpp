// `tetcut remove MESH (--at X,Y,Z ... | --random N|all --seed S) [--strategy basic|neighbours|combined|wide]
//  [--check every|end|none] -o OUT [--report R.json]`: removes tetrahedra without breaking the
// manifold (paper 3.3-3.7) and prints the paper's statistics (Tables 1 and 2).
//
// --at takes one or more points ("X,Y,Z", several separated by ';' or given as further
// arguments after the mesh): each removes the tet containing it at the time of its turn, found
// by Cutter::tet_containing, the engine's one rule for "the tet at a point" (the closed tet by
// the exact orientation predicate, the lowest id on a shared face: the rule scenarios use), and
// removed by Cutter::remove, as a scenario's `remove X,Y,Z` is.
// --random requests tets on the current boundary one at a time, as a cautery meets them; `all`
// goes on until the mesh is empty (or only unresolved tets remain, with --strategy neighbours),
// or 20 requests per initial tet: basic and combined refine, and a cautery that keeps meeting
// the small tets they make can keep the mesh alive (`wide` hollows a mesh out). Both go through
// Cutter::remove, as an integrator's code would; what a request exposed is read from its
// ChangeLog (RequestExposure below).
// --check every runs the local checker after every request and the full one at the end; end
// (default) only the full one; none skips it. Exit 0, 1 if an invariant broke, 2 bad input.
#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "command.hpp"
#include "command_parser.hpp"
#include "tetcut/boundary_tet_picker.hpp"
#include "json_output.hpp"
#include "mesh_input.hpp"
#include "remove/removal.hpp"
#include "tetcut/canonical_hash.hpp"
#include "tetcut/change_log.hpp"
#include "tetcut/cut.hpp"
#include "tetcut/invariants/check.hpp"
#include "tetcut/io.hpp"
#include "tetcut/mechanics/tet_labels.hpp"
#include "tetcut/mesh_builder.hpp"

namespace tetcut::cli {

namespace {

// "X,Y,Z;X,Y,Z" or "X,Y,Z X,Y,Z"; nothing if a point is malformed.
std::optional<std::vector<Vec3>> parse_points(std::string_view text) {
  std::vector<Vec3> points;
  std::size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && (text[i] == ';' || text[i] == ' ')) ++i;
    if (i >= text.size()) break;
    std::size_t j = i;
    while (j < text.size() && text[j] != ';' && text[j] != ' ') ++j;
    const auto p = scenario::parse_vec3(text.substr(i, j - i));
    if (!p) return std::nullopt;
    points.push_back(*p);
    i = j;
  }
  return points;
}

struct RemoveArgs {
  std::optional<std::string> mesh, output, report, random;
  std::optional<std::vector<Vec3>> at;
  std::vector<std::string> more_points;
  std::optional<std::uint64_t> seed;
  std::optional<RemovalStrategy> strategy;
  std::optional<NeighbourSetChoice> neighbour_set;
  std::optional<scenario::CheckMode> check;
  opt::Improvement improvement;
};

void add_options(CLI::App& app, RemoveArgs& a) {
  opt::text(app, "MESH", a.mesh, "the mesh file", "")->required();
  app.add_option("POINTS", a.more_points, "further points for --at")->type_name("X,Y,Z ...");
  opt::parsed(app, "--at", a.at, "remove the tet containing each point in turn (several separated by ';')",
              "X,Y,Z", parse_points, "expects X,Y,Z (several separated by ';')");
  opt::text(app, "--random", a.random, "request N tets (or all) on the current boundary, one at a time", "N|all");
  opt::count(app, "--seed", a.seed, "the seed of --random", "S");
  opt::strategy(app, "--strategy", a.strategy, "removal strategy (default combined)");
  opt::neighbour_set(app, "--neighbour-set", a.neighbour_set,
                     "which removable set the neighbour search (paper 3.5) keeps: the smallest (default) or the first "
                     "it finds");
  opt::improvement(app, a.improvement, "request");
  opt::check_mode(app, a.check, "local check after every request and full check at the end; end (default): full "
                                "check at the end; none");
  opt::text(app, "-o", a.output, "the mesh after the removals", "OUT")->required();
  opt::text(app, "--report", a.report, "`summary` (the paper's statistics) and `details` as JSON", "R.json");
}

// The tets a removal request may have brought to the surface, from its ChangeLog alone (the
// public API): the tets that shared a face with a removed tet, and the created tets on the
// boundary. A removed tet's vertices are gone from the mesh, so the vertices of every tet are
// mirrored here, updated from each ChangeLog in O(changed).
class RequestExposure {
 public:
  explicit RequestExposure(const TetMesh& mesh) {
    verts_.resize(mesh.tet_capacity());
    for (std::uint32_t i = 0; i < mesh.tet_capacity(); ++i)
      if (mesh.is_live(TetId{i})) verts_[i] = mesh.tet(TetId{i});
  }

  // After the request that wrote `log`: its exposed tets, in the order of the removed tets and
  // their faces (face i opposite vertex i), then the created tets.
  std::span<const TetId> after(const TetMesh& mesh, const ChangeLog& log) {
    exposed_.clear();
    for (TetId r : log.removed) {
      const TetMesh::TetVerts& v = verts_[r.value];
      for (int face = 0; face < 4; ++face) {
        const VertId a = v[(face + 1) % 4], b = v[(face + 2) % 4], c = v[(face + 3) % 4];
        if (!mesh.is_live(a)) continue;
        mesh.vertex_shell(a, shell_);
        for (TetId u : shell_)
          if (mesh.local_index(u, b) >= 0 && mesh.local_index(u, c) >= 0) exposed_.push_back(u);
      }
    }
    for (const CreatedTet& c : log.created) {
      if (c.tet.value >= verts_.size()) verts_.resize(c.tet.value + c.tet.value / 4 + 16);
      verts_[c.tet.value] = mesh.tet(c.tet);
      if (mesh.boundary_face_count(c.tet) > 0) exposed_.push_back(c.tet);
    }
    return exposed_;
  }

 private:
  std::vector<TetMesh::TetVerts> verts_;  // by tet id: its vertices while it was live
  std::vector<TetId> exposed_, shell_;
};

Json report_json(const RemovalReport& s, RemovalStrategy strategy, std::uint64_t tets_left, const std::string& hash,
                 std::uint64_t points_outside, bool valid) {
  return Json{{"summary",
               {{"requested", s.requested},
                {"removed", s.removed},
                {"unresolved", s.unresolved},
                {"direct", s.direct},
                {"vertex_singularities", s.vertex_singularities},
                {"edge_singularities", s.edge_singularities},
                {"resolved_by_neighbours", s.resolved_by_neighbours},
                {"resolved_by_refinement", s.resolved_by_refinement},
                {"mean_cardinality", s.mean_cardinality()},
                {"tets_left", tets_left},
                {"hash", hash}}},
              {"details",
               {{"strategy", to_string(strategy)},
                {"repeated_requests", s.repeated_requests},
                {"vertex_resolved_by_neighbours", s.vertex_resolved_by_neighbours},
                {"edge_resolved_by_neighbours", s.edge_resolved_by_neighbours},
                {"vertex_neighbour_set_tets", s.vertex_neighbour_set_tets},
                {"edge_neighbour_set_tets", s.edge_neighbour_set_tets},
                {"resolved_by_optimized_refinement", s.resolved_by_optimized_refinement},
                {"attempts_undone", s.attempts_undone},
                {"tets_removed", s.tets_removed},
                {"tets_created", s.tets_created},
                {"edges_split", s.edges_split},
                {"points_in_no_tet", points_outside},
                {"valid", valid}}}};
}

}  // namespace

int cmd_remove(Args args, std::ostream& out, std::ostream& err) {
  RemoveArgs a;
  CommandParser parser(
      "remove",
      "tetcut remove MESH (--at X,Y,Z ... | --random N|all --seed S) [--strategy basic|neighbours|combined|wide] "
      "[--neighbour-set smallest|first] [--check every|end|none] -o OUT [--report R.json]",
      "Removes tetrahedra without breaking the manifold (paper 3.3-3.7) and prints the paper's\n"
      "statistics (Tables 1 and 2). --at removes the tet containing each point in turn; --random\n"
      "requests tets on the current boundary one at a time, as a cautery meets them.\n",
      "exit: 0, 1 an invariant broke, 2 unreadable input or bad usage");
  add_options(parser.app(), a);
  if (const auto code = parser.parse(args, out, err)) return *code;
  if (a.at.has_value() == a.random.has_value()) return parser.usage_error("give exactly one of --at and --random", err);
  std::vector<Vec3> points = a.at.value_or(std::vector<Vec3>{});
  for (const std::string& more : a.more_points) {
    const auto p = a.at ? parse_points(more) : std::nullopt;
    if (!p) return parser.usage_error("unexpected argument '" + more + "' (not a point X,Y,Z after --at)", err);
    points.insert(points.end(), p->begin(), p->end());
  }
  if (a.at && points.empty()) return parser.usage_error("--at expects at least one point", err);
  std::optional<std::uint64_t> random_count;  // nullopt with --random: all
  if (a.random) {
    if (*a.random != "all" && !(random_count = scenario::parse_uint(*a.random)))
      return parser.usage_error("--random: expects a count or 'all', not '" + *a.random + "'", err);
    if (!a.seed) return parser.usage_error("--random needs --seed S", err);
  } else if (a.seed) {
    return parser.usage_error("--seed goes with --random", err);
  }
  const RemovalStrategy strategy = a.strategy.value_or(RemovalStrategy::kCombined);
  const scenario::CheckMode check_mode = a.check.value_or(scenario::CheckMode::kEnd);

  const std::optional<RawMesh> raw = load_mesh(*a.mesh, err);
  if (!raw) return kExitBadInput;
  BuildResult built = build_mesh(*raw);
  if (!built.ok()) {
    err << "tetcut: " << *a.mesh << ": not a valid manifold mesh: " << built.problems.front().message << " ("
        << built.problems.size() << " problem(s); see tetcut check)\n";
    return kExitBadInput;
  }
  TetMesh& mesh = *built.mesh;

  CutParams params;
  params.strategy = strategy;
  if (a.neighbour_set) params.neighbour_set = *a.neighbour_set;
  opt::improvement_params(a.improvement, params);
  if (auto invalid = validate(params)) {
    err << "tetcut: " << *invalid << "\n";
    return 2;
  }

  std::optional<invariants::LocalChecker> local;
  if (check_mode == scenario::CheckMode::kEvery) local.emplace(mesh.raw_view());
  std::string first_violation;
  auto check_request = [&](std::uint64_t index, std::span<const TetId> removed, std::span<const TetId> created,
                           double min_dihedral_held_deg) {
    if (!local || !first_violation.empty()) return;
    invariants::CheckOptions co = scenario::transaction_check_options(params, min_dihedral_held_deg);
    co.operation = "request " + std::to_string(index);
    const invariants::CheckReport r = local->after_operation(mesh.raw_view(), removed, created, co);
    if (!r.ok()) first_violation = co.operation + ": " + invariants::to_string(r);
  };

  Cutter cutter(mesh, params);
  // The file's labels, carried through every request by its change log, and written back.
  const bool labelled = raw->labelled();
  mechanics::TetLabels labels;
  if (labelled) labels = mechanics::TetLabels(mesh, raw->labels);  // the builder keeps the file's tet order
  ChangeLog label_log;
  std::uint64_t points_outside = 0, refused = 0;
  std::string first_refusal;
  auto request = [&](std::uint64_t index, TetId t, ChangeLog* log) {
    if (labelled && log == nullptr) {
      label_log.clear();
      log = &label_log;
    }
    const CutReport r = cutter.remove(t, log);
    if (r.ok && labelled) labels.apply(mesh, *log);
    if (!r.ok && refused++ == 0) first_refusal = "request " + std::to_string(index) + ": " + r.failure;
    check_request(index, cutter.last_removed(), cutter.last_created(), cutter.last_min_dihedral_held());
  };
  if (!points.empty()) {
    for (std::size_t i = 0; i < points.size(); ++i) {
      const TetId t = cutter.tet_containing(points[i]);
      if (!t.valid()) {
        ++points_outside;
        continue;
      }
      request(i, t, nullptr);
    }
  } else {
    BoundaryTetPicker picker(mesh, *a.seed);
    RequestExposure exposure(mesh);
    ChangeLog log;
    // With `neighbours` an unresolved tet stays on the surface and may be met again; bound the
    // run so that `all` ends when only such tets remain.
    const std::uint64_t limit = random_count ? *random_count : 20ull * mesh.num_tets() + 100;
    for (std::uint64_t i = 0; i < limit; ++i) {
      const TetId t = picker.pick(mesh);
      if (!t.valid()) break;
      log.clear();
      request(i, t, &log);
      picker.add(exposure.after(mesh, log));
    }
  }
  const RemovalReport& s = cutter.removal_report();

  bool valid = first_violation.empty();
  if (check_mode != scenario::CheckMode::kNone) {
    const invariants::CheckReport r = invariants::check_mesh(mesh.raw_view());
    if (!r.ok() && valid) first_violation = "end: " + invariants::to_string(r);
    valid = valid && r.ok();
  }

  const std::string hash = hash_to_hex(canonical_hash(mesh));
  out << "removed " << s.removed << " of " << s.requested << " requested tets (" << to_string(strategy)
      << "): " << s.direct << " direct, " << s.vertex_singularities << " vertex and " << s.edge_singularities
      << " edge singularities, " << s.resolved_by_neighbours << " resolved by neighbours, "
      << s.resolved_by_refinement << " by refinement, " << s.unresolved << " unresolved; mean cardinality "
      << s.mean_cardinality() << "; " << mesh.num_tets() << " tets left\n";
  if (points_outside) out << points_outside << " point(s) in no tet\n";
  if (refused) out << refused << " request(s) refused and rolled back, the first " << first_refusal << "\n";
  out << "hash " << hash << "\n";
  if (!valid) out << "violated: " << first_violation << "\n";

  const Json report = report_json(s, strategy, mesh.num_tets(), hash, points_outside, valid);
  const std::span<const std::uint32_t> by_tet = labelled ? labels.by_tet() : std::span<const std::uint32_t>();
  if (!save_mesh_and_report(*a.output, mesh, a.report, report, err, by_tet)) return kExitBadInput;
  return valid ? kExitOk : kExitViolated;
}

}  // namespace tetcut::cli
