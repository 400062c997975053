#include <cstdio>

#include "tetcut/box_mesh.hpp"
#include "tetcut/canonical_hash.hpp"
#include "tetcut/invariants/check.hpp"
#include "tetcut/mesh_builder.hpp"

int main() {
  const tetcut::BuildResult built = tetcut::build_mesh(tetcut::make_box_mesh(2, 2, 2));
  if (!built.ok()) return 1;
  const tetcut::invariants::CheckReport report = tetcut::invariants::check_mesh(built.mesh->raw_view());
  std::printf("tets %u hash %s valid %d\n", built.mesh->num_tets(),
              tetcut::hash_to_hex(tetcut::canonical_hash(*built.mesh)).c_str(), report.ok() ? 1 : 0);
  return 0;
}
