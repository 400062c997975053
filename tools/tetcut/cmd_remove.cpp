// `tetcut remove MESH (--at X,Y,Z ... | --random N|all --seed S) [--strategy basic|neighbours|combined|wide]
//  [--check every|end|none] -o OUT [--report R.json]`: removes tetrahedra without breaking the
// manifold (paper 3.3-3.7) and prints the paper's statistics (Tables 1 and 2).
//
// --at takes one or more points ("X,Y,Z", several separated by ';' or given as further
// arguments after the mesh): each removes the tet containing it at the time of its turn.
// --random requests tets on the current boundary one at a time, as a cautery meets them; `all`
// goes on until the mesh is empty (or only unresolved tets remain, with --strategy neighbours),
// or 20 requests per initial tet: basic and combined refine, and a cautery that keeps meeting
// the small tets they make can keep the mesh alive (`wide` hollows a mesh out).
// --check every runs the local checker after every request and the full one at the end; end
// (default) only the full one; none skips it. Exit 0, 1 if an invariant broke, 2 bad input.
#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "args.hpp"
#include "command.hpp"
#include "json_writer.hpp"
#include "mesh_input.hpp"
#include "detail/boundary_tet_picker.hpp"
#include "tetcut/canonical_hash.hpp"
#include "tetcut/invariants/check.hpp"
#include "tetcut/io.hpp"
#include "tetcut/mesh_builder.hpp"
#include "tetcut/predicates.hpp"
#include "detail/removal.hpp"

namespace tetcut::cli {

int cmd_remove(Args args, std::ostream& out, std::ostream& err);

namespace {

constexpr OptionSpec kSpecs[] = {
    {"--at", true}, {"--random", true}, {"--seed", true},   {"--strategy", true},
    {"--check", true}, {"-o", true},    {"--report", true},
};

int remove_usage(std::ostream& err, const std::string& message) {
  err << "tetcut remove: " << message << "\n"
      << "usage: tetcut remove MESH (--at X,Y,Z ... | --random N|all --seed S)\n"
         "                          [--strategy basic|neighbours|combined|wide] [--check every|end|none]\n"
         "                          -o OUT [--report R.json]\n";
  return kExitBadInput;
}

// "X,Y,Z;X,Y,Z" or "X,Y,Z X,Y,Z".
bool parse_points(std::string_view text, std::vector<Vec3>& points) {
  std::size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && (text[i] == ';' || text[i] == ' ')) ++i;
    if (i >= text.size()) break;
    std::size_t j = i;
    while (j < text.size() && text[j] != ';' && text[j] != ' ') ++j;
    const auto p = parse_vec3(text.substr(i, j - i));
    if (!p) return false;
    points.push_back(*p);
    i = j;
  }
  return true;
}

// The live tet containing p (closed: a point on a shared face picks the lowest id). A person's
// one-off query: a scan with the exact predicate is fine here, not on the cut path.
TetId locate(const TetMesh& mesh, const Vec3& p) {
  for (std::uint32_t i = 0; i < mesh.tet_capacity(); ++i) {
    const TetId t{i};
    if (!mesh.is_live(t)) continue;
    const auto v = mesh.tet(t);
    bool inside = true;
    for (int f = 0; f < 4 && inside; ++f) {
      Vec3 q[4] = {mesh.position(v[0]), mesh.position(v[1]), mesh.position(v[2]), mesh.position(v[3])};
      q[f] = p;
      inside = orientation(q[0], q[1], q[2], q[3]) >= 0;
    }
    if (inside) return t;
  }
  return kNoTet;
}

enum class CheckMode { kEvery, kEnd, kNone };

}  // namespace

