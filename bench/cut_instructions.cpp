// The deterministic companion of the per-cut timings (issue 7): a fixed cautery sweep on the
// bundled liver whose cuts run inside measured_cuts(), so that
//   valgrind --tool=callgrind --toggle-collect=measured_cuts ...
// counts exactly the instructions of those cuts, whatever else the machine is doing. The
// warm-up cuts run first, outside the function. Prints the number of measured cuts.
#include <cstdio>

#include "bench_meshes.hpp"
#include "tetcut/cut.hpp"

namespace {

constexpr int kWarmUp = 40;

// Not inlined, so callgrind can toggle on it.
[[gnu::noinline]] std::uint64_t measured_cuts(tetcut::Cutter& cutter, const std::vector<tetcut::Vec3>& centres) {
  std::uint64_t removed = 0;
  for (std::size_t i = kWarmUp; i < centres.size(); ++i) removed += cutter.cut(centres[i]).tets_removed;
  return removed;
}

}  // namespace

int main() {
  tetcut::TetMesh mesh = tetcut::bench::corpus_mesh("liver.msh");
  std::vector<tetcut::Vec3> centres;
  for (double z = 60; z <= 150; z += 15)
    for (double y = 40; y <= 180; y += 4) centres.push_back({95, y, z});
  tetcut::Cutter cutter(mesh, {.tool_diameter = 8.0});
  for (int i = 0; i < kWarmUp; ++i) cutter.cut(centres[static_cast<std::size_t>(i)]);
  const std::uint64_t removed = measured_cuts(cutter, centres);
  std::printf("measured_cuts %zu removed %llu\n", centres.size() - kWarmUp, static_cast<unsigned long long>(removed));
  return 0;
}
