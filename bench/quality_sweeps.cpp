// tetcut_quality_sweeps: random cautery sweeps on meshes tetcut did not write, and the shape of
// the tets the cuts create, under a refinement rule (the engine's default, auto, unless asked).
//
//   tetcut_quality_sweeps [--sweeps N] [--seed S] [--only MESH] [--tool TOOL]
//                         [--refinement auto|paper|graded] [--min-dihedral DEG] [--json FILE]
//                         [--gate FILE]
//
// The meshes come from other meshers at other densities: TetGen (through tools/generators) fills
// a box at three densities, one without TetGen's quality bound (its plain Delaunay
// tetrahedralization of the box's points), a cylinder and an icosphere (a curved boundary of even
// density); CGAL Mesh_3 makes a liver of about 6,000 tets from Debian's liver image; and the
// bundled 16k liver (also Mesh_3). On each mesh, for each tool (4, 8 and 12 % of the bounding
// box's diagonal, and 0.05, 0.1, 0.3, 1 and 3 times the median edge: a fine cautery on a coarse
// mesh up to a coarse one on a fine mesh), N sweeps along random chords of the bounding box, one
// cut every half tool diameter, each sweep on a fresh copy of the mesh, with the default
// CutParams (combined, the improvement pass on, floors 0.1 and 15 degrees, or the dihedral floor
// asked for) and the refinement rule asked for.
//
// After every cut the independent checker runs on what it changed, with I7's no-degradation rule at
// the cut's floor and I10, the tissue rule, with its tool (scenario::cut_check_options), and
// measures the created tets (invariants::quality_of). Per mesh and tool: cuts made and refused, by
// reason (a refused cut leaves the mesh as it was: the quality floor the pass cannot lift a
// created tet to, the tissue rule, the tet budget, a degenerate split), checker violations, cuts
// that left tissue in the tool (CutReport::left_in_tool), cuts that allocated, the input's worst
// radius ratio, the goal min(0.1, that), the worst created radius ratio and dihedral angle, the
// tets one cut created (p99, max: net, ok cuts; and of them the ones within the cut's reach, the
// ball grown by D_ref, p99, with the share of all made tets beyond it), the cut times (p50, p99,
// max: every cut that met the mesh, the refused ones included, since a refusal costs its
// attempt), cuts auto made again with the graded rule, cuts whose pass held a lower theta, tets
// removed beyond the cut's reach, and per ok cut the volume left
// in the tool and removed beyond it as shares of the tool's ball (p50, p99).
//
// Deterministic but for the times: the meshers are seeded, and so are the chords (SplitMix64).
// Exit 0; 1 when the checker objected to a cut, a cut was refused or a created tet is below its
// goal; 2 on bad
// arguments or a mesher failure.
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "bench_meshes.hpp"
#include "core/random.hpp"
#include "counting_allocator.hpp"
#include "tetcut/cut.hpp"
#include "tetcut/generators/liver.hpp"
#include "tetcut/generators/shapes.hpp"
#include "tetcut/invariants/check.hpp"
#include "tetcut/io.hpp"
#include "tetcut/mesh_builder.hpp"
#include "tetcut/percentile.hpp"
#include "tetcut/scenario/scenario.hpp"