int cmd_remove(Args args, std::ostream& out, std::ostream& err) {
  const ArgParseResult parsed = parse_args(args, kSpecs);
  if (!parsed.ok()) return remove_usage(err, parsed.error);
  const ParsedArgs& a = parsed.args;
  if (a.positionals.empty()) return remove_usage(err, "expected a MESH");
  const auto output = a.value("-o");
  if (!output) return remove_usage(err, "missing -o OUT");
  if (a.has("--at") == a.has("--random")) return remove_usage(err, "give exactly one of --at and --random");

  std::vector<Vec3> points;
  if (a.has("--at")) {
    if (!parse_points(*a.value("--at"), points)) return remove_usage(err, "--at expects X,Y,Z (several separated by ';')");
    for (std::size_t i = 1; i < a.positionals.size(); ++i)
      if (!parse_points(a.positionals[i], points))
        return remove_usage(err, "unexpected argument '" + a.positionals[i] + "' (not a point X,Y,Z)");
    if (points.empty()) return remove_usage(err, "--at expects at least one point");
  } else if (a.positionals.size() != 1) {
    return remove_usage(err, "expected exactly one MESH");
  }

  std::optional<std::uint64_t> random_count;  // nullopt with --random: all
  std::uint64_t seed = 0;
  if (a.has("--random")) {
    const std::string n = *a.value("--random");
    if (n != "all") {
      random_count = parse_uint(n);
      if (!random_count) return remove_usage(err, "--random expects a count or 'all', not '" + n + "'");
    }
    const auto s = a.value("--seed");
    if (!s) return remove_usage(err, "--random needs --seed S");
    const auto v = parse_uint(*s);
    if (!v) return remove_usage(err, "--seed expects a non-negative integer, not '" + *s + "'");
    seed = *v;
  } else if (a.has("--seed")) {
    return remove_usage(err, "--seed goes with --random");
  }

  RemovalOptions options;
  if (const auto s = a.value("--strategy")) {
    const auto strategy = parse_removal_strategy(*s);
    if (!strategy) return remove_usage(err, "--strategy must be basic, neighbours, combined or wide, not '" + *s + "'");
    options.strategy = *strategy;
  }
  CheckMode check_mode = CheckMode::kEnd;
  if (const auto c = a.value("--check")) {
    if (*c == "every") check_mode = CheckMode::kEvery;
    else if (*c == "end") check_mode = CheckMode::kEnd;
    else if (*c == "none") check_mode = CheckMode::kNone;
    else return remove_usage(err, "--check must be every, end or none, not '" + *c + "'");
  }

  const std::optional<RawMesh> raw = load_mesh(a.positionals[0], err);
  if (!raw) return kExitBadInput;
  BuildResult built = build_mesh(*raw);
  if (!built.ok()) {
    err << "tetcut: " << a.positionals[0] << ": not a valid manifold mesh: " << built.problems.front().message
        << " (" << built.problems.size() << " problem(s); see tetcut check)\n";
    return kExitBadInput;
  }
  TetMesh& mesh = *built.mesh;

  Remover remover(options);
  std::optional<invariants::LocalChecker> local;
  if (check_mode == CheckMode::kEvery) local.emplace(mesh.raw_view());
  std::string first_violation;
  std::uint64_t points_outside = 0;
  auto request = [&](TetId t, std::uint64_t index) {
    remover.remove(mesh, t);
    if (local && first_violation.empty()) {
      invariants::CheckOptions co;
      co.operation = "request " + std::to_string(index);
      const invariants::CheckReport r = local->after_operation(mesh.raw_view(), remover.last_removed(), remover.last_created(), co);
      if (!r.ok()) first_violation = co.operation + ": " + invariants::to_string(r);
    }
  };

  if (!points.empty()) {
    for (std::size_t i = 0; i < points.size(); ++i) {
      const TetId t = locate(mesh, points[i]);
      if (!t.valid()) {
        ++points_outside;
        continue;
      }
      request(t, i);
    }
  } else {
    BoundaryTetPicker picker(mesh, seed);
    // With `neighbours` an unresolved tet stays on the surface and may be met again; bound the
    // run so that `all` ends when only such tets remain.
    const std::uint64_t limit = random_count ? *random_count : 20ull * mesh.num_tets() + 100;
    for (std::uint64_t i = 0; i < limit; ++i) {
      const TetId t = picker.pick(mesh);
      if (!t.valid()) break;
      request(t, i);
      picker.add(remover.last_exposed());
    }
  }

  bool valid = first_violation.empty();
  if (check_mode != CheckMode::kNone) {
    const invariants::CheckReport r = invariants::check_mesh(mesh.raw_view());
    if (!r.ok() && valid) first_violation = "end: " + invariants::to_string(r);
    valid = valid && r.ok();
  }

  const RemovalReport& s = remover.report();
  const std::string hash = hash_to_hex(canonical_hash(mesh));
  out << "removed " << s.removed << " of " << s.requested << " requested tets (" << to_string(options.strategy)
      << "): " << s.direct << " direct, " << s.vertex_singularities << " vertex and " << s.edge_singularities
      << " edge singularities, " << s.resolved_by_neighbours << " resolved by neighbours, "
      << s.resolved_by_refinement << " by refinement, " << s.unresolved << " unresolved; mean cardinality "
      << s.mean_cardinality() << "; " << mesh.num_tets() << " tets left\n";
  if (points_outside) out << points_outside << " point(s) in no tet\n";
  out << "hash " << hash << "\n";
  if (!valid) out << "violated: " << first_violation << "\n";

  const bool saved = save_mesh_and_report(*output, mesh, a.value("--report"), [&](JsonWriter& w) {
    w.key("summary");
    w.begin_object();
    w.field("requested", s.requested);
    w.field("removed", s.removed);
    w.field("unresolved", s.unresolved);
    w.field("direct", s.direct);
    w.field("vertex_singularities", s.vertex_singularities);
    w.field("edge_singularities", s.edge_singularities);
    w.field("resolved_by_neighbours", s.resolved_by_neighbours);
    w.field("resolved_by_refinement", s.resolved_by_refinement);
    w.field("mean_cardinality", s.mean_cardinality());
    w.field("tets_left", static_cast<std::uint64_t>(mesh.num_tets()));
    w.field("hash", hash);
    w.end_object();
    w.key("details");
    w.begin_object();
    w.field("strategy", to_string(options.strategy));
    w.field("repeated_requests", s.repeated_requests);
    w.field("vertex_resolved_by_neighbours", s.vertex_resolved_by_neighbours);
    w.field("edge_resolved_by_neighbours", s.edge_resolved_by_neighbours);
    w.field("vertex_neighbour_set_tets", s.vertex_neighbour_set_tets);
    w.field("edge_neighbour_set_tets", s.edge_neighbour_set_tets);
    w.field("resolved_by_optimized_refinement", s.resolved_by_optimized_refinement);
    w.field("attempts_undone", s.attempts_undone);
    w.field("tets_removed", s.tets_removed);
    w.field("tets_created", s.tets_created);
    w.field("edges_split", s.edges_split);
    w.field("points_in_no_tet", points_outside);
    w.field("valid", valid);
    w.end_object();
  }, err);
  if (!saved) return kExitBadInput;
  return valid ? kExitOk : kExitViolated;
}

}  // namespace tetcut::cli
