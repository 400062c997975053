#include "tet_set_quality.hpp"

#include "tetcut/invariants/check.hpp"

namespace tetcut::peers {

TetSetQuality measure_quality(std::span<const Vec3> positions, std::span<const std::array<std::uint32_t, 4>> tets) {
  TetSetQuality out;
  if (tets.empty()) return out;
  // The full level on a set that is not a closed mesh: its link checks (I5, I6) may well complain
  // about the set's own edges, which says nothing about the tets; only quality and I4 are read.
  const invariants::CheckReport report = invariants::check_raw(RawMeshView{positions, tets});
  out.tets = report.quality.tets;
  out.unmeasured = tets.size() - report.quality.tets;
  out.min_radius_ratio = report.quality.min_radius_ratio;
  out.min_dihedral_deg = report.quality.min_dihedral_deg;
  out.volume = report.volume;
  if (const invariants::Violation* inverted = report.find(invariants::Invariant::kI4Orientation))
    out.not_positive = inverted->count;
  return out;
}

}  // namespace tetcut::peers
