// Where the same-work update ratio (mechanics_bench BM_UpdateScalingSameWork)
// comes from: the model's and the rendered surface's update per cut over the gated sweep on the
// liver and on 64 copies of it (copy 0 the liver), each split into model and surface.
//
//   update_probe [REPS]       REPS (5) sweeps of each, alternating; per-sweep p50s and the
//                             medians over the sweeps of the 1M / 16k ratios (p50, p99)
//   update_probe 16k | 1M     one sweep, for callgrind: only the sweep (cut + update) is
//                             instrumented, e.g. valgrind --tool=callgrind --cache-sim=yes
//                             --LL=8388608,16,64 --instr-atstart=no bench/update_probe 1M
//   update_probe hash         a hash of every bit of both consumers' state after every cut on
//                             both meshes: a change to their tables must leave it as it was
//   update_probe sizes        tets, vertices, edges and triangles of both meshes
#if __has_include(<valgrind/callgrind.h>)
#include <valgrind/callgrind.h>
#else  // no valgrind headers: the timing and hash modes still work
#define RUNNING_ON_VALGRIND 0
#define CALLGRIND_START_INSTRUMENTATION
#define CALLGRIND_STOP_INSTRUMENTATION
#endif

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "bench_meshes.hpp"
#include "gated_sweep.hpp"
#include "tetcut/cut.hpp"
#include "tetcut/mechanics/rendered_surface.hpp"
#include "tetcut/mechanics/tensor_mass.hpp"
#include "tetcut/percentile.hpp"

using namespace tetcut;
namespace {
double us(std::chrono::steady_clock::time_point a, std::chrono::steady_clock::time_point b) {
  return std::chrono::duration<double, std::micro>(b - a).count();
}
struct Samples { std::vector<double> model, surface, both; };
void sweep(const TetMesh& base, Samples& s, bool instrument) {
  TetMesh mesh = base;
  Cutter cutter(mesh, {.tool_diameter = bench::kGatedToolDiameter});
  mechanics::ModelParams p;
  p.gravity = {0, 0, -9.81};
  p.damping = 20;
  mechanics::TensorMassModel model(mesh, p);
  mechanics::RenderedSurface surface(mesh);
  ChangeLog log;
  log.reserve(1u << 14);
  if (instrument) CALLGRIND_START_INSTRUMENTATION;
  for (const Vec3& c : bench::gated_sweep_centres()) {
    log.clear();
    cutter.cut(c, &log);
    const auto t0 = std::chrono::steady_clock::now();
    model.apply(mesh, log);
    const auto t1 = std::chrono::steady_clock::now();
    surface.apply(mesh, log);
    const auto t2 = std::chrono::steady_clock::now();
    s.model.push_back(us(t0, t1));
    s.surface.push_back(us(t1, t2));
    s.both.push_back(us(t0, t2));
  }
  if (instrument) CALLGRIND_STOP_INSTRUMENTATION;
}
}  // namespace

int main(int argc, char** argv) {
  const char* which = argc > 1 ? argv[1] : "5";
  const int reps = std::max(1, std::atoi(which));
  const bool grind = RUNNING_ON_VALGRIND;
  const TetMesh& small = bench::corpus_mesh("liver.msh");
  if (std::strcmp(which, "sizes") == 0) {
    for (const TetMesh* m : {&small, &bench::replicated_corpus_liver()}) {
      mechanics::TensorMassModel model(*m, {});
      mechanics::RenderedSurface surface(*m);
      std::printf("tets %u vertices %u (capacity %u) edges %u slots %zu triangles %u slots %zu\n", m->num_tets(),
                  m->num_vertices(), m->vertex_capacity(), model.edge_count(), model.edge_slots().size(),
                  surface.triangle_count(), surface.triangle_slots().size());
    }
    return 0;
  }
  if (std::strcmp(which, "hash") == 0) {
    // Every bit of both consumers' state after every cut of the sweep, on both meshes.
    for (const TetMesh* base : {&small, &bench::replicated_corpus_liver()}) {
      TetMesh mesh = *base;
      Cutter cutter(mesh, {.tool_diameter = bench::kGatedToolDiameter});
      mechanics::TensorMassModel model(mesh, {});
      mechanics::RenderedSurface surface(mesh);
      ChangeLog log;
      std::uint64_t h = 1469598103934665603ULL;
      auto mix = [&](const void* p, std::size_t n) {
        const auto* b = static_cast<const unsigned char*>(p);
        for (std::size_t i = 0; i < n; ++i) h = (h ^ b[i]) * 1099511628211ULL;
      };
      for (const Vec3& c : bench::gated_sweep_centres()) {
        log.clear();
        cutter.cut(c, &log);
        model.apply(mesh, log);
        surface.apply(mesh, log);
        for (const auto& e : model.edge_slots()) { mix(&e.a, 8); mix(e.k.data(), 72); mix(&e.scale, 8); mix(&e.tets, 4); }
        for (std::uint32_t v = 0; v < model.vertex_capacity(); ++v) {
          mix(model.vertex_stiffness(VertId{v}).data(), 72);
          const double m = model.mass(VertId{v}), sc = model.vertex_scale(VertId{v});
          mix(&m, 8); mix(&sc, 8);
          const Vec3 n = surface.normal_sum(VertId{v});
          const double ns = surface.normal_scale(VertId{v});
          mix(&n, sizeof n); mix(&ns, 8);
        }
        for (const auto& t : surface.triangle_slots()) { mix(t.v.data(), 12); mix(&t.area_vector, sizeof t.area_vector); }
      }
      std::printf("state hash %016llx\n", static_cast<unsigned long long>(h));
    }
    return 0;
  }
  if (std::strcmp(which, "16k") == 0) { Samples s; sweep(small, s, grind); return 0; }
  const TetMesh& large = bench::replicated_corpus_liver();
  if (std::strcmp(which, "1M") == 0) { Samples s; sweep(large, s, grind); return 0; }
  std::vector<double> r50[3], r99[3], a50[3], b50[3];
  for (int r = 0; r < reps; ++r) {
    Samples a, b;
    sweep(small, a, false);
    sweep(large, b, false);
    const std::vector<double>* sa[3] = {&a.model, &a.surface, &a.both};
    const std::vector<double>* sb[3] = {&b.model, &b.surface, &b.both};
    for (int k = 0; k < 3; ++k) {
      r50[k].push_back(percentile(*sb[k], 0.5) / percentile(*sa[k], 0.5));
      r99[k].push_back(percentile(*sb[k], 0.99) / percentile(*sa[k], 0.99));
      a50[k].push_back(percentile(*sa[k], 0.5));
      b50[k].push_back(percentile(*sb[k], 0.5));
    }
    std::printf("rep %d: p50 16k model %.1f surface %.1f both %.1f | 1M model %.1f surface %.1f both %.1f | ratio both p50 %.3f p99 %.3f\n",
                r, percentile(a.model, 0.5), percentile(a.surface, 0.5), percentile(a.both, 0.5), percentile(b.model, 0.5),
                percentile(b.surface, 0.5), percentile(b.both, 0.5), r50[2].back(), r99[2].back());
  }
  const char* names[3] = {"model", "surface", "both"};
  for (int k = 0; k < 3; ++k)
    std::printf("median over %d reps, %s: 16k p50 %.1f us, 1M p50 %.1f us, ratio 1M/16k p50 %.3f p99 %.3f\n", reps, names[k],
                percentile(a50[k], 0.5), percentile(b50[k], 0.5), percentile(r50[k], 0.5), percentile(r99[k], 0.5));
}
