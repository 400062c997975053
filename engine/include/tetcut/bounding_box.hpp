// The axis-aligned box around a mesh's live vertices: where a sweep of cuts draws its chords, how
// large a mesh is (its diagonal). O(#V); nothing in a cut calls it.
#pragma once

#include <algorithm>
#include <cstdint>

#include "tetcut/mesh.hpp"
#include "tetcut/vec3.hpp"

namespace tetcut {

struct BoundingBox {
  // Empty (lo above hi) until a point is added.
  Vec3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};

  void add(const Vec3& p) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  [[nodiscard]] Vec3 size() const { return hi - lo; }
  [[nodiscard]] Vec3 centre() const { return 0.5 * (lo + hi); }
  [[nodiscard]] double diagonal() const { return norm(hi - lo); }
};

inline BoundingBox bounding_box(const TetMesh& mesh) {
  BoundingBox box;
  for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v)
    if (mesh.is_live(VertId{v})) box.add(mesh.position(VertId{v}));
  return box;
}

}  // namespace tetcut
