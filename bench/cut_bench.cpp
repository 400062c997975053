// Per-cut benchmarks: what a simulator feels.
//
// BM_CutSweep/<level> runs a deterministic cautery sweep across the bundled liver (the paths of
// corpus/scenarios/liver-resection.scn, thinned) and times every cut, reporting per-cut p50,
// p90, p99 and max from those samples (every cut, the first included), the first cut on its
// own, cuts per second, tets removed and created, and the heap allocations of the whole sweep
// after the Cutter is constructed (counted by a global operator new).
//
// Levels: 0 = the bundled liver (~16k tets), 1 = its uniform refinement (~126k), 2 = twice
// refined (~1M), 3 = three times (~8M: an organ at a resolution simulators ask for; about 5 GB
// and 20 s of this process, most of it building the mesh and the Cutter, outside the per-cut
// figures). BM_CutScalingSameWork compares the liver with 64 copies of itself instead. The tool diameter shrinks with the edge length (8, 4, 2, 1 mm) so that every cut
// does the same local work: with one tool, the twice-refined liver holds 64 times more tets in
// the same ball and no algorithm could cut it at the same cost. What the ratio of medians then
// measures is what the issue asks: whether the cost grows with the size of the mesh.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <map>
#include <new>
#include <string>
#include <vector>

#include "bench_meshes.hpp"
#include "counting_allocator.hpp"
#include "gated_sweep.hpp"
#include "refined_liver.hpp"
#include "tetcut/cut.hpp"
#include "tetcut/percentile.hpp"

using tetcut::percentile;

