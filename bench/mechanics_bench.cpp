// The change log's consumers (tetcut::mechanics), measured on the bundled liver:
//
//   BM_HapticFrame          a haptic frame on the ~16k liver: one cut of the gated sweep + the
//                           model's and the rendered surface's update from its ChangeLog + one
//                           explicit step; every frame counted (goal: p99 <= 1 ms), by the
//                           wall clock and by this thread's CPU time.
//   BM_UpdateScalingSameWork  the update alone (model + surface) per cut, on the lone liver and
//                           on 64 copies of it (~1M tets), the same sweep on copy 0 in both: the
//                           ratio says whether the update scans the mesh (goal: <= 1.1).
//   BM_StableStepAfterResection/strategy  the CFL stable time step (smallest altitude over the
//                           pressure wave speed) after the bundled resection
//                           (corpus/scenarios/liver-resection.scn) over the one before it:
//                           how the cuts' slivers reach a simulator's time step.
//   BM_ExplicitStep / BM_ExplicitStepSparse  one explicit step's force product on the ~16k
//                           liver: the tensor loop against Eigen's sparse matrix product.
//
// Not in the gate (bench/budgets.json): figures, reported beside their goals.
#include <benchmark/benchmark.h>

#include <atomic>
#include <chrono>
#include <cstdlib>
#include <new>
#include <ctime>
#include <vector>

#include "bench_meshes.hpp"
#include "counting_allocator.hpp"
#include "gated_sweep.hpp"
#include "tetcut/cut.hpp"
#include "tetcut/mechanics/rendered_surface.hpp"
#include "tetcut/mechanics/sparse_reference.hpp"
#include "tetcut/mechanics/tensor_mass.hpp"
#include "tetcut/percentile.hpp"

namespace {

using tetcut::percentile;
using namespace tetcut;

// This thread's CPU time: on a loaded machine (the CI machine runs two builds beside the
// benchmarks) the wall clock's p99 is the scheduler's, not the frame's.
double thread_cpu_us() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) * 1e6 + static_cast<double>(t.tv_nsec) / 1e3;
}

double since_us(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count();
}

mechanics::ModelParams liver_params() {
  mechanics::ModelParams p;  // liver-like material, millimetres
  p.gravity = {0, 0, -9.81};
  p.damping = 20;
  return p;
}

void BM_HapticFrame(benchmark::State& state) {
  const std::vector<Vec3> centres = bench::gated_sweep_centres();
  std::vector<double> frame_us, cut_us, update_us, step_us, model_us, frame_cpu_us;
  std::uint64_t consumer_allocations = 0;
  for (auto* v : {&frame_us, &cut_us, &update_us, &step_us, &model_us, &frame_cpu_us}) v->reserve(1024);
  for (auto _ : state) {
    state.PauseTiming();
    TetMesh mesh = bench::corpus_mesh("liver.msh");
    Cutter cutter(mesh, {.tool_diameter = bench::kGatedToolDiameter});
    mechanics::TensorMassModel model(mesh, liver_params());
    mechanics::RenderedSurface surface(mesh);
    model.fix_where(mesh, [](const Vec3& x) { return x.x > 150; });
    const double dt = 0.5 * model.stable_time_step(mesh).dt;
    ChangeLog log;
    log.reserve(1u << 14);
    state.ResumeTiming();
    for (const Vec3& c : centres) {
      log.clear();
      const double cpu0 = thread_cpu_us();
      const auto t0 = std::chrono::steady_clock::now();
      cutter.cut(c, &log);
      const auto t1 = std::chrono::steady_clock::now();
      const std::uint64_t allocations_before = tetcut::bench::allocations();
      model.apply(mesh, log);
      const auto t_model = std::chrono::steady_clock::now();
      surface.apply(mesh, log);
      const auto t2 = std::chrono::steady_clock::now();
      model.step(dt);
      consumer_allocations += tetcut::bench::allocations() - allocations_before;
      model_us.push_back(std::chrono::duration<double, std::micro>(t_model - t1).count());
      step_us.push_back(since_us(t2));
      update_us.push_back(std::chrono::duration<double, std::micro>(t2 - t1).count());
      cut_us.push_back(std::chrono::duration<double, std::micro>(t1 - t0).count());
      frame_us.push_back(since_us(t0));
      frame_cpu_us.push_back(thread_cpu_us() - cpu0);
    }
  }
  state.counters["frames"] = static_cast<double>(frame_us.size());
  state.counters["p50_us"] = percentile(frame_us, 0.5);
  state.counters["p99_us"] = percentile(frame_us, 0.99);
  state.counters["max_us"] = percentile(frame_us, 1.0);
  state.counters["goal_p99_us"] = 1000;
  state.counters["cpu_p50_us"] = percentile(frame_cpu_us, 0.5);
  state.counters["cpu_p99_us"] = percentile(frame_cpu_us, 0.99);
  state.counters["cut_p99_us"] = percentile(cut_us, 0.99);
  state.counters["update_p50_us"] = percentile(update_us, 0.5);
  state.counters["update_p99_us"] = percentile(update_us, 0.99);
  state.counters["model_update_p99_us"] = percentile(model_us, 0.99);
  state.counters["step_p50_us"] = percentile(step_us, 0.5);
  // Heap allocations in the consumers' update and step over the whole sweep: the goal is none.
  state.counters["consumer_allocations"] = static_cast<double>(consumer_allocations);
}
BENCHMARK(BM_HapticFrame)->Iterations(1)->Unit(benchmark::kMillisecond);

