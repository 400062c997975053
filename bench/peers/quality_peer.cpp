// tetcut_quality_peer: the shape of the tets tetcut's cuts create, beside what CGAL's
// tetrahedral_isotropic_remeshing makes of the same cells after the same cut.
//
//   tetcut_quality_peer [--cuts N] [--every K] [--rings R] [--iterations N] [--improve on|off]
//                       [--json FILE]
//
// The gated sweep (bench/gated_sweep.hpp: the bundled 16k liver, tool 8 mm, 252 cuts), default
// CutParams (--improve off: without the improvement pass, what the paper's algorithm alone hands
// CGAL), runs twice on fresh copies of the mesh:
//   1. timing: every cut timed alone, nothing else in the loop (the gate's measurement, without its
//      cache eviction before the first cut);
//   2. quality: after every cut, the tets it created (Cutter::last_created()) measured; after
//      every K-th cut that created tets (K = 1: all of them), the mesh as the cut left it goes to
//      CGAL (cgal_peer.hpp), the created tets and their face neighbours selected, and CGAL
//      remeshes the selection with the mesh surface and the selection's boundary kept; the
//      selection is measured before (tetcut's cells) and after (CGAL's).
//
// What CGAL loads (--rings): CGAL's remeshing makes passes over its whole triangulation whatever
// the selection (it tests every edge's length before splitting, gathers every vertex before
// smoothing, flips over every edge), so its time grows with what it is given, not with the
// selection. By default (R = 0) it gets the selection alone, closed into a manifold part
// (neighbourhood.hpp): the least it needs, so its times are the most generous to it, and what it
// makes of the selection is what it makes with the whole mesh loaded (its operations only touch
// selected cells, and their boundary is kept either way; the order in which CGAL visits them
// follows what was loaded, so a cut here and there differs by a cell). R = -1 loads the whole
// mesh (~16k cells, seconds per cut): what a CGAL user holding the mesh pays; use K to sample.
// Every tet set is measured by the independent checker (tet_set_quality.hpp). Prints a table of
// the sampled cuts and a summary; --json writes the same (keys below, in write_json()).
//
// Exit 0; 1 when CGAL's output is not a valid mesh region (a cell not positive by the exact
// predicate, a figure not finite, the region's volume changed, a vertex it was told to keep
// moved) or CGAL refused the mesh; 2 on bad arguments.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "bench_meshes.hpp"
#include "cgal_peer.hpp"
#include "gated_sweep.hpp"
#include "neighbourhood.hpp"
#include "tet_set_quality.hpp"
#include "tetcut/cut.hpp"

namespace {

using tetcut::TetId;
using tetcut::peers::TetSetQuality;
using Tet = std::array<std::uint32_t, 4>;

struct Options {
  std::size_t cuts = 0;  // 0: the whole sweep
  std::size_t every = 1;
  unsigned iterations = 1;
  int rings = 0;  // CGAL loads the selection and this many rings of tets around it; -1: the whole mesh
  bool improve = true;  // CutParams::improve
  std::string json;
};

struct CgalFigures {
  std::uint32_t selected = 0, loaded = 0;
  TetSetQuality before, after;  // the selection as tetcut left it, and as CGAL remeshed it
  double target_edge = 0, load_ms = 0, remesh_ms = 0;
  std::uint32_t frozen = 0, frozen_moved = 0;
  std::string error;  // CGAL refused the mesh or the selection

  // CGAL's cells positive, measurable, the region's volume kept (they tile what they replaced),
  // no vertex it was told to keep moved.
  [[nodiscard]] bool valid() const {
    return error.empty() && after.valid() && frozen_moved == 0 && volume_kept();
  }
  [[nodiscard]] bool volume_kept() const {
    return std::abs(after.volume - before.volume) <= kVolumeRelTolerance * std::abs(before.volume);
  }
  // The checker's default I9 tolerance: rounding of a few hundred tet volumes is far below it.
  static constexpr double kVolumeRelTolerance = 1e-9;
};

struct CutRow {
  std::size_t index = 0;
  tetcut::Vec3 centre;
  double tetcut_us = 0;
  std::uint32_t removed = 0, created = 0;
  bool ok = true;
  TetSetQuality created_quality;
  bool sampled = false;
  CgalFigures cgal;
};

// Nearest rank, as cut_bench reports its percentiles.
double percentile(std::vector<double> v, double q) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const auto rank = static_cast<std::size_t>(std::ceil(q * static_cast<double>(v.size())));
  return v[std::min(v.size() - 1, rank == 0 ? 0 : rank - 1)];
}

