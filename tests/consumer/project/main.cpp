#include <cstdio>

#include "tetcut/box_mesh.hpp"
#include "tetcut/canonical_hash.hpp"
#include "tetcut/cut.hpp"
#include "tetcut/invariants/check.hpp"
#include "tetcut/mesh_builder.hpp"

int main() {
  const tetcut::BuildResult built = tetcut::build_mesh(tetcut::make_box_mesh(2, 2, 2));
  if (!built.ok()) return 1;
  const tetcut::invariants::CheckReport report = tetcut::invariants::check_mesh(built.mesh->raw_view());
  std::printf("tets %u hash %s valid %d\n", built.mesh->num_tets(),
              tetcut::hash_to_hex(tetcut::canonical_hash(*built.mesh)).c_str(), report.ok() ? 1 : 0);

  // A cut through the public API only, then a compaction through the Cutter that holds the mesh.
  tetcut::TetMesh mesh = *built.mesh;
  tetcut::Cutter cutter(mesh, {.tool_diameter = 0.8});
  const tetcut::CutReport cut = cutter.cut({0.5, 0.5, 1.0});
  std::printf("cut ok %d removed %u valid %d\n", cut.ok ? 1 : 0, cut.tets_removed,
              tetcut::invariants::check_mesh(mesh.raw_view()).ok() ? 1 : 0);
  cutter.compact();
  const tetcut::CutReport after = cutter.cut({0.5, 0.5, 0.0});
  std::printf("compacted stale %d refused %d\n", cutter.indexes_current_mesh() ? 0 : 1, after.ok ? 0 : 1);
  return 0;
}
