// A planted data race, wrong on purpose: proof that ci/test's ThreadSanitizer run has teeth.
// A reader thread reads the live mesh's positions while the cutting thread cuts, which the
// threading contract (thread_contract.hpp) forbids: a reader on another thread reads a
// SnapshotPublisher frame, never the live mesh. TetMesh::position() takes no read scope, so the
// contract's run-time check does not see this; ThreadSanitizer must (the test passes only when
// its output says "data race").
#include <atomic>
#include <cstdio>
#include <thread>

#include "tetcut/box_mesh.hpp"
#include "tetcut/cut.hpp"
#include "tetcut/mesh_builder.hpp"

int main() {
  using namespace tetcut;
  BuildResult built = build_mesh(make_box_mesh(8, 8, 8));
  if (!built.mesh) return 2;
  TetMesh mesh = std::move(*built.mesh);
  Cutter cutter(mesh, {.tool_diameter = 0.2});
  std::atomic<bool> done{false};
  std::atomic<int> passes{0};
  double sum = 0;
  std::thread reader([&] {
    while (!done.load()) {
      // The bug: the live mesh, no snapshot.
      for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v) sum += mesh.position(VertId{v}).x;
      passes.fetch_add(1);
    }
  });
  // The reader must read while or after the cuts write, with nothing ordering the two: on a
  // loaded machine it was once scheduled only after `done`, read nothing, and left no race to
  // report. So the cuts wait for its first pass, and `done` for a whole pass begun after them
  // (counting passes orders the reader's reads before this thread's later steps, never this
  // thread's writes before its reads).
  while (passes.load() == 0) std::this_thread::yield();
  int cuts = 0;
  for (int k = 0; k < 40; ++k) cuts += cutter.cut({0.1 + 0.02 * k, 0.5, 0.5}).ok ? 1 : 0;
  for (const int seen = passes.load(); passes.load() < seen + 2;) std::this_thread::yield();
  done = true;
  reader.join();
  std::printf("planted race: %d cuts, checksum %.3f\n", cuts, sum);
  return 0;
}