double ms_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// Pass 1: every cut of the sweep timed alone.
std::vector<double> time_cuts(const std::vector<tetcut::Vec3>& centres, const Options& options) {
  tetcut::TetMesh mesh = tetcut::bench::corpus_mesh("liver.msh");
  tetcut::Cutter cutter(mesh, {.tool_diameter = tetcut::bench::kGatedToolDiameter, .improve = options.improve});
  std::vector<double> us;
  us.reserve(centres.size());
  for (const tetcut::Vec3& c : centres) {
    const auto start = std::chrono::steady_clock::now();
    cutter.cut(c);
    us.push_back(ms_since(start) * 1000.0);
  }
  return us;
}

// The cut's created tets and their live face neighbours, as TetIds, each once, in id order.
std::vector<TetId> selection_of(const tetcut::TetMesh& mesh, const std::vector<TetId>& created) {
  std::vector<TetId> out(created.begin(), created.end());
  for (TetId t : created)
    for (int f = 0; f < 4; ++f)
      if (const tetcut::FaceRef n = mesh.neighbour(t, f); n.valid()) out.push_back(n.tet);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::vector<Tet> verts_of(const tetcut::TetMesh& mesh, const std::vector<TetId>& tets) {
  std::vector<Tet> out;
  out.reserve(tets.size());
  for (TetId t : tets) out.push_back(mesh.raw_tets()[t.value]);
  return out;
}

CgalFigures remesh_in_cgal(const tetcut::TetMesh& mesh, const std::vector<TetId>& created, const Options& options) {
  CgalFigures out;
  const std::vector<TetId> selection = selection_of(mesh, created);
  out.selected = static_cast<std::uint32_t>(selection.size());
  out.before = tetcut::peers::measure_quality(mesh.positions(), verts_of(mesh, selection));

  // The whole mesh when the neighbourhood does not settle into a manifold part (not seen so far).
  std::optional<std::vector<TetId>> part = tetcut::peers::manifold_neighbourhood(mesh, selection, options.rings);
  if (!part) part = tetcut::peers::manifold_neighbourhood(mesh, selection, -1);
  const std::vector<TetId>& loaded = *part;
  out.loaded = static_cast<std::uint32_t>(loaded.size());
  tetcut::peers::CgalTetMesh cgal;
  const tetcut::peers::CgalLoadResult load = cgal.load(mesh.positions(), verts_of(mesh, loaded));
  out.load_ms = load.seconds * 1000.0;
  if (!load.ok) {
    out.error = load.error;
    return out;
  }
  std::vector<std::uint32_t> cells;  // the selection's places in `loaded` (both sorted)
  for (TetId t : selection)
    cells.push_back(static_cast<std::uint32_t>(std::lower_bound(loaded.begin(), loaded.end(), t) - loaded.begin()));
  const tetcut::peers::RemeshResult remeshed = cgal.remesh(cells, {.iterations = options.iterations});
  if (!remeshed.ok) {
    out.error = remeshed.error;
    return out;
  }
  out.remesh_ms = remeshed.seconds * 1000.0;
  out.target_edge = remeshed.target_edge_length;
  out.frozen = remeshed.frozen_vertices;
  out.frozen_moved = remeshed.frozen_vertices_moved;
  out.after = tetcut::peers::measure_quality(remeshed.region.positions, remeshed.region.tets);
  return out;
}

// Pass 2: the sweep again, each cut's created tets measured, every `every`-th cut that created
// tets handed to CGAL.
std::vector<CutRow> compare_cuts(const std::vector<tetcut::Vec3>& centres, const Options& options) {
  tetcut::TetMesh mesh = tetcut::bench::corpus_mesh("liver.msh");
  tetcut::Cutter cutter(mesh, {.tool_diameter = tetcut::bench::kGatedToolDiameter, .improve = options.improve});
  std::vector<CutRow> rows;
  std::size_t creating = 0;
  for (std::size_t i = 0; i < centres.size(); ++i) {
    CutRow row{.index = i, .centre = centres[i]};
    const tetcut::CutReport report = cutter.cut(centres[i]);
    row.ok = report.ok;
    row.removed = report.tets_removed;
    row.created = report.tets_created;
    const std::vector<TetId>& created = cutter.last_created();
    row.created_quality = tetcut::peers::measure_quality(mesh.positions(), verts_of(mesh, created));
    if (!created.empty() && creating++ % options.every == 0) {
      row.sampled = true;
      row.cgal = remesh_in_cgal(mesh, created, options);
    }
    rows.push_back(row);
  }
  return rows;
}

// The worst (smallest) figure over rows, and the median of the per-cut worst.
struct Spread {
  double worst = 0, median = 0;
};
template <class Get>
Spread spread(const std::vector<CutRow>& rows, bool sampled_only, Get get) {
  std::vector<double> v;
  for (const CutRow& r : rows)
    if (r.created_quality.tets > 0 && (!sampled_only || r.sampled)) v.push_back(get(r));
  if (v.empty()) return {};
  return {*std::min_element(v.begin(), v.end()), percentile(v, 0.5)};
}

struct Summary {
  std::size_t cuts = 0, creating = 0, sampled = 0, failed_cuts = 0, invalid_cgal = 0;
  // Sampled cuts whose selection CGAL left with a worse worst tet than tetcut gave it: isotropic
  // remeshing aims at edge lengths, and does not promise the worst tet.
  std::size_t cgal_lowered_rr = 0, cgal_lowered_dihedral = 0;
  Spread tetcut_rr_all, tetcut_dih_all;              // every cut that created tets
  Spread tetcut_rr, tetcut_dih, before_rr, before_dih, cgal_rr, cgal_dih;  // the sampled cuts
  double tetcut_p50_us = 0, tetcut_p99_us = 0;
  double load_p50_ms = 0, load_p99_ms = 0, remesh_p50_ms = 0, remesh_p99_ms = 0;
};

Summary summarise(const std::vector<CutRow>& rows) {
  Summary s;
  std::vector<double> tetcut_us, load_ms, remesh_ms;
  for (const CutRow& r : rows) {
    ++s.cuts;
    s.creating += r.created_quality.tets > 0;
    s.failed_cuts += !r.ok;
    tetcut_us.push_back(r.tetcut_us);
    if (!r.sampled) continue;
    ++s.sampled;
    s.invalid_cgal += !r.cgal.valid();
    s.cgal_lowered_rr += r.cgal.after.min_radius_ratio < r.cgal.before.min_radius_ratio;
    s.cgal_lowered_dihedral += r.cgal.after.min_dihedral_deg < r.cgal.before.min_dihedral_deg;
    load_ms.push_back(r.cgal.load_ms);
    remesh_ms.push_back(r.cgal.remesh_ms);
  }
  s.tetcut_rr_all = spread(rows, false, [](const CutRow& r) { return r.created_quality.min_radius_ratio; });
  s.tetcut_dih_all = spread(rows, false, [](const CutRow& r) { return r.created_quality.min_dihedral_deg; });
  s.tetcut_rr = spread(rows, true, [](const CutRow& r) { return r.created_quality.min_radius_ratio; });
  s.tetcut_dih = spread(rows, true, [](const CutRow& r) { return r.created_quality.min_dihedral_deg; });
  s.before_rr = spread(rows, true, [](const CutRow& r) { return r.cgal.before.min_radius_ratio; });
  s.before_dih = spread(rows, true, [](const CutRow& r) { return r.cgal.before.min_dihedral_deg; });
  s.cgal_rr = spread(rows, true, [](const CutRow& r) { return r.cgal.after.min_radius_ratio; });
  s.cgal_dih = spread(rows, true, [](const CutRow& r) { return r.cgal.after.min_dihedral_deg; });
  s.tetcut_p50_us = percentile(tetcut_us, 0.5);
  s.tetcut_p99_us = percentile(tetcut_us, 0.99);
  s.load_p50_ms = percentile(load_ms, 0.5);
  s.load_p99_ms = percentile(load_ms, 0.99);
  s.remesh_p50_ms = percentile(remesh_ms, 0.5);
  s.remesh_p99_ms = percentile(remesh_ms, 0.99);
  return s;
}

void print_table(const std::vector<CutRow>& rows, const Summary& s, const Options& options) {
  std::printf("tetcut beside CGAL %s tetrahedral_isotropic_remeshing: gated liver sweep, tool %.0f mm, "
              "%zu cuts; CGAL on 1 in %zu of the cuts that created tets (%u iteration%s), loading %s\n",
              tetcut::peers::cgal_version(), tetcut::bench::kGatedToolDiameter, s.cuts, options.every,
              options.iterations, options.iterations == 1 ? "" : "s",
              options.rings < 0 ? "the whole mesh"
                                : (options.rings == 0 ? "the selection" : "the selection and rings around it"));
  std::printf("selection: the cut's created tets and their face neighbours; CGAL keeps the surface and the "
              "selection's boundary\n\n");
  std::printf("%4s %6s %6s | %8s %5s %8s %7s | %5s %8s %7s | %5s %8s %7s %7s %6s %8s %9s\n", "cut", "y", "z",
              "tetcut", "made", "rr", "dih", "sel", "rr", "dih", "cgal", "rr", "dih", "edge", "loaded", "load", "remesh");
  std::printf("%4s %6s %6s | %8s %5s %8s %7s | %5s %8s %7s | %5s %8s %7s %7s %6s %8s %9s\n", "", "", "", "us", "",
              "created", "deg", "", "before", "deg", "cells", "after", "deg", "mm", "cells", "ms", "ms");
  for (const CutRow& r : rows) {
    if (!r.sampled) continue;
    const CgalFigures& c = r.cgal;
    std::printf("%4zu %6.1f %6.1f | %8.1f %5u %8.4f %7.2f | %5u %8.4f %7.2f | %5llu %8.4f %7.2f %7.2f %6u %8.2f %9.2f%s\n",
                r.index, r.centre.y, r.centre.z, r.tetcut_us, r.created, r.created_quality.min_radius_ratio,
                r.created_quality.min_dihedral_deg, c.selected, c.before.min_radius_ratio, c.before.min_dihedral_deg,
                static_cast<unsigned long long>(c.after.tets), c.after.min_radius_ratio, c.after.min_dihedral_deg,
                c.target_edge, c.loaded, c.load_ms, c.remesh_ms, c.valid() ? "" : "  INVALID");
    if (!c.error.empty()) std::printf("     CGAL: %s\n", c.error.c_str());
  }
  std::printf("\n%-44s %10s %10s\n", "worst tet (radius ratio, min dihedral deg)", "worst", "median");
  auto line = [](const char* what, const Spread& rr, const Spread& dih) {
    std::printf("%-44s %10.4f %10.4f   %7.2f %7.2f\n", what, rr.worst, rr.median, dih.worst, dih.median);
  };
  line("tetcut, created, every cut", s.tetcut_rr_all, s.tetcut_dih_all);
  line("tetcut, created, sampled cuts", s.tetcut_rr, s.tetcut_dih);
  line("selection before CGAL (tetcut's cells)", s.before_rr, s.before_dih);
  line("selection after CGAL", s.cgal_rr, s.cgal_dih);
  std::printf("\ntimes: tetcut cut p50 %.1f us p99 %.1f us (all %zu cuts); CGAL load p50 %.1f ms p99 %.1f ms, "
              "remesh p50 %.1f ms p99 %.1f ms (%zu sampled)\n",
              s.tetcut_p50_us, s.tetcut_p99_us, s.cuts, s.load_p50_ms, s.load_p99_ms, s.remesh_p50_ms,
              s.remesh_p99_ms, s.sampled);
  std::printf("CGAL left the selection's worst tet worse than tetcut's in %zu of %zu sampled cuts by radius ratio, "
              "%zu by min dihedral\n",
              s.cgal_lowered_rr, s.sampled, s.cgal_lowered_dihedral);
  if (s.failed_cuts > 0) std::printf("tetcut: %zu cuts rolled back\n", s.failed_cuts);
  if (s.invalid_cgal > 0) std::printf("CGAL: %zu sampled cuts gave an invalid region\n", s.invalid_cgal);
}

nlohmann::json quality_json(const TetSetQuality& q) {
  return {{"tets", q.tets},
          {"min_radius_ratio", q.min_radius_ratio},
          {"min_dihedral_deg", q.min_dihedral_deg},
          {"volume", q.volume},
          {"not_positive", q.not_positive},
          {"unmeasured", q.unmeasured}};
}

nlohmann::json spread_json(const Spread& rr, const Spread& dih) {
  return {{"worst_radius_ratio", rr.worst}, {"median_radius_ratio", rr.median},
          {"worst_min_dihedral_deg", dih.worst}, {"median_min_dihedral_deg", dih.median}};
}

bool write_json(const std::string& path, const std::vector<CutRow>& rows, const Summary& s, const Options& options) {
  nlohmann::json cuts = nlohmann::json::array();
  for (const CutRow& r : rows) {
    nlohmann::json row = {{"cut", r.index},
                          {"centre", {r.centre.x, r.centre.y, r.centre.z}},
                          {"ok", r.ok},
                          {"tetcut_us", r.tetcut_us},
                          {"removed", r.removed},
                          {"created", r.created},
                          {"created_quality", quality_json(r.created_quality)}};
    if (r.sampled) {
      const CgalFigures& c = r.cgal;
      row["cgal"] = {{"selected", c.selected},        {"loaded", c.loaded},
                     {"before", quality_json(c.before)},
                     {"after", quality_json(c.after)}, {"target_edge_length", c.target_edge},
                     {"load_ms", c.load_ms},           {"remesh_ms", c.remesh_ms},
                     {"frozen_vertices", c.frozen},    {"frozen_vertices_moved", c.frozen_moved},
                     {"valid", c.valid()},             {"error", c.error}};
    }
    cuts.push_back(std::move(row));
  }
  const nlohmann::json out = {
      {"mesh", "liver.msh"},
      {"tool_diameter", tetcut::bench::kGatedToolDiameter},
      {"cgal_every", options.every},
      {"cgal_iterations", options.iterations},
      {"cgal_rings", options.rings},
      {"improve", options.improve},
      {"summary",
       {{"cuts", s.cuts},
        {"cuts_creating", s.creating},
        {"cuts_sampled", s.sampled},
        {"cuts_rolled_back", s.failed_cuts},
        {"cgal_invalid", s.invalid_cgal},
        {"cgal_lowered_worst_radius_ratio", s.cgal_lowered_rr},
        {"cgal_lowered_worst_min_dihedral", s.cgal_lowered_dihedral},
        {"tetcut_created_all", spread_json(s.tetcut_rr_all, s.tetcut_dih_all)},
        {"tetcut_created_sampled", spread_json(s.tetcut_rr, s.tetcut_dih)},
        {"selection_before_cgal", spread_json(s.before_rr, s.before_dih)},
        {"selection_after_cgal", spread_json(s.cgal_rr, s.cgal_dih)},
        {"tetcut_p50_us", s.tetcut_p50_us},
        {"tetcut_p99_us", s.tetcut_p99_us},
        {"cgal_load_p50_ms", s.load_p50_ms},
        {"cgal_load_p99_ms", s.load_p99_ms},
        {"cgal_remesh_p50_ms", s.remesh_p50_ms},
        {"cgal_remesh_p99_ms", s.remesh_p99_ms}}},
      {"cuts", std::move(cuts)}};
  std::ofstream file(path);
  file << out.dump(1) << '\n';
  return static_cast<bool>(file);
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  CLI::App app{"tetcut's cuts beside CGAL's remeshing of the same cells"};
  app.add_option("--cuts", options.cuts, "only the first N cuts of the gated sweep (0: all 252)");
  app.add_option("--every", options.every, "hand every K-th cut that created tets to CGAL")->check(CLI::PositiveNumber);
  app.add_option("--iterations", options.iterations, "CGAL's number_of_iterations")->check(CLI::PositiveNumber);
  app.add_option("--rings", options.rings,
                 "CGAL loads the selection and N rings of tets around it (-1: the whole mesh)")
      ->check(CLI::Range(-1, 1000));
  std::string improve = "on";
  app.add_option("--improve", improve, "tetcut's improvement pass (CutParams::improve)")
      ->check(CLI::IsMember({"on", "off"}));
  app.add_option("--json", options.json, "also write the figures to FILE");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  options.improve = improve == "on";

  std::vector<tetcut::Vec3> centres = tetcut::bench::gated_sweep_centres();
  if (options.cuts > 0 && options.cuts < centres.size()) centres.resize(options.cuts);

  const std::vector<double> us = time_cuts(centres, options);
  std::vector<CutRow> rows = compare_cuts(centres, options);
  for (std::size_t i = 0; i < rows.size(); ++i) rows[i].tetcut_us = us[i];
  const Summary summary = summarise(rows);
  print_table(rows, summary, options);
  if (!options.json.empty() && !write_json(options.json, rows, summary, options)) {
    std::fprintf(stderr, "tetcut_quality_peer: cannot write %s\n", options.json.c_str());
    return 2;
  }
  return summary.invalid_cgal == 0 ? 0 : 1;
}
