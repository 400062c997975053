// The deterministic companion of the per-cut timings: a fixed cautery sweep whose cuts run inside
// measured_cuts(), one call of one_measured_cut() each, so that
//   valgrind --tool=callgrind --toggle-collect='*measured_cuts*' --dump-after='*one_measured_cut*' ...
// counts exactly the instructions of those cuts, cut by cut, whatever else the machine is doing
// (bench/instructions_gate.sh). Every cut of the sweep is counted, the first included (the Cutter
// prepares itself when constructed). Prints the number of measured cuts, the mesh's tets and the
// toolchain it was built with.
//
//   cut_instructions                     the gated sweep on the bundled liver (~16k tets)
//   cut_instructions --shuffled-copies   the same sweep on copy 0 of 64 copies of the liver (~1M
//                                        tets) whose ids are shuffled with a fixed seed: the
//                                        cache-miss figure (callgrind --cache-sim=yes)
//
// Under callgrind --instr-atstart=no, instrumentation starts just before the first cut, so that
// reading the liver and building a million tets run at valgrind's uninstrumented speed; the
// simulated caches then start empty at the first cut.
#include <valgrind/callgrind.h>

#include <cstdio>
#include <cstring>

#include "bench_meshes.hpp"
#include "gated_sweep.hpp"
#include "tetcut/cut.hpp"
#include "toolchain.hpp"

namespace {

// Not inlined, so that callgrind can toggle collection on the sweep and dump after each cut.
[[gnu::noinline]] std::uint32_t one_measured_cut(tetcut::Cutter& cutter, const tetcut::Vec3& centre) {
  return cutter.cut(centre).tets_removed;
}

[[gnu::noinline]] std::uint64_t measured_cuts(tetcut::Cutter& cutter, const std::vector<tetcut::Vec3>& centres) {
  std::uint64_t removed = 0;
  for (const tetcut::Vec3& c : centres) removed += one_measured_cut(cutter, c);
  return removed;
}

}  // namespace

int main(int argc, char** argv) {
  const bool shuffled = argc > 1 && std::strcmp(argv[1], "--shuffled-copies") == 0;
  if (argc > 1 && !shuffled) {
    std::fprintf(stderr, "usage: cut_instructions [--shuffled-copies]\n");
    return 2;
  }
  using tetcut::bench::CopiesOrder;
  tetcut::TetMesh mesh = shuffled ? tetcut::bench::replicated_corpus_liver(CopiesOrder::kShuffled)
                                  : tetcut::bench::corpus_mesh("liver.msh");
  const std::vector<tetcut::Vec3> centres = tetcut::bench::gated_sweep_centres();
  const auto tets = static_cast<unsigned long long>(mesh.num_tets());
  tetcut::Cutter cutter(mesh, {.tool_diameter = tetcut::bench::kGatedToolDiameter});
  CALLGRIND_START_INSTRUMENTATION;
  const std::uint64_t removed = measured_cuts(cutter, centres);
  CALLGRIND_STOP_INSTRUMENTATION;
  std::printf("measured_cuts %zu removed %llu\n", centres.size(), static_cast<unsigned long long>(removed));
  std::printf("tets %llu\n", tets);
  std::printf("toolchain %s\n", TETCUT_TOOLCHAIN);
  return 0;
}
