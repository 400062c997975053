// One side of the paired wall-time comparison (bench/paired_gate.py, `ci/bench --paired`): the
// gated sweep on the bundled liver and on the liver refined twice (~1M tets), timed cut by cut and
// stage by stage (CutReport::time), one round each time the comparison asks for it.
//
//   paired_sweep MESH_DIR [--small-only]
//
// Reads MESH_DIR/liver.raw and MESH_DIR/liver-1M.raw (written by paired_meshes, raw_mesh_file.hpp),
// prints "ready", then for each line "run" on its input sweeps the 1M liver once, then the liver
// once untimed and 5 times timed (each sweep from the mesh as read), and prints one line of JSON:
// per mesh, the p50 and p99 of the cut and of each stage over the round's timed cuts, in
// microseconds. Ends at "quit" or the end of its input. The liver's sweep is short (252 cuts of
// tens of microseconds), so a round pools five of them, after one that brings the liver back into
// the caches the 1M sweep emptied: a p50 over 1,260 warm cuts moves less from one round to the
// next, and the pairs' ratios are tighter for it (a 10 % slowdown of a stage on the liver is what
// its 5 % limit must catch).
//
// It uses only the engine's public API, so that the same source builds against the engine of an
// older commit (bench/paired/CMakeLists.txt): the reference of the comparison is that commit's
// engine driven by this harness, with this harness's meshes and sweep. The comparison starts both
// sides afresh for each pair and they take turns, so that each round of one is next in time to a
// round of the other and no side keeps one address layout for every pair.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "gated_sweep.hpp"
#include "raw_mesh_file.hpp"
#include "tetcut/cut.hpp"
#include "tetcut/mesh_builder.hpp"
#include "tetcut/percentile.hpp"

namespace {

using Clock = std::chrono::steady_clock;

// A mesh and its Cutter, kept for the whole run: each round assigns the mesh back to its base and
// resets the Cutter (Cutter::reset, a new index), so that a round does not fault in a new copy of
// a million tets and a new Cutter's arrays (most of a round's time otherwise, and none of it timed).
struct Sweep {
  Sweep(const char* n, int w, int r, tetcut::TetMesh b, double tool)
      : name(n), warm_ups(w), repeats(r), base(std::move(b)), mesh(base), cutter(mesh, {.tool_diameter = tool}) {}
  const char* name;      // the prefix of its figures in the JSON line
  int warm_ups;          // untimed sweeps a round starts with
  int repeats;           // timed sweeps a round pools
  tetcut::TetMesh base;  // as read
  tetcut::TetMesh mesh;  // what the rounds cut
  tetcut::Cutter cutter;
};

// Per-cut samples, in microseconds: the whole cut as its caller times it, and each stage as the
// CutReport times it (CutTimings) over the cuts that met tissue, the ones whose stages ran.
struct Samples {
  std::vector<double> cut, locate, refine, select, remove, improve, finish;
};

// One sweep from the mesh as read, its samples added to `s`.
void sweep_once(Sweep& sweep, const std::vector<tetcut::Vec3>& centres, Samples& s) {
  sweep.mesh = sweep.base;
  sweep.cutter.reset();
  tetcut::Cutter& cutter = sweep.cutter;
  for (const tetcut::Vec3& c : centres) {
    const Clock::time_point t0 = Clock::now();
    const tetcut::CutReport r = cutter.cut(c);
    const Clock::time_point t1 = Clock::now();
    s.cut.push_back(std::chrono::duration<double, std::micro>(t1 - t0).count());
    if (r.tets_hit == 0) continue;
    s.locate.push_back(r.time.locate_us);
    s.refine.push_back(r.time.refine_us);
    s.select.push_back(r.time.select_us);
    s.remove.push_back(r.time.remove_us);
    s.improve.push_back(r.time.improve_us);
    s.finish.push_back(r.time.finish_us);
  }
}

Samples round_of(Sweep& sweep, const std::vector<tetcut::Vec3>& centres) {
  Samples s;
  for (int i = 0; i < sweep.warm_ups; ++i) sweep_once(sweep, centres, s);
  s = Samples{};
  for (int i = 0; i < sweep.repeats; ++i) sweep_once(sweep, centres, s);
  return s;
}

void print_figures(const char* prefix, const Samples& s, bool& first) {
  const std::pair<const char*, const std::vector<double>*> series[] = {
      {"cut", &s.cut},         {"locate", &s.locate},   {"refine", &s.refine}, {"select", &s.select},
      {"remove", &s.remove}, {"improve", &s.improve}, {"finish", &s.finish}};
  for (const auto& [name, samples] : series)
    for (const auto& [q, label] : {std::pair{0.50, "p50"}, std::pair{0.99, "p99"}}) {
      std::printf("%s\"%s %s %s\": %.4f", first ? "" : ", ", prefix, name, label, tetcut::percentile(*samples, q));
      first = false;
    }
}

tetcut::TetMesh load(const std::string& path) {
  std::string error;
  std::optional<tetcut::RawMesh> raw = tetcut::bench::read_raw_mesh_file(path, error);
  if (!raw) {
    std::fprintf(stderr, "paired_sweep: %s\n", error.c_str());
    std::exit(2);
  }
  tetcut::BuildResult built = tetcut::build_mesh(*raw);
  if (!built.ok()) {
    std::fprintf(stderr, "paired_sweep: %s does not build\n", path.c_str());
    std::exit(2);
  }
  return std::move(*built.mesh);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2 || (argc == 3 && std::string(argv[2]) != "--small-only") || argc > 3) {
    std::fprintf(stderr, "usage: paired_sweep MESH_DIR [--small-only]\n");
    return 2;
  }
  const std::string dir = argv[1];
  // Not moved once made: each Cutter holds a reference to its mesh.
  std::vector<std::unique_ptr<Sweep>> sweeps;
  // The liver refined twice: its edges are a quarter of the bundled liver's, and so is the tool.
  if (argc == 2)
    sweeps.push_back(std::make_unique<Sweep>("1M", 0, 1, load(dir + "/liver-1M.raw"), tetcut::bench::kGatedToolDiameter / 4));
  sweeps.push_back(std::make_unique<Sweep>("16k", 1, 5, load(dir + "/liver.raw"), tetcut::bench::kGatedToolDiameter));
  const std::vector<tetcut::Vec3> centres = tetcut::bench::gated_sweep_centres();
  std::printf("ready\n");
  std::fflush(stdout);
  std::string line;
  while (std::getline(std::cin, line) && line == "run") {
    bool first = true;
    std::printf("{");
    for (const auto& sweep : sweeps) print_figures(sweep->name, round_of(*sweep, centres), first);
    std::printf("}\n");
    std::fflush(stdout);
  }
  return 0;
}
