// The shape of a set of tets, as the peers compare it: measured by the independent checker
// (invariants/, check_raw), so that tetcut's tets and a peer's are measured by one set of
// formulas, and not by the engine whose output is being judged. The checker's definitions
// (invariants/src/tet_quality.hpp): radius ratio 3r/R (1 for the regular tet, 0 for a flat
// one), minimum dihedral angle in degrees (70.53 for the regular tet).
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <span>

#include "tetcut/vec3.hpp"

namespace tetcut::peers {

struct TetSetQuality {
  std::uint64_t tets = 0;
  double min_radius_ratio = 1.0;   // 1 and 180 when there are no tets, so that min() over sets works
  double min_dihedral_deg = 180.0;
  // Tets that are not strictly positive by the exact orientation predicate (I4): a peer's output
  // with any is not a valid mesh, whatever its quality figures say.
  std::uint64_t not_positive = 0;
  // The sum of the tets' signed volumes: a peer that remeshes a region while keeping its boundary
  // must give it back (to rounding), or its cells do not tile the region they replaced.
  double volume = 0;
  // Tets the checker could not measure (a repeated vertex, an id out of range, a duplicate: I1).
  std::uint64_t unmeasured = 0;

  [[nodiscard]] bool finite() const { return std::isfinite(min_radius_ratio) && std::isfinite(min_dihedral_deg); }
  // Every tet measured, positive, and the figures finite.
  [[nodiscard]] bool valid() const { return not_positive == 0 && unmeasured == 0 && finite(); }
};

// `tets`: #T by 4 ids into `positions` (positions no tet uses are ignored). O(#T + #positions).
TetSetQuality measure_quality(std::span<const Vec3> positions, std::span<const std::array<std::uint32_t, 4>> tets);

}  // namespace tetcut::peers
