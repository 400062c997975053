// The deterministic companion of the per-cut timings (issue 7): a fixed cautery sweep on the
// bundled liver whose cuts run inside measured_cuts(), so that
//   valgrind --tool=callgrind --toggle-collect=measured_cuts ...
// counts exactly the instructions of those cuts, whatever else the machine is doing. Every cut
// of the sweep is counted, the first included (the Cutter prepares itself when constructed).
// Prints the number of measured cuts and the toolchain it was built with.
#include <cstdio>

#include "bench_meshes.hpp"
#include "gated_sweep.hpp"
#include "tetcut/cut.hpp"
#include "toolchain.hpp"

namespace {

// Not inlined, so callgrind can toggle on it.
[[gnu::noinline]] std::uint64_t measured_cuts(tetcut::Cutter& cutter, const std::vector<tetcut::Vec3>& centres) {
  std::uint64_t removed = 0;
  for (const tetcut::Vec3& c : centres) removed += cutter.cut(c).tets_removed;
  return removed;
}

}  // namespace

int main() {
  tetcut::TetMesh mesh = tetcut::bench::corpus_mesh("liver.msh");
  const std::vector<tetcut::Vec3> centres = tetcut::bench::gated_sweep_centres();
  tetcut::Cutter cutter(mesh, {.tool_diameter = tetcut::bench::kGatedToolDiameter});
  const std::uint64_t removed = measured_cuts(cutter, centres);
  std::printf("measured_cuts %zu removed %llu\n", centres.size(), static_cast<unsigned long long>(removed));
  std::printf("toolchain %s\n", TETCUT_TOOLCHAIN);
  return 0;
}
