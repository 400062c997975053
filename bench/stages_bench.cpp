// Per-stage micro benchmarks and the per-cut sweep on every bundled mesh.
//
//   BM_CutSweepCorpus/<mesh>   a sweep along the longest axis of each bundled mesh, tool
//                              diameter 1/25 of the bounding box diagonal: per-cut p50/p99/max
//   BM_Locate                  the tool query alone (spatial index + exact ball-tet test)
//   BM_RemovalByStrategy/<s>/<mesh>   one removal request on the current boundary, as a
//                              cautery meets it, per strategy: per-request p50/p99/max, mean
//                              cardinality; mesh 0 = bundled liver (~16k), 1 = a 1M-tet box
//   BM_LocalCheck              the local checker after one cut
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "bench_meshes.hpp"
#include "tetcut/boundary_tet_picker.hpp"
#include "cut/spatial_index.hpp"
#include "remove/removal.hpp"
#include "tetcut/cut.hpp"
#include "tetcut/invariants/check.hpp"
#include "tetcut/percentile.hpp"

namespace {

using tetcut::percentile;
using tetcut::TetId;
using tetcut::Vec3;
using Clock = std::chrono::steady_clock;

constexpr const char* kCorpus[] = {"cylinder.msh", "sheet.msh", "liver-coarse.msh", "liver-refined.msh", "liver.msh"};

using tetcut::BoundingBox;
using tetcut::bounding_box;

// Three passes along the longest axis through the middle third of the other two.
std::vector<Vec3> corpus_sweep(const BoundingBox& b, double step) {
  const Vec3 size = b.hi - b.lo;
  const int axis = size.x >= size.y && size.x >= size.z ? 0 : size.y >= size.z ? 1 : 2;
  auto at = [](const Vec3& v, int a) { return a == 0 ? v.x : a == 1 ? v.y : v.z; };
  std::vector<Vec3> out;
  const int u = (axis + 1) % 3, w = (axis + 2) % 3;
  for (double f : {0.4, 0.5, 0.6})
    for (double s = at(b.lo, axis); s <= at(b.hi, axis); s += step) {
      double c[3];
      c[axis] = s;
      c[u] = at(b.lo, u) + f * at(size, u);
      c[w] = at(b.lo, w) + 0.5 * at(size, w);
      out.push_back({c[0], c[1], c[2]});
    }
  return out;
}

void BM_CutSweepCorpus(benchmark::State& state) {
  const tetcut::TetMesh& base = tetcut::bench::corpus_mesh(kCorpus[state.range(0)]);
  const BoundingBox b = bounding_box(base);
  const double diameter = norm(b.hi - b.lo) / 25;
  const std::vector<Vec3> centres = corpus_sweep(b, diameter / 2);
  std::vector<double> samples;
  std::uint64_t removed = 0, created = 0, unresolved = 0;
  double cutting_us = 0.0;
  for (auto _ : state) {
    tetcut::TetMesh mesh = base;
    tetcut::Cutter cutter(mesh, {.tool_diameter = diameter});
    for (const Vec3& c : centres) {
      const auto t0 = Clock::now();
      const tetcut::CutReport r = cutter.cut(c);
      samples.push_back(std::chrono::duration<double, std::micro>(Clock::now() - t0).count());
      cutting_us += samples.back();
      removed += r.tets_removed;
      created += r.tets_created;
      unresolved += r.unresolved;
    }
  }
  state.SetLabel(kCorpus[state.range(0)]);
  state.counters["cuts"] = static_cast<double>(samples.size());
  state.counters["p50_us"] = percentile(samples, 0.5);
  state.counters["p90_us"] = percentile(samples, 0.9);
  state.counters["p99_us"] = percentile(samples, 0.99);
  state.counters["max_us"] = percentile(samples, 1.0);
  state.counters["cuts_per_second"] = static_cast<double>(samples.size()) / (cutting_us * 1e-6);
  state.counters["tets_removed_per_cut"] = static_cast<double>(removed) / static_cast<double>(samples.size());
  state.counters["tets_created_per_cut"] = static_cast<double>(created) / static_cast<double>(samples.size());
  state.counters["unresolved"] = static_cast<double>(unresolved);
}
BENCHMARK(BM_CutSweepCorpus)->DenseRange(0, 4)->Iterations(1)->Unit(benchmark::kMillisecond);

void BM_Locate(benchmark::State& state) {
  tetcut::TetMesh mesh = tetcut::bench::corpus_mesh("liver.msh");
  const BoundingBox b = bounding_box(mesh);
  tetcut::SpatialIndex index(8.0);
  index.build(mesh);
  std::vector<TetId> hit;
  std::uint64_t found = 0;
  double y = b.lo.y;
  for (auto _ : state) {
    y = y + 3.0 > b.hi.y ? b.lo.y : y + 3.0;
    index.query(mesh, {{0.5 * (b.lo.x + b.hi.x), y, 0.5 * (b.lo.z + b.hi.z)}, 4.0}, hit);
    found += hit.size();
  }
  state.counters["tets_per_query"] = static_cast<double>(found) / static_cast<double>(state.iterations());
}
BENCHMARK(BM_Locate)->Unit(benchmark::kMicrosecond);

const tetcut::TetMesh& removal_mesh(int which) {
  if (which == 0) return tetcut::bench::corpus_mesh("liver.msh");
  static const tetcut::TetMesh box = std::move(*tetcut::build_mesh(tetcut::make_box_mesh(55, 55, 55)).mesh);
  return box;
}

void BM_RemovalByStrategy(benchmark::State& state) {
  const auto strategy = static_cast<tetcut::RemovalStrategy>(state.range(0));
  const tetcut::TetMesh& base = removal_mesh(static_cast<int>(state.range(1)));
  std::vector<double> samples;
  tetcut::RemovalReport report;
  for (auto _ : state) {
    state.PauseTiming();
    tetcut::TetMesh mesh = base;
    // Prepared as a Cutter prepares it: a copy has no spare capacity, and the first split's
    // growth of the mesh's arrays (2 ms once) is not a request's cost.
    mesh.reserve(mesh.tet_capacity() * 2, mesh.vertex_capacity() * 2);
    tetcut::Remover remover({.strategy = strategy});
    remover.reserve(mesh.tet_capacity() * 2, mesh.vertex_capacity() * 2);
    tetcut::BoundaryTetPicker picker(mesh, 2002);
    state.ResumeTiming();
    for (int i = 0; i < 2000; ++i) {
      const TetId t = picker.pick(mesh);
      if (!t.valid()) break;
      const auto t0 = Clock::now();
      remover.remove(mesh, t);
      samples.push_back(std::chrono::duration<double, std::micro>(Clock::now() - t0).count());
      picker.add(remover.last_exposed());
    }
    report = remover.report();
  }
  state.SetLabel(std::string(tetcut::to_string(strategy)) + (state.range(1) == 0 ? " liver 16k" : " box 1M"));
  state.counters["p50_us"] = percentile(samples, 0.5);
  state.counters["p99_us"] = percentile(samples, 0.99);
  state.counters["max_us"] = percentile(samples, 1.0);
  state.counters["mean_cardinality"] = report.mean_cardinality();
  // How the requests went: the tail of the times is the refinements and the fallbacks.
  state.counters["refinements"] = static_cast<double>(report.resolved_by_refinement);
  state.counters["fallbacks"] = static_cast<double>(report.resolved_by_fallback);
  state.counters["attempts_undone"] = static_cast<double>(report.attempts_undone);
  state.counters["unresolved"] = static_cast<double>(report.unresolved);
}
BENCHMARK(BM_RemovalByStrategy)
    ->ArgsProduct({{static_cast<int>(tetcut::RemovalStrategy::kBasic), static_cast<int>(tetcut::RemovalStrategy::kNeighbours),
                    static_cast<int>(tetcut::RemovalStrategy::kCombined), static_cast<int>(tetcut::RemovalStrategy::kWide)},
                   {0, 1}})
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);

