// Points ordered along the Morton curve (Z-order) of their bounding box: neighbours in space come
// near each other in the order, so ids numbered this way put a cut's tets near each other in
// memory (TetMesh::compact(), design: performance). Written here rather than taken from CGAL's
// spatial_sort: the engine's core links no CGAL, and a Morton key is twenty lines whose result is
// fixed bit for bit (a key is computed in plain doubles, without contraction, the same on every
// compiler), where a median-split Hilbert sort would tie the order to CGAL's version.
#pragma once

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <span>
#include <vector>

#include "tetcut/bounding_box.hpp"
#include "tetcut/vec3.hpp"

namespace tetcut {

// The Morton key of points in `box`: 21 bits a coordinate, interleaved (x lowest).
class MortonKey {
 public:
  explicit MortonKey(const BoundingBox& box)
      : lo_(box.lo), extent_(std::max({box.hi.x - box.lo.x, box.hi.y - box.lo.y, box.hi.z - box.lo.z, 1e-300})) {}

  [[nodiscard]] std::uint64_t operator()(const Vec3& p) const {
    return spread(cell(p.x, lo_.x)) | spread(cell(p.y, lo_.y)) << 1 | spread(cell(p.z, lo_.z)) << 2;
  }

 private:
  static constexpr double kCells = 2097151.0;  // 2^21 - 1

  // A coordinate outside the box (it should not be) is clamped to it.
  [[nodiscard]] std::uint64_t cell(double c, double lo) const {
    const double u = (c - lo) / extent_ * kCells;
    return u > 0.0 ? static_cast<std::uint64_t>(std::min(u, kCells)) : 0;
  }
  // The 21 low bits of x, two zero bits between each.
  static std::uint64_t spread(std::uint64_t x) {
    x &= 0x1fffff;
    x = (x | x << 32) & 0x1f00000000ffffULL;
    x = (x | x << 16) & 0x1f0000ff0000ffULL;
    x = (x | x << 8) & 0x100f00f00f00f00fULL;
    x = (x | x << 4) & 0x10c30c30c30c30c3ULL;
    x = (x | x << 2) & 0x1249249249249249ULL;
    return x;
  }

  Vec3 lo_;
  double extent_;
};

// The indices 0..keys.size()-1 in the order of their keys; equal keys keep their order.
inline std::vector<std::uint32_t> order_by_key(std::span<const std::uint64_t> keys) {
  std::vector<std::uint32_t> order(keys.size());
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return keys[a] < keys[b]; });
  return order;
}

}  // namespace tetcut