namespace {

using tetcut::TetMesh;
using tetcut::Vec3;
namespace gen = tetcut::generators;
namespace inv = tetcut::invariants;

struct SourceMesh {
  std::string name, made_by;
  std::function<gen::GenResult()> make;  // empty: the bundled liver
};

std::vector<SourceMesh> source_meshes() {
  return {
      {"box-coarse", "TetGen, spacing 0.25, -q1.4/12",
       [] { return gen::generate_box({.spacing = 0.25}); }},
      {"box-fine", "TetGen, spacing 0.1, -q2.0",
       [] { return gen::generate_box({.spacing = 0.1, .radius_edge_ratio = 2.0, .min_dihedral_deg = 0.0}); }},
      {"box-delaunay", "TetGen, spacing 0.15, no quality bound",
       [] { return gen::generate_box({.spacing = 0.15, .radius_edge_ratio = 0.0, .min_dihedral_deg = 0.0}); }},
      {"cylinder", "TetGen, radius 1, height 4, 24 sides",
       [] { return gen::generate_cylinder({.segments = 24}); }},
      // The icosphere of 2 subdivisions (320 triangles, edges about 0.3) filled with tets of that
      // size: 5,754 tets (TetGen's default volume bound for it gives 3,088).
      {"sphere", "TetGen, icosphere of 2 subdivisions, -a0.0042",
       [] { return gen::generate_sphere({.subdivisions = 2, .max_volume = 0.0042}); }},
      {"liver-6k", "CGAL Mesh_3, about 6,000 tets",
       [] { return gen::generate_liver({.cell_size = gen::liver_cell_size_for_tets(6000)}); }},
      {"liver-16k", "CGAL Mesh_3, the bundled liver.msh", {}},
  };
}

struct Tool {
  std::string name;
  double diameter;
};

struct Row {
  std::string mesh, made_by, tool, refinement;
  double diameter = 0;
  std::uint32_t tets = 0;
  double input_worst = 1, goal = 0.1;
  double input_min_dihedral = 180, dihedral_goal = 15;  // the input's and min(theta, that)
  std::uint64_t cuts = 0, refused = 0, violations = 0, max_created = 0;
  std::uint64_t left = 0;          // ok cuts that left tissue in the tool (CutReport::left_in_tool)
  std::uint64_t beyond_reach = 0;  // tets removed beyond the cut's reach (CutReport::tets_removed_beyond_reach)
  std::uint64_t retried = 0;       // ok cuts made again with the graded rule (auto's retry)
  std::uint64_t theta_lowered = 0; // ok cuts whose pass held a lower theta (CutReport::min_dihedral_held_deg)
  // Per ok cut: the volume of tissue left in the tool and removed beyond it, as shares of the ball.
  std::vector<double> left_share, beyond_share;
  std::uint64_t allocating = 0;    // cuts that allocated on the heap
  std::array<std::uint64_t, tetcut::kCutRefusals> refused_by{};  // by CutRefusal
  inv::QualityStats created;
  std::vector<double> cut_us;      // every cut that met the mesh, refused ones included
  std::vector<double> made;        // net tets created, per ok cut
  // Of those, per ok cut, the ones whose centroid lies within the cut's reach (the tool's ball
  // grown by D_ref): what the tissue rule asks for near the tool. The rest grade the refinement
  // out to the mesh's own size.
  std::vector<double> made_within_reach;
  std::uint64_t made_total = 0, made_beyond_total = 0;
  std::string first_violation, first_refusal;
  // Met: no cut refused or lowering theta, and no created tet below either goal (an angle within
  // rounding of its goal meets it: a split child keeps its parent's angles).
  [[nodiscard]] bool goal_met() const {
    return refused == 0 && theta_lowered == 0 &&
           (created.tets == 0 || (created.min_radius_ratio >= goal && created.min_dihedral_deg >= dihedral_goal - 1e-7));
  }
};

double max_of(const std::vector<double>& values) {
  return values.empty() ? 0.0 : *std::max_element(values.begin(), values.end());
}

// The refusals by reason, the common ones first: "floor 12, tissue 3".
std::string refusal_reasons(const Row& row) {
  std::string out;
  for (int k = 1; k < tetcut::kCutRefusals; ++k) {
    if (row.refused_by[static_cast<std::size_t>(k)] == 0) continue;
    if (!out.empty()) out += ", ";
    out += std::string(tetcut::to_string(static_cast<tetcut::CutRefusal>(k))) + " " +
           std::to_string(row.refused_by[static_cast<std::size_t>(k)]);
  }
  return out;
}

double median_edge(const TetMesh& mesh) {
  std::vector<double> lengths;
  for (std::uint32_t t = 0; t < mesh.tet_capacity(); ++t) {
    if (!mesh.is_live(tetcut::TetId{t})) continue;
    const auto v = mesh.tet(tetcut::TetId{t});
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) lengths.push_back(norm(mesh.position(v[j]) - mesh.position(v[i])));
  }
  return tetcut::percentile(lengths, 0.5);  // each interior edge once per tet around it: a weighted median
}

// The live tets among `created` whose centroid lies within `radius` of `centre`.
std::uint32_t made_within_reach(const TetMesh& mesh, std::span<const tetcut::TetId> created, const Vec3& centre,
                                double radius) {
  std::uint32_t within = 0;
  for (const tetcut::TetId t : created) {
    if (!mesh.is_live(t)) continue;
    Vec3 centroid{0, 0, 0};
    for (const tetcut::VertId v : mesh.tet(t)) centroid = centroid + 0.25 * mesh.position(v);
    within += norm(centroid - centre) <= radius ? 1 : 0;
  }
  return within;
}

