#include "tetcut/boundary_tet_picker.hpp"

namespace tetcut {

BoundaryTetPicker::BoundaryTetPicker(const TetMesh& mesh, std::uint64_t seed) : rng_(seed) {
  in_pool_.assign(mesh.tet_capacity(), 0);
  for (std::uint32_t i = 0; i < mesh.tet_capacity(); ++i) {
    const TetId t{i};
    if (mesh.is_live(t) && mesh.boundary_face_count(t) > 0) {
      pool_.push_back(t);
      in_pool_[i] = 1;
    }
  }
}

void BoundaryTetPicker::add(std::span<const TetId> tets) {
  for (TetId t : tets) {
    if (t.value >= in_pool_.size()) in_pool_.resize(t.value + t.value / 4 + 16, 0);
    if (in_pool_[t.value]) continue;
    in_pool_[t.value] = 1;
    pool_.push_back(t);
  }
}

TetId BoundaryTetPicker::pick(const TetMesh& mesh) {
  while (!pool_.empty()) {
    const std::uint32_t i = rng_.below(static_cast<std::uint32_t>(pool_.size()));
    const TetId t = pool_[i];
    if (mesh.is_live(t) && mesh.boundary_face_count(t) > 0) return t;
    // Gone (or no longer on the surface): drop it.
    in_pool_[t.value] = 0;
    pool_[i] = pool_.back();
    pool_.pop_back();
  }
  return kNoTet;
}

}  // namespace tetcut
