// Shared by the mechanics tests: the bundled meshes, a lancet sweep through them, and labels
// with a material each, so that a label inherited wrongly changes the tensors.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

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

struct Bounds {
  Vec3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  [[nodiscard]] double diagonal() const { return norm(hi - lo); }
};
inline Bounds bounds_of(const TetMesh& mesh) {
  Bounds b;
  for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v) {
    if (!mesh.is_live(VertId{v})) continue;
    const Vec3 p = mesh.position(VertId{v});
    b.lo = {std::min(b.lo.x, p.x), std::min(b.lo.y, p.y), std::min(b.lo.z, p.z)};
    b.hi = {std::max(b.hi.x, p.x), std::max(b.hi.y, p.y), std::max(b.hi.z, p.z)};
  }
  return b;
}

// `cuts` tool centres along the longest axis of the box, through its middle (the paper's lancet).
inline std::vector<Vec3> lancet_sweep(const Bounds& b, int cuts) {
  std::vector<Vec3> out;
  const Vec3 size = b.hi - b.lo, mid = 0.5 * (b.lo + b.hi);
  const int axis = size.x >= size.y && size.x >= size.z ? 0 : size.y >= size.z ? 1 : 2;
  for (int i = 0; i < cuts; ++i) {
    Vec3 p = mid;
    const double s = cuts == 1 ? 0.5 : 0.1 + 0.8 * i / (cuts - 1);
    if (axis == 0) p.x = b.lo.x + s * size.x;
    if (axis == 1) p.y = b.lo.y + s * size.y;
    if (axis == 2) p.z = b.lo.z + s * size.z;
    out.push_back(p);
  }
  return out;
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