Row sweep(const SourceMesh& source, const TetMesh& base, const Tool& tool, int sweeps, std::uint64_t seed,
          tetcut::RefinementRule rule, double min_dihedral_deg) {
  Row row{.mesh = source.name, .made_by = source.made_by, .tool = tool.name, .refinement = tetcut::to_string(rule),
          .diameter = tool.diameter, .tets = base.num_tets()};
  const inv::QualityStats input = inv::check_mesh(base.raw_view()).quality;
  row.input_worst = input.min_radius_ratio;
  row.goal = std::min(0.1, row.input_worst);
  row.input_min_dihedral = input.min_dihedral_deg;
  row.dihedral_goal = std::min(min_dihedral_deg, input.min_dihedral_deg);
  const tetcut::BoundingBox box = tetcut::bounding_box(base);
  tetcut::SplitMix64 rng(seed);
  auto point = [&] {
    return Vec3{box.lo.x + rng.unit() * (box.hi.x - box.lo.x), box.lo.y + rng.unit() * (box.hi.y - box.lo.y),
                box.lo.z + rng.unit() * (box.hi.z - box.lo.z)};
  };
  const tetcut::CutParams params{.tool_diameter = tool.diameter, .refinement = rule, .min_dihedral_deg = min_dihedral_deg};
  for (int s = 0; s < sweeps; ++s) {
    TetMesh mesh = base;
    tetcut::Cutter cutter(mesh, params);
    inv::LocalChecker local(mesh.raw_view());
    const Vec3 a = point(), b = point();
    const auto steps = static_cast<int>(norm(b - a) / (0.5 * tool.diameter));
    for (int k = 0; k <= steps; ++k) {
      const Vec3 centre = steps == 0 ? a : a + (static_cast<double>(k) / steps) * (b - a);
      const std::uint64_t allocations = tetcut::bench::allocations();
      const tetcut::CutReport r = cutter.cut(centre);
      row.allocating += tetcut::bench::allocations() != allocations ? 1 : 0;
      if (r.tets_hit > 0) row.cut_us.push_back(r.time.total_us);
      if (!r.ok) {
        if (row.refused++ == 0) row.first_refusal = r.failure;
        ++row.refused_by[static_cast<std::size_t>(r.refusal)];
        continue;
      }
      if (r.tets_hit == 0) continue;  // the tool in the air: not a cut
      ++row.cuts;
      row.made.push_back(r.tets_created);
      const std::uint32_t within = made_within_reach(mesh, cutter.last_created(), centre, 0.5 * tool.diameter + r.d_ref);
      row.made_within_reach.push_back(within);
      row.made_total += r.tets_created;
      row.made_beyond_total += r.tets_created - within;
      row.max_created = std::max<std::uint64_t>(row.max_created, r.tets_created);
      row.left += r.left_in_tool > 0 ? 1 : 0;
      row.beyond_reach += r.tets_removed_beyond_reach;
      row.retried += r.retries;
      row.theta_lowered += r.min_dihedral_held_deg < params.min_dihedral_deg;
      const double ball = std::numbers::pi / 6.0 * tool.diameter * tool.diameter * tool.diameter;
      row.left_share.push_back(r.volume_left_in_tool / ball);
      row.beyond_share.push_back(r.volume_removed_beyond_tool / ball);
      inv::pool(row.created, inv::quality_of(mesh.raw_view(), cutter.last_created()));
      const inv::CheckReport report =
          local.after_operation(mesh.raw_view(), cutter.last_removed(), cutter.last_created(),
                                tetcut::scenario::cut_check_options(cutter, centre));
      if (!report.ok() && row.violations++ == 0) row.first_violation = inv::to_string(report);
    }
  }
  return row;
}

std::string figure(double value, const char* format) {
  char buf[32];
  std::snprintf(buf, sizeof buf, format, value);
  return buf;
}

