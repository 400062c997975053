// Per-cut benchmarks (issues 6 and 7): what a simulator feels.
//
// BM_CutSweep/<level> runs a deterministic cautery sweep across the bundled liver (the paths of
// corpus/scenarios/liver-resection.scn, thinned) and times every cut, reporting per-cut p50,
// p90, p99 and max from those samples, cuts per second, tets removed and created, and heap
// allocations per cut after warm-up (counted by a global operator new).
//
// Levels: 0 = the bundled liver (~16k tets), 1 = its uniform refinement (~126k), 2 = twice
// refined (~1M). The tool diameter shrinks with the edge length (8, 4, 2 mm) so that every cut
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

#include "bench_meshes.hpp"
#include "tetcut/cut.hpp"
#include "tetcut/local_tables.hpp"

namespace {
std::atomic<std::uint64_t> g_allocations{0};
}  // namespace

// Counting allocator: every heap allocation in the process goes through here.
void* operator new(std::size_t size) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t size) { return operator new(size); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }

namespace {

using tetcut::TetId;

// The liver refined `level` times uniformly (cached).
const tetcut::TetMesh& liver_at(int level) {
  static std::map<int, tetcut::TetMesh> cache;
  auto it = cache.find(level);
  if (it != cache.end()) return it->second;
  tetcut::TetMesh mesh = tetcut::bench::corpus_mesh("liver.msh");
  tetcut::EdgeSplitter splitter;
  for (int i = 0; i < level; ++i) {
    std::vector<tetcut::Edge> edges;
    for (std::uint32_t t = 0; t < mesh.tet_capacity(); ++t)
      if (mesh.is_live(TetId{t}))
        for (int e = 0; e < 6; ++e)
          edges.push_back({mesh.vertex(TetId{t}, tetcut::kEdgeVerts[e][0]), mesh.vertex(TetId{t}, tetcut::kEdgeVerts[e][1])});
    splitter.split(mesh, edges, tetcut::SplitMethod::kTemplates);
    mesh.compact();
  }
  return cache.emplace(level, std::move(mesh)).first->second;
}

// Tool centres: passes across the organ in the plane x = 95 mm, every 4 mm, at 7 heights.
std::vector<tetcut::Vec3> sweep_centres() {
  std::vector<tetcut::Vec3> c;
  for (double z = 60; z <= 150; z += 15)
    for (double y = 40; y <= 180; y += 4) c.push_back({95, y, z});
  return c;
}

double percentile(std::vector<double> v, double q) {
  std::sort(v.begin(), v.end());
  const auto rank = static_cast<std::size_t>(std::ceil(q * static_cast<double>(v.size())));
  return v[std::min(v.size() - 1, rank == 0 ? 0 : rank - 1)];
}

void BM_CutSweep(benchmark::State& state) {
  const int level = static_cast<int>(state.range(0));
  const tetcut::TetMesh& base = liver_at(level);
  const std::vector<tetcut::Vec3> centres = sweep_centres();
  const double diameter = 8.0 / (1 << level);
  std::vector<double> samples;
  std::uint64_t removed = 0, created = 0, unresolved = 0, cuts = 0, allocations = 0, counted_cuts = 0;
  for (auto _ : state) {
    state.PauseTiming();
    tetcut::TetMesh mesh = base;
    tetcut::Cutter cutter(mesh, {.tool_diameter = diameter});
    state.ResumeTiming();
    for (std::size_t i = 0; i < centres.size(); ++i) {
      const std::uint64_t before = g_allocations.load(std::memory_order_relaxed);
      const auto t0 = std::chrono::steady_clock::now();
      const tetcut::CutReport r = cutter.cut(centres[i]);
      const auto t1 = std::chrono::steady_clock::now();
      samples.push_back(std::chrono::duration<double, std::micro>(t1 - t0).count());
      // Warm-up: the first half of the sweep grows the scratch buffers and the free lists.
      if (i >= centres.size() / 2) {
        allocations += g_allocations.load(std::memory_order_relaxed) - before;
        ++counted_cuts;
      }
      removed += r.tets_removed;
      created += r.tets_created;
      unresolved += r.unresolved;
      ++cuts;
    }
  }
  state.counters["tets"] = static_cast<double>(base.num_tets());
  state.counters["cuts"] = static_cast<double>(cuts);
  state.counters["p50_us"] = percentile(samples, 0.50);
  state.counters["p90_us"] = percentile(samples, 0.90);
  state.counters["p99_us"] = percentile(samples, 0.99);
  state.counters["max_us"] = percentile(samples, 1.0);
  state.counters["cuts_per_second"] = benchmark::Counter(static_cast<double>(cuts), benchmark::Counter::kIsRate);
  state.counters["tets_removed_per_cut"] = static_cast<double>(removed) / static_cast<double>(cuts);
  state.counters["tets_created_per_cut"] = static_cast<double>(created) / static_cast<double>(cuts);
  state.counters["unresolved"] = static_cast<double>(unresolved);
  state.counters["allocations_per_cut"] = static_cast<double>(allocations) / static_cast<double>(std::max<std::uint64_t>(1, counted_cuts));
}
BENCHMARK(BM_CutSweep)->DenseRange(0, 2)->Iterations(1)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
