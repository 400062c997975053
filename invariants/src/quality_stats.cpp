// Quality statistics of a chosen set of tets, and pooling them over many operations: what
// `tetcut stats` reports of the tets the cuts created, measured by the checker's own
// geometry so that the figures owe the engine nothing.
#include "tetcut/invariants/check.hpp"

#include <algorithm>

#include "report_builder.hpp"
#include "tet_checks.hpp"

namespace tetcut::invariants {

QualityStats quality_of(const RawMeshView& mesh, RawIds tets) {
  detail::ReportBuilder unused;  // a floor of 0 judges nothing
  detail::TetGeometryChecker geometry(0.0, unused);
  for (std::uint32_t t : tets) {
    if (t >= mesh.tets.size() || mesh.tets[t][0] == kDeadTetMarker) continue;
    const detail::RawTet& q = mesh.tets[t];
    if (std::any_of(q.begin(), q.end(), [&](std::uint32_t v) { return v >= mesh.positions.size(); })) continue;
    geometry.check(t, q, mesh.positions);
  }
  CheckReport report;
  geometry.finish(report);
  return report.quality;
}

void pool(QualityStats& into, const QualityStats& more) {
  if (more.tets == 0) return;
  if (into.tets == 0) {
    into = more;
    return;
  }
  const double a = static_cast<double>(into.tets), b = static_cast<double>(more.tets);
  into.mean_radius_ratio = (into.mean_radius_ratio * a + more.mean_radius_ratio * b) / (a + b);
  into.mean_min_dihedral_deg = (into.mean_min_dihedral_deg * a + more.mean_min_dihedral_deg * b) / (a + b);
  into.min_radius_ratio = std::min(into.min_radius_ratio, more.min_radius_ratio);
  into.min_dihedral_deg = std::min(into.min_dihedral_deg, more.min_dihedral_deg);
  for (std::size_t i = 0; i < kHistogramBins; ++i) into.radius_ratio_histogram[i] += more.radius_ratio_histogram[i];
  for (std::size_t i = 0; i < kDihedralBins; ++i) into.min_dihedral_histogram[i] += more.min_dihedral_histogram[i];
  into.tets += more.tets;
}

}  // namespace tetcut::invariants
