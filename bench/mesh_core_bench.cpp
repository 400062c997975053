// Mesh core benchmarks: building a mesh with its adjacency and validation, and the independent
// full check, on structured boxes of about 16k and 1M tets; plus the mesh's bytes per tet.
// Targets (2-core machine): build of 1M tets under 1 s, full check of 1M under 2 s,
// at most 64 bytes per tet without attributes. The budgets live in bench/budgets.json.
#include <benchmark/benchmark.h>

#include <map>

#include "tetcut/box_mesh.hpp"
#include "tetcut/invariants/check.hpp"
#include "tetcut/mesh_builder.hpp"

namespace {

// Box dimensions for a requested size: 6 * n * n * m tets.
tetcut::RawMesh box_for(std::int64_t tets) {
  if (tets <= 20000) return tetcut::make_box_mesh(16, 16, 11);  // 16,896 tets
  return tetcut::make_box_mesh(55, 55, 55);                    // 998,250 tets
}

const tetcut::RawMesh& cached_box(std::int64_t tets) {
  static std::map<std::int64_t, tetcut::RawMesh> cache;
  auto it = cache.find(tets);
  if (it == cache.end()) it = cache.emplace(tets, box_for(tets)).first;
  return it->second;
}

void BM_BuildMesh(benchmark::State& state) {
  const tetcut::RawMesh& raw = cached_box(state.range(0));
  for (auto _ : state) {
    tetcut::BuildResult built = tetcut::build_mesh(raw);
    if (!built.ok()) state.SkipWithError("build failed");
    benchmark::DoNotOptimize(built);
  }
  state.counters["tets"] = static_cast<double>(raw.tets.size());
  state.counters["tets_per_second"] =
      benchmark::Counter(static_cast<double>(raw.tets.size()), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_BuildMesh)->Arg(16000)->Arg(1000000)->Unit(benchmark::kMillisecond);

void BM_FullCheck(benchmark::State& state) {
  const tetcut::BuildResult built = tetcut::build_mesh(cached_box(state.range(0)));
  if (!built.ok()) {
    state.SkipWithError("build failed");
    return;
  }
  for (auto _ : state) {
    tetcut::invariants::CheckReport report = tetcut::invariants::check_mesh(built.mesh->raw_view());
    if (!report.ok()) state.SkipWithError("check found a violation on a valid mesh");
    benchmark::DoNotOptimize(report);
  }
  state.counters["tets"] = static_cast<double>(built.mesh->num_tets());
  state.counters["tets_per_second"] = benchmark::Counter(static_cast<double>(built.mesh->num_tets()),
                                                         benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_FullCheck)->Arg(16000)->Arg(1000000)->Unit(benchmark::kMillisecond);

// Not a timing: reports the memory the mesh holds per tet as a counter for the budget gate.
void BM_BytesPerTet(benchmark::State& state) {
  const tetcut::BuildResult built = tetcut::build_mesh(cached_box(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(built.mesh->memory_bytes());
  state.counters["bytes_per_tet"] =
      static_cast<double>(built.mesh->memory_bytes()) / static_cast<double>(built.mesh->num_tets());
}
BENCHMARK(BM_BytesPerTet)->Arg(1000000)->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
