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
  double sum = 0;
  std::thread reader([&] {
    while (!done.load()) {
      // The bug: the live mesh, no snapshot.
      for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v) sum += mesh.position(VertId{v}).x;
    }
  });
  int cuts = 0;
  for (int k = 0; k < 40; ++k) cuts += cutter.cut({0.1 + 0.02 * k, 0.5, 0.5}).ok ? 1 : 0;
  done = true;
  reader.join();
  std::printf("planted race: %d cuts, checksum %.3f\n", cuts, sum);
  return 0;
}
