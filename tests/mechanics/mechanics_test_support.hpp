// Shared by the mechanics tests: the bundled meshes, a lancet sweep through them, and labels
// with a material each, so that a label inherited wrongly changes the tensors.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "../engine/test_meshes.hpp"  // test_name_of_mesh, lancet_sweep
#include "tetcut/io.hpp"
#include "tetcut/mechanics/tensor_mass.hpp"
#include "tetcut/mesh_builder.hpp"

namespace tetcut::testing {

inline TetMesh load_bundled(const std::string& name) {
  ReadResult read = read_mesh(std::string(TETCUT_CORPUS_DIR) + "/meshes/" + name);
  if (!read.mesh) {
    ADD_FAILURE() << "cannot read " << name;
    return {};
  }
  BuildResult built = build_mesh(*read.mesh);
  if (!built.ok()) {
    ADD_FAILURE() << "cannot build " << name;
    return {};
  }
  return std::move(*built.mesh);
}

// Labels 0..3 by a hash of the tet id, each with its own Young's modulus: a tet that inherits
// the wrong label has tensors of another size.
inline std::vector<std::uint32_t> hashed_labels(const TetMesh& mesh) {
  std::vector<std::uint32_t> labels(mesh.tet_capacity());
  for (std::uint32_t t = 0; t < labels.size(); ++t) labels[t] = (t * 2654435761u >> 7) % 4;
  return labels;
}
inline mechanics::ModelParams four_materials() {
  mechanics::ModelParams p;
  p.materials = {{3000, 0.45, 1000}, {6000, 0.40, 1050}, {1500, 0.45, 980}, {12000, 0.30, 1100}};
  return p;
}

inline bool sanitized_build() {
#if defined(__SANITIZE_ADDRESS__)
  return true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
  return true;
#endif
#endif
  return false;
}

}  // namespace tetcut::testing