namespace {

using tetcut::TetId;

// The liver refined `level` times uniformly (refined_liver.hpp).
const tetcut::TetMesh& liver_at(int level) { return tetcut::bench::refined_corpus_liver(level); }

struct SweepResult {
  std::vector<double> samples_us;  // every cut, the first included
  std::vector<double> first_us;    // the first cut of each sweep
  std::uint64_t removed = 0, created = 0, unresolved = 0, allocations = 0, counted_cuts = 0;
  // The tissue rule's figures: refused cuts, tets left in the tool, tets removed beyond the cut's
  // reach, and per cut that met tissue the volume left in the tool and removed beyond it, as a
  // share of the tool's ball.
  std::uint64_t refused = 0, left_in_tool = 0, beyond_reach = 0;
  std::vector<double> left_share, beyond_share;
  // The angle floor's: the smallest dihedral angle of a tet an ok cut created, and the cuts whose
  // improvement pass held a theta below the params' (CutReport::min_dihedral_held_deg).
  double worst_created_dihedral_deg = 180.0;
  std::uint64_t theta_lowered = 0;
  // The search for the pieces each cut detached (CutTimings::pieces_us), and the pieces.
  std::vector<double> pieces_us;
  std::uint64_t fragments = 0;
};

// Writes and reads back 64 MiB, more than any cache of the CI machine holds, so that nothing of
// the mesh or the Cutter is left in them.
void evict_caches() {
  static std::vector<unsigned char> buffer(std::size_t{64} << 20);
  unsigned sum = 0;
  for (std::size_t i = 0; i < buffer.size(); i += 64) {
    buffer[i] = static_cast<unsigned char>(buffer[i] + 1);
    sum += buffer[i];
  }
  benchmark::DoNotOptimize(sum);
}

// One sweep on a fresh copy of `base` with a tool of `tool_diameter`, every cut timed and its
// heap allocations counted: the Cutter is constructed (and so prepared) before the first cut, and
// a simulator feels the first cut like any other (no warm-up is dropped). The first cut starts
// with the caches emptied, as a simulator's does after loading and rendering; without that it
// depended on what the previous repetition left in them (5-8 us warm against 12-20 us cold in
// one process, and the gate's median of three repetitions mixed the two).
// With `strokes`, the passes are cut by the swept tool (gated_strokes()) instead of balls.
void run_sweep(const tetcut::TetMesh& base, double tool_diameter, SweepResult& out, bool strokes = false) {
  static const std::vector<tetcut::Vec3> centres = tetcut::bench::gated_sweep_centres();
  static const std::vector<tetcut::bench::Stroke> swept = tetcut::bench::gated_strokes();
  tetcut::TetMesh mesh = base;
  tetcut::Cutter cutter(mesh, {.tool_diameter = tool_diameter});
  evict_caches();
  const std::size_t cuts = strokes ? swept.size() : centres.size();
  for (std::size_t i = 0; i < cuts; ++i) {
    const std::uint64_t before = tetcut::bench::allocations();
    const auto t0 = std::chrono::steady_clock::now();
    const tetcut::CutReport r = strokes ? cutter.cut_segment(swept[i].from, swept[i].to) : cutter.cut(centres[i]);
    const auto t1 = std::chrono::steady_clock::now();
    // Read before this loop's own bookkeeping allocates (the sample lists grow).
    out.allocations += tetcut::bench::allocations() - before;
    ++out.counted_cuts;
    out.samples_us.push_back(std::chrono::duration<double, std::micro>(t1 - t0).count());
    if (i == 0) out.first_us.push_back(out.samples_us.back());
    out.removed += r.tets_removed;
    out.created += r.tets_created;
    out.unresolved += r.unresolved;
    out.refused += r.ok ? 0 : 1;
    out.left_in_tool += r.left_in_tool;
    out.beyond_reach += r.tets_removed_beyond_reach;
    if (r.ok) out.worst_created_dihedral_deg = std::min(out.worst_created_dihedral_deg, r.min_dihedral_deg);
    out.pieces_us.push_back(r.time.pieces_us);
    out.fragments += r.fragments;
    out.theta_lowered += r.ok && r.min_dihedral_held_deg < cutter.params().min_dihedral_deg;
    if (r.ok && r.tets_hit > 0) {
      // The tool's volume: the ball, and for a stroke the cylinder between its ends too.
      const double radius = cutter.params().tool_diameter / 2, pi = 3.14159265358979323846;
      const double length = strokes ? tetcut::norm(swept[i].to - swept[i].from) : 0.0;
      const double tool = 4.0 / 3.0 * pi * radius * radius * radius + pi * radius * radius * length;
      out.left_share.push_back(r.volume_left_in_tool / tool);
      out.beyond_share.push_back(r.volume_removed_beyond_tool / tool);
    }
  }
}

// The gated sweep on the liver refined `level` times, the tool scaled to its edges.
void run_sweep(int level, SweepResult& out, bool strokes = false) {
  run_sweep(liver_at(level), tetcut::bench::kGatedToolDiameter / (1 << level), out, strokes);
}

void report_sweep(benchmark::State& state, int level, const SweepResult& sweep);

void BM_CutSweep(benchmark::State& state) {
  const int level = static_cast<int>(state.range(0));
  SweepResult sweep;
  for (auto _ : state) {
    state.PauseTiming();
    liver_at(level);  // built outside the timing
    state.ResumeTiming();
    run_sweep(level, sweep);
  }
  report_sweep(state, level, sweep);
}
BENCHMARK(BM_CutSweep)->DenseRange(0, 3)->Iterations(1)->Unit(benchmark::kMillisecond);

// The gated sweep's passes cut by the swept tool: each pass's consecutive centres joined by a
// capsule (gated_strokes()), on the bundled liver: the capsule's per-cut figures beside the
// ball's (BM_CutSweep/0).
void BM_CapsuleSweep(benchmark::State& state) {
  SweepResult sweep;
  for (auto _ : state) run_sweep(0, sweep, true);
  report_sweep(state, 0, sweep);
}
BENCHMARK(BM_CapsuleSweep)->Iterations(1)->Unit(benchmark::kMillisecond);

// One stroke across the bundled liver (the gated tool, y = 40 to 180 mm at x = 95, z = 105) cut
// as 1, 2, 5, 10 and 20 capsules, and as balls at the same 2, 3, 6, 11 and 21 samples: the volume
// each removes. The capsules' should not depend on the sampling (to the refinement's resolution),
// the balls' does: coarse samples leave the tissue between them.
void BM_StrokeSampling(benchmark::State& state) {
  const tetcut::Vec3 from{95, 40, 105}, to{95, 180, 105};
  for (auto _ : state) {
    for (const int pieces : {1, 2, 5, 10, 20}) {
      double capsules = 0.0, balls = 0.0;
      for (const bool swept : {true, false}) {
        tetcut::TetMesh mesh = liver_at(0);
        tetcut::Cutter cutter(mesh, {.tool_diameter = tetcut::bench::kGatedToolDiameter});
        double removed = 0.0;
        for (int k = 0; k <= pieces; ++k) {
          const tetcut::Vec3 a = from + (static_cast<double>(k) / pieces) * (to - from);
          const tetcut::Vec3 b = from + (static_cast<double>(k + 1) / pieces) * (to - from);
          if (swept && k == pieces) break;
          const tetcut::CutReport r = swept ? cutter.cut_segment(a, b) : cutter.cut(a);
          removed += r.ok ? r.volume_removed : 0.0;
        }
        (swept ? capsules : balls) = removed;
      }
      state.counters["capsules_" + std::to_string(pieces) + "_volume"] = capsules;
      state.counters["balls_" + std::to_string(pieces + 1) + "_volume"] = balls;
    }
  }
}
BENCHMARK(BM_StrokeSampling)->Iterations(1)->Unit(benchmark::kMillisecond);

void report_sweep(benchmark::State& state, int level, const SweepResult& sweep) {
  const auto cuts = static_cast<double>(sweep.samples_us.size());
  state.counters["tets"] = static_cast<double>(liver_at(level).num_tets());
  state.counters["cuts"] = cuts;
  state.counters["p50_us"] = percentile(sweep.samples_us, 0.50);
  state.counters["p90_us"] = percentile(sweep.samples_us, 0.90);
  state.counters["p99_us"] = percentile(sweep.samples_us, 0.99);
  state.counters["max_us"] = percentile(sweep.samples_us, 1.0);
  state.counters["first_us"] = percentile(sweep.first_us, 1.0);
  state.counters["cuts_per_second"] = benchmark::Counter(cuts, benchmark::Counter::kIsRate);
  state.counters["tets_removed_per_cut"] = static_cast<double>(sweep.removed) / cuts;
  state.counters["tets_created_per_cut"] = static_cast<double>(sweep.created) / cuts;
  state.counters["unresolved"] = static_cast<double>(sweep.unresolved);
  state.counters["refused"] = static_cast<double>(sweep.refused);
  state.counters["left_in_tool"] = static_cast<double>(sweep.left_in_tool);
  state.counters["tets_removed_beyond_reach"] = static_cast<double>(sweep.beyond_reach);
  state.counters["worst_created_min_dihedral_deg"] = sweep.worst_created_dihedral_deg;
  state.counters["cuts_lowering_theta"] = static_cast<double>(sweep.theta_lowered);
  state.counters["volume_left_share_p50"] = percentile(sweep.left_share, 0.5);
  state.counters["volume_left_share_p99"] = percentile(sweep.left_share, 0.99);
  state.counters["volume_removed_beyond_share_p50"] = percentile(sweep.beyond_share, 0.5);
  state.counters["volume_removed_beyond_share_p99"] = percentile(sweep.beyond_share, 0.99);
  // Over the whole sweep, not averaged away: the goal is none at all once the Cutter is prepared.
  state.counters["allocations"] = static_cast<double>(sweep.allocations);
  state.counters["allocations_per_cut"] =
      static_cast<double>(sweep.allocations) / static_cast<double>(std::max<std::uint64_t>(1, sweep.counted_cuts));
  state.counters["pieces_p50_us"] = percentile(sweep.pieces_us, 0.50);
  state.counters["pieces_p99_us"] = percentile(sweep.pieces_us, 0.99);
  state.counters["fragments"] = static_cast<double>(sweep.fragments);
}

// The scaling figure of its own: median (and p99) per-cut time on the ~1M-tet liver over the
// ~16k one, the two sweeps interleaved cut-set by cut-set so that machine noise hits both.
void BM_CutScaling(benchmark::State& state) {
  liver_at(0);
  liver_at(2);
  SweepResult small, large;
  for (auto _ : state) {
    run_sweep(0, small);
    run_sweep(2, large);
  }
  state.counters["p50_ratio_1M_over_16k"] = percentile(large.samples_us, 0.5) / percentile(small.samples_us, 0.5);
  state.counters["p99_ratio_1M_over_16k"] = percentile(large.samples_us, 0.99) / percentile(small.samples_us, 0.99);
}
BENCHMARK(BM_CutScaling)->Iterations(1)->Unit(benchmark::kMillisecond);

// The same figure with the local work held identical: the lone liver against 64 copies of it
// (~1M tets), the sweep on copy 0 in both, interleaved in one process. This isolates what the
// mesh's size alone costs. The argument orders the copies' ids (bench_meshes.hpp CopiesOrder): 0 copy
// by copy (copy 0 keeps the lone liver's memory layout: no scan shows, but neither does a large
// mesh's scatter), 1 shuffled with a fixed seed (copy 0's tets spread through the whole mesh's
// memory, as a real large mesh's are), 2 sorted along a space-filling curve.
void BM_CutScalingSameWork(benchmark::State& state) {
  const auto order = static_cast<tetcut::bench::CopiesOrder>(state.range(0));
  liver_at(0);
  const tetcut::TetMesh& copies = tetcut::bench::replicated_corpus_liver(order);
  SweepResult small, large;
  for (auto _ : state) {
    run_sweep(0, small);
    run_sweep(copies, tetcut::bench::kGatedToolDiameter, large);
  }
  state.counters["tets_large"] = static_cast<double>(copies.num_tets());
  state.counters["p50_ratio_1M_over_16k"] = percentile(large.samples_us, 0.5) / percentile(small.samples_us, 0.5);
  state.counters["p99_ratio_1M_over_16k"] = percentile(large.samples_us, 0.99) / percentile(small.samples_us, 0.99);
  state.counters["p50_us_16k"] = percentile(small.samples_us, 0.5);
  state.counters["p50_us_1M"] = percentile(large.samples_us, 0.5);
}
BENCHMARK(BM_CutScalingSameWork)->DenseRange(0, 2)->ArgName("order")->Iterations(1)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
