#include "no_degradation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "tet_checks.hpp"
#include "tet_quality.hpp"

namespace tetcut::invariants::detail {
namespace {

// Six times the signed volume, the checker's own determinant.
double volume6(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const Vec3 u = b - a, v = c - a, w = d - a;
  return u.x * (v.y * w.z - v.z * w.y) - u.y * (v.x * w.z - v.z * w.x) + u.z * (v.x * w.y - v.y * w.x);
}

// A barycentric coordinate this far below 0 is still "inside": the rounding of a determinant of
// the tet's own edge vectors, relative to its volume, for the tets a cut makes.
constexpr double kInsideTolerance = 1e-9;

}  // namespace

void NoDegradationCheck::begin() {
  removed_.clear();
  created_.clear();
}

void NoDegradationCheck::add_removed(std::uint32_t t, const RawTet& q) {
  removed_.push_back({t, q, std::numeric_limits<double>::quiet_NaN(), {}, {}});
}

void NoDegradationCheck::add_created(std::uint32_t t, const RawTet& q, double radius_ratio) {
  created_.push_back({t, q, radius_ratio});
}

bool NoDegradationCheck::hosts(const Removed& r, const Vec3& point, std::span<const Vec3> positions) const {
  const Vec3 slack = 1e-9 * (r.hi - r.lo);
  if (point.x < r.lo.x - slack.x || point.y < r.lo.y - slack.y || point.z < r.lo.z - slack.z || point.x > r.hi.x + slack.x ||
      point.y > r.hi.y + slack.y || point.z > r.hi.z + slack.z)
    return false;
  const Vec3 p[4] = {positions[r.q[0]], positions[r.q[1]], positions[r.q[2]], positions[r.q[3]]};
  const double whole = volume6(p[0], p[1], p[2], p[3]);
  if (!(whole > 0.0)) return false;
  for (int i = 0; i < 4; ++i) {
    Vec3 x[4] = {p[0], p[1], p[2], p[3]};
    x[i] = point;
    if (volume6(x[0], x[1], x[2], x[3]) / whole < -kInsideTolerance) return false;
  }
  return true;
}

void NoDegradationCheck::locate(const Created& c, std::span<const Vec3> positions) {
  const Vec3 centroid = 0.25 * (positions[c.q[0]] + positions[c.q[1]] + positions[c.q[2]] + positions[c.q[3]]);
  const std::size_t first = hosts_.size();
  // The removed tets sharing a vertex with it first (a split's child keeps a corner of its
  // parent), then, if none holds it, all of them (the central children of a 1:8 split).
  for (std::uint32_t v : c.q) {
    auto it = std::lower_bound(by_vertex_.begin(), by_vertex_.end(), std::make_pair(v, 0u));
    for (; it != by_vertex_.end() && it->first == v; ++it)
      if (std::find(hosts_.begin() + static_cast<std::ptrdiff_t>(first), hosts_.end(), it->second) == hosts_.end() &&
          hosts(removed_[it->second], centroid, positions))
        hosts_.push_back(it->second);
  }
  if (hosts_.size() > first) return;
  for (std::uint32_t k = 0; k < removed_.size(); ++k)
    if (hosts(removed_[k], centroid, positions)) hosts_.push_back(k);
}

void NoDegradationCheck::finish(std::span<const Vec3> positions, double floor, ReportBuilder& report) {
  if (created_.empty() || !(floor > 0.0)) return;
  by_vertex_.clear();
  for (std::uint32_t k = 0; k < removed_.size(); ++k) {
    Removed& r = removed_[k];
    r.lo = r.hi = positions[r.q[0]];
    for (std::uint32_t v : r.q) {
      by_vertex_.push_back({v, k});
      const Vec3& p = positions[v];
      r.lo = {std::min(r.lo.x, p.x), std::min(r.lo.y, p.y), std::min(r.lo.z, p.z)};
      r.hi = {std::max(r.hi.x, p.x), std::max(r.hi.y, p.y), std::max(r.hi.z, p.z)};
    }
  }
  std::sort(by_vertex_.begin(), by_vertex_.end());
  hosts_.clear();
  host_begin_.clear();
  double worst_replaced = std::numeric_limits<double>::infinity();
  std::uint32_t worst_id = 0;
  for (const Created& c : created_) {
    host_begin_.push_back(static_cast<std::uint32_t>(hosts_.size()));
    locate(c, positions);
  }
  host_begin_.push_back(static_cast<std::uint32_t>(hosts_.size()));
  for (std::uint32_t k : hosts_) {
    Removed& r = removed_[k];
    if (std::isnan(r.ratio))
      r.ratio = tet_radius_ratio(positions[r.q[0]], positions[r.q[1]], positions[r.q[2]], positions[r.q[3]]);
    if (r.ratio < worst_replaced) {
      worst_replaced = r.ratio;
      worst_id = r.id;
    }
  }
  const double bound = std::min(floor, worst_replaced);
  for (std::size_t k = 0; k < created_.size(); ++k) {
    const Created& c = created_[k];
    if (c.ratio >= bound) continue;
    report.add(Invariant::kI7Quality, {c.id}, {}, [&] {
      std::string hosts_text;
      for (std::uint32_t h = host_begin_[k]; h < host_begin_[k + 1]; ++h)
        hosts_text += (hosts_text.empty() ? "" : ", ") + str(removed_[hosts_[h]].id) + " (" + num(removed_[hosts_[h]].ratio) + ")";
      return "created tet " + str(c.id) + " has radius ratio " + num(c.ratio) + ", below min(" + num(floor) +
             ", worst replaced " + (std::isfinite(worst_replaced) ? num(worst_replaced) + " (tet " + str(worst_id) + ")" : std::string("none")) +
             "); it replaces " + (hosts_text.empty() ? std::string("no removed tet") : hosts_text);
    });
  }
}

}  // namespace tetcut::invariants::detail