void BM_LocalCheck(benchmark::State& state) {
  tetcut::TetMesh mesh = tetcut::bench::corpus_mesh("liver.msh");
  const BoundingBox b = bounding_box(mesh);
  tetcut::Cutter cutter(mesh, {.tool_diameter = 8.0});
  tetcut::invariants::LocalChecker local(mesh.raw_view());
  double y = b.lo.y + 20;
  std::uint64_t failures = 0;
  for (auto _ : state) {
    state.PauseTiming();
    y = y + 4.0 > b.hi.y - 20 ? b.lo.y + 20 : y + 4.0;
    cutter.cut({95, y, 100});
    tetcut::invariants::CheckOptions options;  // with the tissue rule (I10) at the cut's tool
    options.tool = tetcut::invariants::ToolRule{.centre = {95, y, 100}, .radius = 4.0, .d_ref = cutter.params().d_ref(),
                                                .left = cutter.last_left_in_tool()};
    options.moved = cutter.last_moved();
    state.ResumeTiming();
    failures += !local.after_operation(mesh.raw_view(), cutter.last_removed(), cutter.last_created(), options).ok();
  }
  state.counters["violations"] = static_cast<double>(failures);
}
BENCHMARK(BM_LocalCheck)->Unit(benchmark::kMicrosecond)->Iterations(200);

}  // namespace

BENCHMARK_MAIN();
