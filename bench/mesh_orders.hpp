// The ids of a mesh in another order: shuffled with a fixed seed (a large mesh whose tets lie
// scattered in memory, as one assembled or edited over time has them), or sorted along a
// space-filling curve (neighbours in space near in memory). The same tets and vertices, so a
// sweep does the same work up to the ties the engine breaks by id; what changes is the memory
// each cut touches.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <numeric>
#include <random>
#include <vector>

#include "tetcut/bounding_box.hpp"
#include "tetcut/raw_mesh.hpp"

namespace tetcut::bench {

// The fixed seed of every shuffled mesh the gate measures: a new seed is a new figure.
inline constexpr std::uint64_t kShuffleSeed = 20261128;

// A permutation of 0..n-1 drawn from `seed`, the same on every platform: Fisher-Yates on
// mt19937_64, whose output the standard fixes (std::shuffle's algorithm is the library's own).
inline std::vector<std::uint32_t> seeded_permutation(std::uint32_t n, std::uint64_t seed) {
  std::vector<std::uint32_t> p(n);
  std::iota(p.begin(), p.end(), 0u);
  std::mt19937_64 rng(seed);
  for (std::uint32_t i = n; i > 1; --i) std::swap(p[i - 1], p[rng() % i]);
  return p;
}

// `mesh` with tet k of the result being tet tet_order[k] of the input, and vertex j of the
// result vertex vert_order[j] of the input (labels follow their tets).
inline RawMesh renumbered(const RawMesh& mesh, const std::vector<std::uint32_t>& tet_order,
                          const std::vector<std::uint32_t>& vert_order) {
  std::vector<std::uint32_t> new_id(vert_order.size());
  for (std::uint32_t j = 0; j < vert_order.size(); ++j) new_id[vert_order[j]] = j;
  RawMesh out;
  out.positions.reserve(mesh.positions.size());
  for (std::uint32_t v : vert_order) out.positions.push_back(mesh.positions[v]);
  out.tets.reserve(mesh.tets.size());
  for (std::uint32_t t : tet_order) {
    const auto& old = mesh.tets[t];
    out.tets.push_back({new_id[old[0]], new_id[old[1]], new_id[old[2]], new_id[old[3]]});
    if (mesh.labelled()) out.labels.push_back(mesh.labels[t]);
  }
  return out;
}

// Tets and vertices in an order drawn from `seed`.
inline RawMesh shuffled(const RawMesh& mesh, std::uint64_t seed = kShuffleSeed) {
  return renumbered(mesh, seeded_permutation(static_cast<std::uint32_t>(mesh.tets.size()), seed),
                    seeded_permutation(static_cast<std::uint32_t>(mesh.positions.size()), seed + 1));
}

// Tets (by centroid) and vertices sorted along the Morton curve (Z-order) of the mesh's box:
// 21 bits a coordinate, interleaved; ties keep the input's order.
inline RawMesh curve_sorted(const RawMesh& mesh) {
  BoundingBox box;
  for (const Vec3& p : mesh.positions) box.add(p);
  const Vec3 lo = box.lo, hi = box.hi;
  const double extent = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z, 1e-300});
  const auto spread = [](std::uint64_t x) {  // the 21 low bits of x, two zero bits between each
    x &= 0x1fffff;
    x = (x | x << 32) & 0x1f00000000ffffULL;
    x = (x | x << 16) & 0x1f0000ff0000ffULL;
    x = (x | x << 8) & 0x100f00f00f00f00fULL;
    x = (x | x << 4) & 0x10c30c30c30c30c3ULL;
    x = (x | x << 2) & 0x1249249249249249ULL;
    return x;
  };
  const auto key = [&](const Vec3& p) {
    const auto cell = [&](double c, double l) { return static_cast<std::uint64_t>((c - l) / extent * 2097151.0); };
    return spread(cell(p.x, lo.x)) | spread(cell(p.y, lo.y)) << 1 | spread(cell(p.z, lo.z)) << 2;
  };
  const auto sorted_by = [](std::vector<std::uint64_t> keys) {
    std::vector<std::uint32_t> order(keys.size());
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return keys[a] < keys[b]; });
    return order;
  };
  std::vector<std::uint64_t> vert_keys, tet_keys;
  vert_keys.reserve(mesh.positions.size());
  for (const Vec3& p : mesh.positions) vert_keys.push_back(key(p));
  tet_keys.reserve(mesh.tets.size());
  for (const auto& t : mesh.tets)
    tet_keys.push_back(key(0.25 * (mesh.positions[t[0]] + mesh.positions[t[1]] + mesh.positions[t[2]] + mesh.positions[t[3]])));
  return renumbered(mesh, sorted_by(std::move(tet_keys)), sorted_by(std::move(vert_keys)));
}

}  // namespace tetcut::bench
