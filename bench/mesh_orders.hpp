// The ids of a mesh shuffled with a fixed seed: a large mesh whose tets lie scattered in memory,
// as one assembled or edited over time has them (TetMesh::compact() sorts them back along a
// space-filling curve). The same tets and vertices, so a sweep does the same work up to the ties
// the engine breaks by id; what changes is the memory each cut touches.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <numeric>
#include <random>
#include <vector>

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

}  // namespace tetcut::bench