void print(const std::vector<Row>& rows) {
  std::printf("%-13s %-6s %-6s %8s %6s %6s %7s %5s %5s %5s %7s %6s %7s %7s %7s %7s %9s %9s %9s %9s\n", "mesh", "rule", "tool",
              "diameter", "tets", "cuts", "refused", "viol.", "left", "alloc", "input", "goal", "worst", "min dih",
              "made p99", "max", "reach p99", "p50 us", "p99 us", "max us");
  for (const Row& r : rows)
    std::printf("%-13s %-6s %-6s %8.3g %6u %6llu %7llu %5llu %5llu %5llu %7.3g %6.3g %7s %7s %7.0f %7llu %9.0f %9.1f %9.1f %9.1f%s\n",
                r.mesh.c_str(), r.refinement.c_str(), r.tool.c_str(), r.diameter, r.tets,
                static_cast<unsigned long long>(r.cuts), static_cast<unsigned long long>(r.refused),
                static_cast<unsigned long long>(r.violations), static_cast<unsigned long long>(r.left),
                static_cast<unsigned long long>(r.allocating), r.input_worst, r.goal,
                r.created.tets ? figure(r.created.min_radius_ratio, "%.3g").c_str() : "-",
                r.created.tets ? figure(r.created.min_dihedral_deg, "%.1f").c_str() : "-",
                tetcut::percentile(r.made, 0.99), static_cast<unsigned long long>(r.max_created),
                tetcut::percentile(r.made_within_reach, 0.99), tetcut::percentile(r.cut_us, 0.5), tetcut::percentile(r.cut_us, 0.99), max_of(r.cut_us),
                r.goal_met() ? "" : "  BELOW GOAL");
  for (const Row& r : rows)
    if (r.refused) std::printf("%s, %s: refused %s\n", r.mesh.c_str(), r.tool.c_str(), refusal_reasons(r).c_str());
  for (const Row& r : rows)
    if (r.violations) std::printf("%s, %s: %s\n", r.mesh.c_str(), r.tool.c_str(), r.first_violation.c_str());
}

bool write_json(const std::string& path, const std::vector<Row>& rows, int sweeps, std::uint64_t seed,
                tetcut::RefinementRule rule, double min_dihedral_deg) {
  nlohmann::json out_rows = nlohmann::json::array();
  for (const Row& r : rows) {
    nlohmann::json row = {{"mesh", r.mesh},
                          {"made_by", r.made_by},
                          {"tets", r.tets},
                          {"tool", r.tool},
                          {"refinement", r.refinement},
                          {"tool_diameter", r.diameter},
                          {"cuts", r.cuts},
                          {"refused", r.refused},
                          {"checker_violations", r.violations},
                          {"cuts_leaving_tissue", r.left},
                          {"allocating_cuts", r.allocating},
                          {"input_worst_radius_ratio", r.input_worst},
                          {"goal", r.goal},
                          {"input_min_dihedral_deg", r.input_min_dihedral},
                          {"dihedral_goal_deg", r.dihedral_goal},
                          {"goal_met", r.goal_met()},
                          {"created_tets", r.created.tets},
                          {"max_created_per_cut", r.max_created},
                          {"p99_created_per_cut", tetcut::percentile(r.made, 0.99)},
                          {"p99_created_within_reach_per_cut", tetcut::percentile(r.made_within_reach, 0.99)},
                          {"created_beyond_reach_share",
                           r.made_total ? static_cast<double>(r.made_beyond_total) / static_cast<double>(r.made_total) : 0.0},
                          {"retried_cuts", r.retried},
                          {"cuts_lowering_theta", r.theta_lowered},
                          {"tets_removed_beyond_reach", r.beyond_reach},
                          {"volume_left_share_p50", tetcut::percentile(r.left_share, 0.5)},
                          {"volume_left_share_p99", tetcut::percentile(r.left_share, 0.99)},
                          {"volume_removed_beyond_share_p50", tetcut::percentile(r.beyond_share, 0.5)},
                          {"volume_removed_beyond_share_p99", tetcut::percentile(r.beyond_share, 0.99)},
                          {"p50_us", tetcut::percentile(r.cut_us, 0.5)},
                          {"p99_us", tetcut::percentile(r.cut_us, 0.99)},
                          {"max_us", max_of(r.cut_us)}};
    if (r.created.tets) {
      row["worst_created_radius_ratio"] = r.created.min_radius_ratio;
      row["worst_created_min_dihedral_deg"] = r.created.min_dihedral_deg;
    }
    if (r.refused) {
      row["first_refusal"] = r.first_refusal;
      nlohmann::json reasons = nlohmann::json::object();
      for (int k = 1; k < tetcut::kCutRefusals; ++k)
        if (r.refused_by[static_cast<std::size_t>(k)])
          reasons[tetcut::to_string(static_cast<tetcut::CutRefusal>(k))] = r.refused_by[static_cast<std::size_t>(k)];
      row["refusals"] = std::move(reasons);
    }
    if (r.violations) row["first_violation"] = r.first_violation;
    out_rows.push_back(std::move(row));
  }
  const nlohmann::json out = {
      {"sweeps_per_tool", sweeps}, {"seed", seed}, {"refinement", tetcut::to_string(rule)}, {"min_dihedral_deg", min_dihedral_deg},
      {"rows", std::move(out_rows)}};
  return tetcut::write_file_atomically(path, out.dump(1) + "\n").ok;
}

