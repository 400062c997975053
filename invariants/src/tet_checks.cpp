#include "tet_checks.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "tet_quality.hpp"
#include "tetcut/predicates.hpp"

namespace tetcut::invariants::detail {

bool check_references(std::uint32_t t, const RawTet& q, std::span<const Vec3> positions, ReportBuilder& report) {
  for (int i = 0; i < 4; ++i) {
    if (q[i] >= positions.size()) {
      report.add(Invariant::kI1References, {t}, {}, [&] {
        return "tet " + str(t) + " references vertex " + str(q[i]) + ", but there are only " +
               str(static_cast<std::uint32_t>(positions.size())) + " vertices";
      });
      return false;
    }
  }
  for (int i = 0; i < 4; ++i) {
    for (int j = i + 1; j < 4; ++j) {
      if (q[i] == q[j]) {
        report.add(Invariant::kI1References, {t}, {q[i]}, [&] {
          return "tet " + str(t) + " lists vertex " + str(q[i]) + " twice";
        });
        return false;
      }
    }
  }
  for (int i = 0; i < 4; ++i) {
    if (!is_finite(positions[q[i]])) {
      report.add(Invariant::kI1References, {t}, {q[i]}, [&] {
        return "tet " + str(t) + " references vertex " + str(q[i]) + " at a non-finite position";
      });
      return false;
    }
  }
  return true;
}

double tet_volume(const RawTet& q, std::span<const Vec3> positions) {
  const Vec3& a = positions[q[0]];
  return dot(positions[q[1]] - a, cross(positions[q[2]] - a, positions[q[3]] - a)) / 6.0;
}

double tet_volume_rounding_bound(const RawTet& q, std::span<const Vec3> positions) {
  const Vec3& a = positions[q[0]];
  const double product = norm(positions[q[1]] - a) * norm(positions[q[2]] - a) * norm(positions[q[3]] - a);
  return 16.0 * std::numeric_limits<double>::epsilon() * product / 6.0;
}

void VolumeSum::add(double x) {
  const double t = sum_ + x;
  if (std::fabs(sum_) >= std::fabs(x)) compensation_ += (sum_ - t) + x;
  else compensation_ += (x - t) + sum_;
  sum_ = t;
}

TetGeometryChecker::Shape TetGeometryChecker::check(std::uint32_t t, const RawTet& q, std::span<const Vec3> positions) {
  const Vec3& a = positions[q[0]];
  const Vec3& b = positions[q[1]];
  const Vec3& c = positions[q[2]];
  const Vec3& d = positions[q[3]];
  const int sign = orientation(a, b, c, d);
  if (sign <= 0) {
    report_.add(Invariant::kI4Orientation, {t}, {q[0], q[1], q[2], q[3]}, [&] {
      return "tet " + str(t) + " (" + str(q[0]) + ", " + str(q[1]) + ", " + str(q[2]) + ", " + str(q[3]) +
             ") is " + (sign < 0 ? "inverted" : "flat") + " by the exact orientation predicate";
    });
  }
  volume_.add(tet_volume(q, positions));

  const double ratio = tet_radius_ratio(a, b, c, d);
  const double dihedral = tet_min_dihedral_deg(a, b, c, d);
  if (stats_.tets == 0) {
    stats_.min_radius_ratio = ratio;
    stats_.min_dihedral_deg = dihedral;
  }
  ++stats_.tets;
  stats_.min_radius_ratio = std::min(stats_.min_radius_ratio, ratio);
  stats_.min_dihedral_deg = std::min(stats_.min_dihedral_deg, dihedral);
  sum_ratio_ += ratio;
  sum_dihedral_ += dihedral;
  // NaN-safe binning: anything not in [0, 1) by comparison goes to an end bin.
  std::size_t bin = 0;
  if (ratio >= 1.0) bin = kHistogramBins - 1;
  else if (ratio > 0.0) bin = std::min(kHistogramBins - 1, static_cast<std::size_t>(ratio * kHistogramBins));
  ++stats_.radius_ratio_histogram[bin];
  std::size_t angle_bin = kDihedralBins - 1;
  if (dihedral >= 0.0 && dihedral < 5.0 * static_cast<double>(kDihedralBins - 1)) angle_bin = static_cast<std::size_t>(dihedral / 5.0);
  else if (!(dihedral >= 0.0)) angle_bin = 0;
  ++stats_.min_dihedral_histogram[angle_bin];
  if (floor_ > 0.0 && !(ratio >= floor_)) {
    report_.add(Invariant::kI7Quality, {t}, {}, [&] {
      return "tet " + str(t) + " has radius ratio " + num(ratio) + ", below the floor " + num(floor_);
    });
  }
  return {ratio, dihedral};
}

void TetGeometryChecker::finish(CheckReport& report) const {
  report.quality = stats_;
  if (stats_.tets > 0) {
    report.quality.mean_radius_ratio = sum_ratio_ / static_cast<double>(stats_.tets);
    report.quality.mean_min_dihedral_deg = sum_dihedral_ / static_cast<double>(stats_.tets);
  }
}

void check_volume(double actual, double expected, double scale, double rel_tolerance, const char* what,
                  ReportBuilder& report, double rounding_allowance) {
  const double allowed = rel_tolerance * std::max(std::fabs(scale), 1e-300) + rounding_allowance;
  if (std::fabs(actual - expected) <= allowed) return;
  report.add(Invariant::kI9Volume, {}, {}, [&] {
    return std::string(what) + " is " + num(actual) + ", expected " + num(expected) + " (relative tolerance " +
           num(rel_tolerance) + ")";
  });
}

}  // namespace tetcut::invariants::detail
