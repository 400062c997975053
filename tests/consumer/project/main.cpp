#include <cstdio>

#include "tetcut/box_mesh.hpp"
#include "tetcut/canonical_hash.hpp"
#include "tetcut/mesh_builder.hpp"

int main() {
  const tetcut::BuildResult built = tetcut::build_mesh(tetcut::make_box_mesh(2, 2, 2));
  if (!built.ok()) return 1;
  std::printf("tets %u hash %s\n", built.mesh->num_tets(), tetcut::hash_to_hex(tetcut::canonical_hash(*built.mesh)).c_str());
  return 0;
}
