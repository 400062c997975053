// Picks live tets with a boundary face at random, one at a time, the way a cautery meets the
// surface (tests and `tetcut remove --random`). Seeded: the same sequence on every platform.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "core/random.hpp"
#include "tetcut/ids.hpp"
#include "tetcut/mesh.hpp"

namespace tetcut {

class BoundaryTetPicker {
 public:
  // O(#T) once: every tet with a boundary face becomes a candidate.
  BoundaryTetPicker(const TetMesh& mesh, std::uint64_t seed);
  // A uniformly chosen candidate that is still live and on the boundary; kNoTet when none.
  TetId pick(const TetMesh& mesh);
  // Tets that may have reached the boundary since (e.g. Remover::last_exposed()).
  void add(std::span<const TetId> tets);

 private:
  std::vector<TetId> pool_;
  std::vector<std::uint8_t> in_pool_;
  SplitMix64 rng_;
};

}  // namespace tetcut
