// Every engine adapter (tetcut/harness/engine.h) on the same cuts, interleaved cut by cut in one
// process: the fair side-by-side figures of docs/engines.md and docs/results.md.
//
//   engines_compare [--mesh M] [--cuts N] [--json FILE] [--gate FILE] ADAPTER.so...
//
// --gate FILE writes the same figures as Google Benchmark runs named engines/<adapter> (ci/bench
// merges them into its results, and bench/budgets.json bounds tetcut's ratios and its own
// correctness on them).
//
// The cuts are the gated sweep (bench/gated_sweep.hpp: 252 balls of 8 mm across the 16k liver),
// the first N of them with --cuts. Cut k is made by every approach before cut k + 1 is made by
// any, the approach that goes first rotating with k, so that a slow stretch of the machine falls
// on all of them alike. Per approach:
//   - the time of the adapter's cut call alone (steady_clock), p50 and p99 over the cuts;
//   - tets removed and created per cut (its change log; without one, only the net change of the
//     live tets is known);
//   - volume removed per cut, and the part of it outside the tool: the drop of the mesh's volume,
//     less the drop of its volume inside the tool's ball (each tet's share of the ball measured on
//     its 64 equal children of two midpoint subdivisions: a resolution of 1/64 of a tet that
//     straddles the ball's surface);
//   - the volume still inside the tool after its cut: what the approach left of the tissue asked
//     for (a refusal leaves it all);
//   - the full check after every cut, the same for every approach: the cuts that left more
//     singular vertices (I5), singular edges (I6) or flat or inverted tets (I4) than there were
//     before them, and how many of each are left at the end, with the worst tet's smallest
//     dihedral angle and radius ratio then;
//   - the ratios tetcut / approach: per cut (p50 over p50) and per volume removed (p50 per mm3
//     removed, over the same of the approach).
// The checks and measurements are outside the timed call.
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "gated_sweep.hpp"
#include "tetcut/harness/engine_library.hpp"
#include "tetcut/invariants/check.hpp"
#include "tetcut/io.hpp"
#include "tetcut/percentile.hpp"

namespace {

using tetcut::Vec3;
using tetcut::harness::EngineChanges;
using tetcut::harness::EngineInstance;
using tetcut::harness::EngineLibrary;
using tetcut::harness::EngineMesh;
namespace inv = tetcut::invariants;
using Clock = std::chrono::steady_clock;
using Tet = std::array<Vec3, 4>;

double tet_volume(const Tet& t) {
  return std::abs(dot(t[1] - t[0], cross(t[2] - t[0], t[3] - t[0]))) / 6.0;
}

Vec3 midpoint(const Vec3& a, const Vec3& b) { return 0.5 * (a + b); }

// The share of tet `t` inside the ball, on its 8^levels equal children (midpoint subdivision).
double share_inside(const Tet& t, const Vec3& centre, double r2, int levels) {
  auto inside = [&](const Vec3& p) { return dot(p - centre, p - centre) <= r2; };
  if (levels == 0) return inside(0.25 * (t[0] + t[1] + t[2] + t[3])) ? 1.0 : 0.0;
  const Vec3 m01 = midpoint(t[0], t[1]), m02 = midpoint(t[0], t[2]), m03 = midpoint(t[0], t[3]);
  const Vec3 m12 = midpoint(t[1], t[2]), m13 = midpoint(t[1], t[3]), m23 = midpoint(t[2], t[3]);
  const Tet children[8] = {{t[0], m01, m02, m03}, {m01, t[1], m12, m13}, {m02, m12, t[2], m23},
                           {m03, m13, m23, t[3]}, {m01, m02, m03, m13}, {m01, m02, m12, m13},
                           {m02, m03, m13, m23},  {m02, m12, m13, m23}};
  double share = 0;
  for (const Tet& c : children) share += share_inside(c, centre, r2, levels - 1) / 8;
  return share;
}

// The mesh's volume, and its volume inside the ball.
struct Volumes {
  double total = 0, in_tool = 0;
};

Volumes volumes(const EngineMesh& mesh, const Vec3& centre, double radius) {
  Volumes v;
  const double r2 = radius * radius;
  for (const auto& ids : mesh.tets) {
    if (ids[0] == tetcut::kDeadTetMarker) continue;
    const Tet t{mesh.positions[ids[0]], mesh.positions[ids[1]], mesh.positions[ids[2]], mesh.positions[ids[3]]};
    const double volume = tet_volume(t);
    v.total += volume;
    int corners_inside = 0;
    double far = 0;
    for (const Vec3& p : t) {
      const double d2 = dot(p - centre, p - centre);
      corners_inside += d2 <= r2 ? 1 : 0;
      far = std::max(far, d2);
    }
    if (corners_inside == 4) {
      v.in_tool += volume;  // the ball is convex
      continue;
    }
    // Disjoint when the tet's bounding sphere about its centroid misses the ball.
    const Vec3 c = 0.25 * (t[0] + t[1] + t[2] + t[3]);
    double reach2 = 0;
    for (const Vec3& p : t) reach2 = std::max(reach2, dot(p - c, p - c));
    const double gap = std::sqrt(dot(c - centre, c - centre)) - std::sqrt(reach2);
    if (gap > radius) continue;
    v.in_tool += volume * share_inside(t, centre, r2, 2);
  }
  return v;
}

// Singular vertices and edges and flat or inverted tets in a full check's report.
std::uint64_t count_broken(const inv::CheckReport& report) {
  std::uint64_t n = 0;
  for (inv::Invariant id : {inv::Invariant::kI4Orientation, inv::Invariant::kI5VertexShell, inv::Invariant::kI6EdgeShell}) {
    if (const inv::Violation* v = report.find(id)) n += v->count;
  }
  return n;
}

struct Approach {
  std::unique_ptr<EngineLibrary> library;
  std::unique_ptr<EngineInstance> engine;
  std::uint64_t broken = 0;  // count_broken() after the last cut
  std::vector<double> times_us;
  std::uint64_t removed = 0, created = 0, refused = 0, objections = 0;  // removed, created: change log only
  double net_tets = 0;  // live tets after the cuts less before, whatever the log
  std::optional<std::size_t> first_objection;
  double volume_removed = 0, volume_outside = 0, volume_left = 0;
  inv::CheckReport final_check;
};

}  // namespace

