// Refinement benchmarks: tets created per second by the split templates, the paper's
// refinement loop around a tool on the bundled liver (time per loop, iterations), and templates
// against sequential bisection in tets created and worst quality.
#include <benchmark/benchmark.h>

#include <algorithm>

#include "bench_meshes.hpp"
#include "core/quality.hpp"
#include "refine/refine.hpp"
#include "tetcut/detail/local_tables.hpp"

namespace {

using tetcut::TetId;

void BM_SplitUniform(benchmark::State& state) {
  const auto method = static_cast<tetcut::SplitMethod>(state.range(0));
  const tetcut::BuildResult built = tetcut::build_mesh(tetcut::make_box_mesh(12, 12, 12));
  std::vector<tetcut::Edge> edges;
  for (std::uint32_t t = 0; t < built.mesh->tet_capacity(); ++t)
    for (int e = 0; e < 6; ++e)
      edges.push_back({built.mesh->vertex(TetId{t}, tetcut::kEdgeVerts[e][0]), built.mesh->vertex(TetId{t}, tetcut::kEdgeVerts[e][1])});
  tetcut::EdgeSplitter splitter;
  std::uint64_t created = 0;
  double worst = 1.0;
  std::vector<TetId> children;
  for (auto _ : state) {
    state.PauseTiming();
    tetcut::TetMesh mesh = *built.mesh;
    state.ResumeTiming();
    children.clear();
    const tetcut::SplitResult r = splitter.split(mesh, edges, method, &children);
    created += r.tets_created;
    state.PauseTiming();  // the quality figure is not the split's work
    worst = std::min(worst, tetcut::min_radius_ratio(mesh, children));
    state.ResumeTiming();
  }
  state.counters["tets_created_per_second"] = benchmark::Counter(static_cast<double>(created), benchmark::Counter::kIsRate);
  state.counters["min_radius_ratio"] = worst;
}
BENCHMARK(BM_SplitUniform)->Arg(static_cast<int>(tetcut::SplitMethod::kTemplates))
    ->Arg(static_cast<int>(tetcut::SplitMethod::kBisection))->Unit(benchmark::kMillisecond);

// The loop of paper 3.2 around a tool of diameter 4 (mm) at fixed spots inside the liver.
void BM_RefineLoopOnLiver(benchmark::State& state) {
  const auto method = static_cast<tetcut::SplitMethod>(state.range(0));
  const tetcut::TetMesh& liver = tetcut::bench::corpus_mesh("liver.msh");
  // Tool centres: the centroids of every 997th tet (deterministic, spread through the organ).
  std::vector<tetcut::Vec3> centres;
  for (std::uint32_t t = 0; t < liver.tet_capacity(); t += 997) {
    tetcut::Vec3 c{};
    for (tetcut::VertId v : liver.tet(TetId{t})) c = c + 0.25 * liver.position(v);
    centres.push_back(c);
  }
  const double diameter = 4.0;
  tetcut::Refiner refiner;
  std::vector<TetId> hit, region;
  std::uint64_t loops = 0, iterations = 0, max_iterations = 0, created = 0;
  double worst = 1.0;
  std::size_t next = 0;
  for (auto _ : state) {
    state.PauseTiming();
    tetcut::TetMesh mesh = liver;
    const tetcut::Tool tool = tetcut::Tool::ball(centres[next++ % centres.size()], diameter / 2);
    hit.clear();
    for (std::uint32_t t = 0; t < mesh.tet_capacity(); ++t) {
      const auto v = mesh.tet(TetId{t});
      if (tetcut::intersects(tool, mesh.position(v[0]), mesh.position(v[1]), mesh.position(v[2]), mesh.position(v[3])))
        hit.push_back(TetId{t});
    }
    state.ResumeTiming();
    const tetcut::RefineReport r =
        refiner.refine(mesh, hit, {.d_ref = 1.5 * diameter, .p = 1.5, .method = method, .focus = tool}, region);
    ++loops;
    iterations += r.iterations;
    max_iterations = std::max<std::uint64_t>(max_iterations, r.iterations);
    created += r.tets_created;
    worst = std::min(worst, r.min_radius_ratio);
  }
  state.counters["mean_iterations"] = static_cast<double>(iterations) / static_cast<double>(loops);
  state.counters["max_iterations"] = static_cast<double>(max_iterations);
  state.counters["tets_created_per_loop"] = static_cast<double>(created) / static_cast<double>(loops);
  state.counters["min_radius_ratio"] = worst;
}
BENCHMARK(BM_RefineLoopOnLiver)->Arg(static_cast<int>(tetcut::SplitMethod::kTemplates))
    ->Arg(static_cast<int>(tetcut::SplitMethod::kBisection))->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