// The tool-size gate (--gate): a TetGen box, the TetGen sphere and the bundled CGAL liver, cut
// with the five tools scaled to each mesh's median edge, from a cautery finer than a tenth of the
// edge to one three edges wide. Its figures pool the three meshes per tool.
constexpr std::array<const char*, 3> kGatedMeshes = {"box-fine", "sphere", "liver-16k"};
constexpr std::array<const char*, 5> kGatedTools = {"0.05x", "0.1x", "0.3x", "1x", "3x"};

bool gated(const std::string& name, const auto& names) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

// One Google Benchmark entry per tool size, named tool_sizes/TOOL, for ci/bench to merge and
// bench/budget_gate.py to read (bench/budgets.json): the tets made per cut and the cut times (p99,
// max) over the three meshes' cuts pooled, the worst created tet, and the counts that must stay 0.
bool write_gate(const std::string& path, const std::vector<Row>& rows, int sweeps, std::uint64_t seed) {
  nlohmann::json benchmarks = nlohmann::json::array();
  for (const char* tool : kGatedTools) {
    std::vector<double> made, cut_us;
    std::uint64_t cuts = 0, refused = 0, violations = 0, left = 0, beyond = 0, lowered = 0, max_made = 0;
    inv::QualityStats created;
    for (const Row& r : rows) {
      if (r.tool != tool) continue;
      made.insert(made.end(), r.made.begin(), r.made.end());
      cut_us.insert(cut_us.end(), r.cut_us.begin(), r.cut_us.end());
      cuts += r.cuts;
      refused += r.refused;
      violations += r.violations;
      left += r.left;
      beyond += r.beyond_reach;
      lowered += r.theta_lowered;
      max_made = std::max(max_made, r.max_created);
      inv::pool(created, r.created);
    }
    const std::string name = std::string("tool_sizes/") + tool;
    nlohmann::json entry = {{"name", name},
                            {"run_name", name},
                            {"run_type", "iteration"},
                            {"cuts", cuts},
                            {"refused", refused},
                            {"checker_violations", violations},
                            {"cuts_leaving_tissue", left},
                            {"tets_removed_beyond_reach", beyond},
                            {"cuts_lowering_theta", lowered},
                            {"made_max", max_made}};
    // No cut, no percentile and no worst tet: those figures are left out, and the gate says they
    // are missing.
    if (!made.empty()) entry["made_p99"] = tetcut::percentile(made, 0.99);
    if (!cut_us.empty()) {
      entry["p99_us"] = tetcut::percentile(cut_us, 0.99);
      entry["max_us"] = max_of(cut_us);
    }
    if (created.tets) {
      entry["worst_created_radius_ratio"] = created.min_radius_ratio;
      entry["worst_created_min_dihedral_deg"] = created.min_dihedral_deg;
    }
    benchmarks.push_back(std::move(entry));
  }
  // And tool_sizes/all: the counts that must stay 0, summed over every tool.
  nlohmann::json all = {{"name", "tool_sizes/all"}, {"run_name", "tool_sizes/all"}, {"run_type", "iteration"}};
  for (const char* count :
       {"cuts", "refused", "checker_violations", "cuts_leaving_tissue", "tets_removed_beyond_reach", "cuts_lowering_theta"}) {
    std::uint64_t sum = 0;
    for (const nlohmann::json& entry : benchmarks) sum += entry[count].get<std::uint64_t>();
    all[count] = sum;
  }
  benchmarks.push_back(std::move(all));
  const nlohmann::json out = {
      {"context", {{"source", "tetcut_quality_sweeps --gate"}, {"sweeps_per_tool", sweeps}, {"seed", seed}}},
      {"benchmarks", std::move(benchmarks)}};
  return tetcut::write_file_atomically(path, out.dump(1) + "\n").ok;
}

}  // namespace