int main(int argc, char** argv) {
  std::string mesh_path = std::string(TETCUT_CORPUS_DIR) + "/meshes/liver.msh";
  std::size_t max_cuts = 0;
  std::string json_path, gate_path;
  std::vector<std::string> adapters;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--mesh" && i + 1 < argc) {
      mesh_path = argv[++i];
    } else if (arg == "--cuts" && i + 1 < argc) {
      max_cuts = std::stoul(argv[++i]);
    } else if (arg == "--json" && i + 1 < argc) {
      json_path = argv[++i];
    } else if (arg == "--gate" && i + 1 < argc) {
      gate_path = argv[++i];
    } else if (!arg.empty() && arg[0] != '-') {
      adapters.push_back(arg);
    } else {
      std::fprintf(stderr, "usage: engines_compare [--mesh M] [--cuts N] [--json FILE] [--gate FILE] ADAPTER.so...\n");
      return 2;
    }
  }
  if (adapters.empty()) {
    std::fprintf(stderr, "engines_compare: no adapter given\n");
    return 2;
  }
  tetcut::ReadResult read = tetcut::read_mesh(mesh_path);
  if (!read.mesh) {
    std::fprintf(stderr, "engines_compare: %s\n", read.error->message().c_str());
    return 2;
  }
  std::vector<Vec3> centres = tetcut::bench::gated_sweep_centres();
  if (max_cuts > 0 && max_cuts < centres.size()) centres.resize(max_cuts);
  const double diameter = tetcut::bench::kGatedToolDiameter;

  std::vector<Approach> approaches(adapters.size());
  try {
    for (std::size_t a = 0; a < adapters.size(); ++a) {
      approaches[a].library = std::make_unique<EngineLibrary>(adapters[a]);
      approaches[a].engine = std::make_unique<EngineInstance>(*approaches[a].library, *read.mesh);
      approaches[a].engine->read("create");
    }
    for (std::size_t k = 0; k < centres.size(); ++k) {
      const std::string name = "cut " + std::to_string(k + 1);
      for (std::size_t turn = 0; turn < approaches.size(); ++turn) {
        Approach& ap = approaches[(k + turn) % approaches.size()];
        const Volumes before = volumes(ap.engine->last_read(), centres[k], diameter / 2);
        const std::size_t tets_before = ap.engine->last_read().tets.size();
        const std::uint64_t live_before = ap.engine->last_read().live_tets;
        const auto start = Clock::now();
        const auto status = ap.engine->cut(centres[k], std::nullopt, diameter, name);
        ap.times_us.push_back(std::chrono::duration<double, std::micro>(Clock::now() - start).count());
        if (status == tetcut::harness::EngineStatus::kRefused) ++ap.refused;
        const EngineMesh& mesh = ap.engine->read(name);
        const Volumes after = volumes(mesh, centres[k], diameter / 2);
        ap.volume_removed += before.total - after.total;
        ap.volume_outside += (before.total - after.total) - (before.in_tool - after.in_tool);
        ap.volume_left += after.in_tool;
        if (ap.library->has(TETCUT_ENGINE_CHANGE_LOG)) {
          const EngineChanges changes = ap.engine->changes(tets_before, name);
          ap.removed += changes.removed.size();
          ap.created += changes.created.size();
        }
        ap.net_tets += static_cast<double>(mesh.live_tets) - static_cast<double>(live_before);
        // The full check for every approach, so that "objected" means the same for all: the cut
        // made more singular vertices, singular edges or flat tets than the mesh had before it.
        inv::CheckOptions options;
        options.operation = name;
        const inv::CheckReport report = inv::check_raw(mesh.view(), options);
        const std::uint64_t broken = count_broken(report);
        if (broken > ap.broken) {
          ++ap.objections;
          if (!ap.first_objection) ap.first_objection = k + 1;
        }
        ap.broken = broken;
      }
    }
    for (Approach& ap : approaches) ap.final_check = inv::check_raw(ap.engine->last_read().view());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "engines_compare: %s\n", e.what());
    return 1;
  }

  const double cuts = static_cast<double>(centres.size());
  nlohmann::ordered_json doc = {{"mesh", mesh_path}, {"cuts", centres.size()}, {"tool_diameter", diameter}};
  doc["approaches"] = nlohmann::ordered_json::array();
  const Approach* tetcut = nullptr;
  for (const Approach& ap : approaches) {
    if (ap.library->name() == "tetcut") tetcut = &ap;
  }
  auto p50 = [](const Approach& ap) { return tetcut::percentile(ap.times_us, 0.5); };
  std::printf("%-12s %9s %9s %8s %8s %10s %10s %10s %6s %6s %6s %8s %8s\n", "approach", "p50 us", "p99 us",
              "rem/cut", "net/cut", "mm3/cut", "out mm3", "left mm3", "objec", "sing V", "sing E", "x/cut", "x/mm3");
  for (const Approach& ap : approaches) {
    auto count = [&](inv::Invariant id) {
      const inv::Violation* v = ap.final_check.find(id);
      return v != nullptr ? v->count : 0;
    };
    const double per_cut = p50(ap);
    const bool has_log = ap.library->has(TETCUT_ENGINE_CHANGE_LOG);
    const double per_volume = per_cut / std::max(ap.volume_removed / cuts, 1e-300);
    nlohmann::ordered_json j = {
        {"name", ap.library->name()},
        {"version", ap.library->version()},
        {"capabilities", tetcut::harness::capability_names(ap.library->api().capabilities)},
        {"p50_us", per_cut},
        {"p99_us", tetcut::percentile(ap.times_us, 0.99)},
        {"tets_removed_per_cut", has_log ? nlohmann::ordered_json(ap.removed / cuts) : nullptr},
        {"tets_created_per_cut", has_log ? nlohmann::ordered_json(ap.created / cuts) : nullptr},
        {"net_tets_per_cut", ap.net_tets / cuts},
        {"volume_removed_per_cut", ap.volume_removed / cuts},
        {"volume_outside_tool_per_cut", ap.volume_outside / cuts},
        {"volume_left_in_tool_per_cut", ap.volume_left / cuts},
        {"refused", ap.refused},
        {"cuts_objected", ap.objections},
        {"first_objection", ap.first_objection ? nlohmann::ordered_json(*ap.first_objection) : nullptr},
        {"singular_vertices", count(inv::Invariant::kI5VertexShell)},
        {"singular_edges", count(inv::Invariant::kI6EdgeShell)},
        {"inverted_tets", count(inv::Invariant::kI4Orientation)},
        {"final_min_dihedral_deg", ap.final_check.quality.min_dihedral_deg},
        {"final_min_radius_ratio", ap.final_check.quality.min_radius_ratio}};
    if (tetcut != nullptr) {
      const double tetcut_per_volume = p50(*tetcut) / std::max(tetcut->volume_removed / cuts, 1e-300);
      j["ratio_per_cut"] = p50(*tetcut) / per_cut;
      j["ratio_per_volume"] = tetcut_per_volume / per_volume;
    }
    std::printf("%-12s %9.1f %9.1f %8.2f %8.2f %10.1f %10.1f %10.1f %6llu %6llu %6llu %8.3g %8.3g\n",
                ap.library->name().c_str(), per_cut, j["p99_us"].get<double>(), has_log ? ap.removed / cuts : NAN,
                ap.net_tets / cuts,
                ap.volume_removed / cuts, ap.volume_outside / cuts, ap.volume_left / cuts,
                static_cast<unsigned long long>(ap.objections),
                static_cast<unsigned long long>(count(inv::Invariant::kI5VertexShell)),
                static_cast<unsigned long long>(count(inv::Invariant::kI6EdgeShell)),
                j.value("ratio_per_cut", 0.0), j.value("ratio_per_volume", 0.0));
    doc["approaches"].push_back(j);
  }
  // As Google Benchmark runs, for the gate: one per approach, its figures as fields.
  nlohmann::ordered_json gate = {{"benchmarks", nlohmann::ordered_json::array()}};
  for (const auto& a : doc["approaches"]) {
    nlohmann::ordered_json run = {{"name", "engines/" + a["name"].get<std::string>()},
                                  {"run_name", "engines/" + a["name"].get<std::string>()},
                                  {"run_type", "iteration"}};
    for (const auto& [field, value] : a.items()) {
      if (value.is_number()) run[field] = value;
    }
    gate["benchmarks"].push_back(run);
  }
  for (const auto& [path, content] : {std::pair{json_path, &doc}, std::pair{gate_path, &gate}}) {
    if (path.empty()) continue;
    const std::string temporary = path + ".tmp";
    std::ofstream(temporary) << content->dump(2) << "\n";
    if (std::rename(temporary.c_str(), path.c_str()) != 0) {
      std::fprintf(stderr, "engines_compare: cannot write %s\n", path.c_str());
      return 1;
    }
  }
  return 0;
}
