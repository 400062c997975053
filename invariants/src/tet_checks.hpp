// Per-tet checks shared by the full and the local level: references (I1), exact orientation
// (I4), quality (I7 and the statistics) and volume.
#pragma once

#include <cstdint>
#include <span>

#include "report_builder.hpp"
#include "tetcut/vec3.hpp"
#include "vertex_link.hpp"

namespace tetcut::invariants::detail {

// I1 without duplicates (those need the shells): 4 distinct vertices, each in range and at a
// finite position. Reports and returns false otherwise.
bool check_references(std::uint32_t t, const RawTet& q, std::span<const Vec3> positions, ReportBuilder& report);

// det(b - a, c - a, d - a) / 6 in plain floating point.
double tet_volume(const RawTet& q, std::span<const Vec3> positions);
// A bound on the rounding error of tet_volume: it is a determinant of edge vectors, so its error
// scales with the product of their lengths, not with the volume (a sliver's volume can be all
// rounding).
double tet_volume_rounding_bound(const RawTet& q, std::span<const Vec3> positions);

// Compensated (Neumaier) sum: a million volumes add up to the same total whichever way the
// mesh was cut, to well within I9's relative tolerance.
class VolumeSum {
 public:
  void add(double x);
  [[nodiscard]] double value() const { return sum_ + compensation_; }

 private:
  double sum_ = 0.0;
  double compensation_ = 0.0;
};

// I4 and I7 over a sequence of tets whose references are valid, plus quality statistics and
// the signed volume.
class TetGeometryChecker {
 public:
  TetGeometryChecker(double radius_ratio_floor, ReportBuilder& report)
      : floor_(radius_ratio_floor), report_(report) {}

  // The tet's radius ratio and smallest dihedral angle (degrees).
  struct Shape {
    double ratio, dihedral_deg;
  };
  Shape check(std::uint32_t t, const RawTet& q, std::span<const Vec3> positions);
  // Quality statistics and volume into the report.
  void finish(CheckReport& report) const;
  [[nodiscard]] double volume() const { return volume_.value(); }

 private:
  double floor_;
  ReportBuilder& report_;
  QualityStats stats_;
  double sum_ratio_ = 0.0;
  double sum_dihedral_ = 0.0;
  VolumeSum volume_;
};

// |actual - expected| <= tolerance * scale, reported as I9 with `what` in the detail.
void check_volume(double actual, double expected, double scale, double rel_tolerance, const char* what,
                  ReportBuilder& report, double rounding_allowance = 0.0);

}  // namespace tetcut::invariants::detail