int main(int argc, char** argv) {
  int sweeps = 4;
  std::uint64_t seed = 29;
  std::string only, only_tool, json, refinement = "auto";
  double min_dihedral = tetcut::CutParams{}.min_dihedral_deg;
  CLI::App app{"random cautery sweeps on meshes from TetGen and CGAL: the tets the cuts create"};
  app.add_option("--sweeps", sweeps, "sweeps per mesh and tool")->check(CLI::Range(1, 1000));
  app.add_option("--seed", seed, "the chords' random seed");
  app.add_option("--only", only, "one mesh: box-coarse, box-fine, box-delaunay, cylinder, sphere, liver-6k, liver-16k");
  app.add_option("--tool", only_tool, "one tool: 4%, 8%, 12%, 0.05x, 0.1x, 0.3x, 1x, 3x (x the median edge)");
  app.add_option("--refinement", refinement, "the refinement rule: auto (the engine's default), paper (3.2) or graded");
  app.add_option("--min-dihedral", min_dihedral, "the dihedral floor theta, degrees (CutParams::min_dihedral_deg)")
      ->check(CLI::Range(0.0, 70.0));
  app.add_option("--json", json, "also write the rows to FILE");
  std::string gate;
  app.add_option("--gate", gate,
                 "only the tool-size gate's meshes (box-fine, sphere, liver-16k) and tools (0.05x to 3x), and write "
                 "their figures per tool, pooled over the meshes, to FILE (Google Benchmark JSON for ci/bench)");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  const std::optional<tetcut::RefinementRule> rule = tetcut::parse_refinement_rule(refinement);
  if (!rule) {
    std::fprintf(stderr, "tetcut_quality_sweeps: --refinement %s: must be auto, paper or graded\n", refinement.c_str());
    return 2;
  }

  std::vector<Row> rows;
  bool known = only.empty();
  for (const SourceMesh& source : source_meshes()) {
    if (!only.empty() && source.name != only) continue;
    if (!gate.empty() && !gated(source.name, kGatedMeshes)) continue;
    known = true;
    TetMesh base;
    if (source.make) {
      gen::GenResult made = source.make();
      if (!made.ok()) {
        std::fprintf(stderr, "tetcut_quality_sweeps: %s: %s\n", source.name.c_str(), made.error.c_str());
        return 2;
      }
      tetcut::BuildResult built = tetcut::build_mesh(*made.mesh);
      if (!built.ok()) {
        std::fprintf(stderr, "tetcut_quality_sweeps: %s: not a valid manifold mesh: %s\n", source.name.c_str(),
                     built.problems.front().message.c_str());
        return 2;
      }
      base = std::move(*built.mesh);
    } else {
      base = tetcut::bench::corpus_mesh("liver.msh");
    }
    const tetcut::BoundingBox box = tetcut::bounding_box(base);
    const double diagonal = norm(box.hi - box.lo);
    const double median = median_edge(base);
    const std::vector<Tool> tools = {{"4%", 0.04 * diagonal},    {"8%", 0.08 * diagonal},   {"12%", 0.12 * diagonal},
                                     {"0.05x", 0.05 * median}, {"0.1x", 0.1 * median}, {"0.3x", 0.3 * median},
                                     {"1x", median},           {"3x", 3 * median}};
    for (const Tool& tool : tools)
      if ((only_tool.empty() || tool.name == only_tool) && (gate.empty() || gated(tool.name, kGatedTools)))
        rows.push_back(sweep(source, base, tool, sweeps, seed, *rule, min_dihedral));
  }
  if (!known) {
    std::fprintf(stderr, "tetcut_quality_sweeps: --only %s: no such mesh\n", only.c_str());
    return 2;
  }
  if (rows.empty() && !only_tool.empty()) {
    std::fprintf(stderr, "tetcut_quality_sweeps: --tool %s: no such tool\n", only_tool.c_str());
    return 2;
  }
  print(rows);
  if (!json.empty() && !write_json(json, rows, sweeps, seed, *rule, min_dihedral)) {
    std::fprintf(stderr, "tetcut_quality_sweeps: cannot write %s\n", json.c_str());
    return 2;
  }
  if (!gate.empty() && !write_gate(gate, rows, sweeps, seed)) {
    std::fprintf(stderr, "tetcut_quality_sweeps: cannot write %s\n", gate.c_str());
    return 2;
  }
  const bool clean = std::all_of(rows.begin(), rows.end(), [](const Row& r) { return r.violations == 0 && r.goal_met(); });
  return clean ? 0 : 1;
}