// The update's time per cut over the gated sweep on `base` (copy 0 of it is the liver).
void update_sweep(const TetMesh& base, std::vector<double>& samples) {
  TetMesh mesh = base;
  Cutter cutter(mesh, {.tool_diameter = bench::kGatedToolDiameter});
  mechanics::TensorMassModel model(mesh, liver_params());
  mechanics::RenderedSurface surface(mesh);
  ChangeLog log;
  log.reserve(1u << 14);
  for (const Vec3& c : bench::gated_sweep_centres()) {
    log.clear();
    cutter.cut(c, &log);
    const auto t0 = std::chrono::steady_clock::now();
    model.apply(mesh, log);
    surface.apply(mesh, log);
    samples.push_back(since_us(t0));
  }
}

void BM_UpdateScalingSameWork(benchmark::State& state) {
  bench::corpus_mesh("liver.msh");
  bench::replicated_corpus_liver();
  std::vector<double> small, large;
  for (auto _ : state) {
    update_sweep(bench::corpus_mesh("liver.msh"), small);
    update_sweep(bench::replicated_corpus_liver(), large);
  }
  state.counters["tets_large"] = static_cast<double>(bench::replicated_corpus_liver().num_tets());
  state.counters["p50_us_16k"] = percentile(small, 0.5);
  state.counters["p50_us_1M"] = percentile(large, 0.5);
  state.counters["p50_ratio_1M_over_16k"] = percentile(large, 0.5) / percentile(small, 0.5);
  state.counters["p99_ratio_1M_over_16k"] = percentile(large, 0.99) / percentile(small, 0.99);
  state.counters["goal_ratio"] = 1.1;
}
BENCHMARK(BM_UpdateScalingSameWork)->Iterations(1)->Unit(benchmark::kMillisecond);

// The resection of corpus/scenarios/liver-resection.scn: a slot across the organ at x = 95 mm,
// one pass every 5 mm of height, a cut every 4 mm, tool 8 mm.
std::vector<Vec3> resection_centres() {
  std::vector<Vec3> c;
  for (double z = 10; z <= 200; z += 5) {
    for (double y = 15; y <= 200 + 1e-9; y += 4) c.push_back({95, y, z});
    if (c.back().y < 200) c.push_back({95, 200, z});
  }
  return c;
}

void BM_StableStepAfterResection(benchmark::State& state) {
  const auto strategy = static_cast<RemovalStrategy>(state.range(0));
  state.SetLabel(to_string(strategy));
  double before = 0, after = 0, altitude_before = 0, altitude_after = 0;
  for (auto _ : state) {
    TetMesh mesh = bench::corpus_mesh("liver.msh");
    const auto s0 = mechanics::TensorMassModel(mesh, liver_params()).stable_time_step(mesh);
    Cutter cutter(mesh, {.tool_diameter = 8.0, .strategy = strategy});
    for (const Vec3& c : resection_centres()) cutter.cut(c);
    const auto s1 = mechanics::TensorMassModel(mesh, liver_params()).stable_time_step(mesh);
    before = s0.dt, after = s1.dt, altitude_before = s0.min_altitude, altitude_after = s1.min_altitude;
  }
  state.counters["stable_dt_before_us"] = before * 1e6;
  state.counters["stable_dt_after_us"] = after * 1e6;
  state.counters["ratio_after_over_before"] = after / before;
  state.counters["min_altitude_before_mm"] = altitude_before * 1e3;
  state.counters["min_altitude_after_mm"] = altitude_after * 1e3;
}
BENCHMARK(BM_StableStepAfterResection)->DenseRange(0, 3)->Iterations(1)->Unit(benchmark::kMillisecond);

mechanics::TensorMassModel& displaced_liver_model() {
  static mechanics::TensorMassModel model = [] {
    const TetMesh& mesh = bench::corpus_mesh("liver.msh");
    mechanics::TensorMassModel m(mesh, liver_params());
    for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v)
      m.set_displacement(VertId{v}, {1e-4 * std::sin(v), 1e-4 * std::cos(3.0 * v), 1e-4 * std::sin(7.0 * v)});
    return m;
  }();
  return model;
}

void BM_ExplicitStep(benchmark::State& state) {
  const mechanics::TensorMassModel& model = displaced_liver_model();
  std::vector<Vec3> forces;
  for (auto _ : state) {
    model.elastic_forces(forces);
    benchmark::DoNotOptimize(forces.data());
  }
  state.counters["vertices"] = static_cast<double>(bench::corpus_mesh("liver.msh").num_vertices());
  state.counters["edges"] = static_cast<double>(model.edge_count());
}
BENCHMARK(BM_ExplicitStep)->Unit(benchmark::kMicrosecond);

void BM_ExplicitStepSparse(benchmark::State& state) {
  const mechanics::TensorMassModel& model = displaced_liver_model();
  const mechanics::SparseStiffness k(model);
  std::vector<Vec3> forces;
  for (auto _ : state) {
    k.elastic_forces(model, forces);
    benchmark::DoNotOptimize(forces.data());
  }
  state.counters["nonzeros"] = static_cast<double>(k.nonzeros());
}
BENCHMARK(BM_ExplicitStepSparse)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
