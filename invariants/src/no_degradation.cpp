#include "no_degradation.hpp"

#include <array>
#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <string>

#include "tet_checks.hpp"
#include "tet_intersection.hpp"
#include "tet_quality.hpp"
#include "tissue_rule.hpp"

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

// A split child keeps its parent's dihedral angles at the parent's edges: equal angles, each
// computed from its own tet's normals, may differ by rounding (1e-13 degrees and less). An angle
// this close to its floor meets it.
constexpr double kAngleTolerance = 1e-7;

// The mesh rule's volumes agree to this share of the created tets' volume: the shared volume of
// a child and its parent is the child's volume up to the clip's rounding.
constexpr double kVolumeTolerance = 1e-9;

// The unsigned volume, for the mesh rule's sums.
double tet_volume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) { return std::abs(volume6(a, b, c, d)) / 6.0; }

}  // namespace

void NoDegradationCheck::begin() {
  removed_.clear();
  created_.clear();
}

void NoDegradationCheck::add_removed(std::uint32_t t, const RawTet& q) {
  removed_.push_back({t, q, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN(), {}, {}});
}

void NoDegradationCheck::add_created(std::uint32_t t, const RawTet& q, double radius_ratio, double min_dihedral_deg) {
  created_.push_back({t, q, radius_ratio, min_dihedral_deg});
}

void NoDegradationCheck::measure(Removed& r, std::span<const Vec3> old_positions) const {
  if (!std::isnan(r.ratio)) return;
  const Vec3 &a = old_positions[r.q[0]], &b = old_positions[r.q[1]], &c = old_positions[r.q[2]],
             &d = old_positions[r.q[3]];
  r.ratio = tet_radius_ratio(a, b, c, d);
  r.dihedral = tet_min_dihedral_deg(a, b, c, d);
}

bool NoDegradationCheck::hosts(const Removed& r, const Vec3& point, std::span<const Vec3> old_positions) const {
  const Vec3 slack = 1e-9 * (r.hi - r.lo);
  if (point.x < r.lo.x - slack.x || point.y < r.lo.y - slack.y || point.z < r.lo.z - slack.z || point.x > r.hi.x + slack.x ||
      point.y > r.hi.y + slack.y || point.z > r.hi.z + slack.z)
    return false;
  const Vec3 p[4] = {old_positions[r.q[0]], old_positions[r.q[1]], old_positions[r.q[2]], old_positions[r.q[3]]};
  const double whole = volume6(p[0], p[1], p[2], p[3]);
  if (!(whole > 0.0)) return false;
  for (int i = 0; i < 4; ++i) {
    Vec3 x[4] = {p[0], p[1], p[2], p[3]};
    x[i] = point;
    if (volume6(x[0], x[1], x[2], x[3]) / whole < -kInsideTolerance) return false;
  }
  return true;
}

void NoDegradationCheck::locate(const Created& c, std::span<const Vec3> old_positions,
                                std::span<const Vec3> positions) {
  const Vec3 centroid = 0.25 * (positions[c.q[0]] + positions[c.q[1]] + positions[c.q[2]] + positions[c.q[3]]);
  const std::size_t first = hosts_.size();
  // The removed tets sharing a vertex with it first (a split's child keeps a corner of its
  // parent), then, if none holds it, all of them (the central children of a 1:8 split).
  for (std::uint32_t v : c.q) {
    auto it = std::lower_bound(by_vertex_.begin(), by_vertex_.end(), std::make_pair(v, 0u));
    for (; it != by_vertex_.end() && it->first == v; ++it)
      if (std::find(hosts_.begin() + static_cast<std::ptrdiff_t>(first), hosts_.end(), it->second) == hosts_.end() &&
          hosts(removed_[it->second], centroid, old_positions))
        hosts_.push_back(it->second);
  }
  if (hosts_.size() > first) return;
  for (std::uint32_t k = 0; k < removed_.size(); ++k)
    if (hosts(removed_[k], centroid, old_positions)) hosts_.push_back(k);
}

void NoDegradationCheck::finish(std::span<const Vec3> old_positions, std::span<const Vec3> positions, double floor,
                                double min_dihedral_deg, const ToolRule* tool, ReportBuilder& report) {
  if (created_.empty() || !(floor > 0.0 || min_dihedral_deg > 0.0)) return;
  by_vertex_.clear();
  for (std::uint32_t k = 0; k < removed_.size(); ++k) {
    Removed& r = removed_[k];
    r.lo = r.hi = old_positions[r.q[0]];
    for (std::uint32_t v : r.q) {
      by_vertex_.push_back({v, k});
      const Vec3& p = old_positions[v];
      r.lo = {std::min(r.lo.x, p.x), std::min(r.lo.y, p.y), std::min(r.lo.z, p.z)};
      r.hi = {std::max(r.hi.x, p.x), std::max(r.hi.y, p.y), std::max(r.hi.z, p.z)};
    }
  }
  std::sort(by_vertex_.begin(), by_vertex_.end());
  hosts_.clear();
  host_begin_.clear();
  // Only the tets below F or theta need their hosts.
  auto needs_hosts = [&](const Created& c) { return c.ratio < floor || c.dihedral < min_dihedral_deg; };
  double worst_ratio = std::numeric_limits<double>::infinity(), worst_dihedral = worst_ratio;
  for (const Created& c : created_) {
    host_begin_.push_back(static_cast<std::uint32_t>(hosts_.size()));
    if (needs_hosts(c)) locate(c, old_positions, positions);
  }
  host_begin_.push_back(static_cast<std::uint32_t>(hosts_.size()));
  for (std::uint32_t k : hosts_) {
    measure(removed_[k], old_positions);
    worst_ratio = std::min(worst_ratio, removed_[k].ratio);
    worst_dihedral = std::min(worst_dihedral, removed_[k].dihedral);
  }
  for (std::size_t k = 0; k < created_.size(); ++k) {
    const Created& c = created_[k];
    if (!needs_hosts(c)) continue;
    // Its own hosts' worst; the operation's worst host when none holds its centroid.
    double host_ratio = host_begin_[k] == host_begin_[k + 1] ? worst_ratio : std::numeric_limits<double>::infinity();
    double host_dihedral = host_begin_[k] == host_begin_[k + 1] ? worst_dihedral : std::numeric_limits<double>::infinity();
    for (std::uint32_t h = host_begin_[k]; h < host_begin_[k + 1]; ++h) {
      host_ratio = std::min(host_ratio, removed_[hosts_[h]].ratio);
      host_dihedral = std::min(host_dihedral, removed_[hosts_[h]].dihedral);
    }
    const double ratio_bound = std::min(floor, host_ratio), dihedral_bound = std::min(min_dihedral_deg, host_dihedral);
    if (c.ratio >= ratio_bound && c.dihedral >= dihedral_bound - kAngleTolerance) continue;
    report.add(Invariant::kI7Quality, {c.id}, {}, [&] {
      std::string hosts_text;
      for (std::uint32_t h = host_begin_[k]; h < host_begin_[k + 1]; ++h) {
        const Removed& r = removed_[hosts_[h]];
        hosts_text += (hosts_text.empty() ? "" : ", ") + str(r.id) + " (" + num(r.ratio) + ", " + num(r.dihedral) + " deg)";
      }
      return "created tet " + str(c.id) + " has radius ratio " + num(c.ratio) + " (floor " + num(ratio_bound) +
             " = min(" + num(floor) + ", its hosts')) and smallest dihedral angle " + num(c.dihedral) + " deg (floor " +
             num(dihedral_bound) + " = min(" + num(min_dihedral_deg) + ", its hosts')); its hosts: " +
             (hosts_text.empty() ? std::string("none holds its centroid, the operation's worst taken") : hosts_text);
    });
  }
  if (min_dihedral_deg > 0.0) check_bad_volume(old_positions, positions, min_dihedral_deg, tool, report);
}

double NoDegradationCheck::bad_volume_under(const Created& c, std::span<const Vec3> old_positions,
                                            std::span<const Vec3> positions, double min_dihedral_deg, bool all) {
  const std::array<Vec3, 4> corners = {positions[c.q[0]], positions[c.q[1]], positions[c.q[2]], positions[c.q[3]]};
  Vec3 lo = corners[0], hi = corners[0];
  for (const Vec3& p : corners) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  candidates_.clear();
  if (all) {
    for (std::uint32_t k = 0; k < removed_.size(); ++k) candidates_.push_back(k);
  } else {
    for (std::uint32_t v : c.q)
      for (auto it = std::lower_bound(by_vertex_.begin(), by_vertex_.end(), std::make_pair(v, 0u));
           it != by_vertex_.end() && it->first == v; ++it)
        candidates_.push_back(it->second);
    const Vec3 centroid = 0.25 * (corners[0] + corners[1] + corners[2] + corners[3]);
    for (std::uint32_t k = 0; k < removed_.size(); ++k)
      if (hosts(removed_[k], centroid, old_positions)) candidates_.push_back(k);
    std::sort(candidates_.begin(), candidates_.end());
    candidates_.erase(std::unique(candidates_.begin(), candidates_.end()), candidates_.end());
  }
  double shared = 0.0;
  for (std::uint32_t k : candidates_) {
    Removed& r = removed_[k];
    if (r.hi.x < lo.x || r.hi.y < lo.y || r.hi.z < lo.z || r.lo.x > hi.x || r.lo.y > hi.y || r.lo.z > hi.z) continue;
    measure(r, old_positions);
    if (!(r.dihedral < min_dihedral_deg)) continue;
    shared += tet_intersection_volume(
        corners, {old_positions[r.q[0]], old_positions[r.q[1]], old_positions[r.q[2]], old_positions[r.q[3]]});
  }
  return shared;
}

void NoDegradationCheck::check_bad_volume(std::span<const Vec3> old_positions, std::span<const Vec3> positions,
                                          double min_dihedral_deg, const ToolRule* tool, ReportBuilder& report) {
  // The created tets outside the tool, and after: the volume of those below theta. A created tet
  // within rounding of theta is not below it (a split child keeps its parent's angles).
  outside_.clear();
  double after = 0.0, scale = 0.0;
  for (std::uint32_t k = 0; k < created_.size(); ++k) {
    const Created& c = created_[k];
    const Vec3 centroid = 0.25 * (positions[c.q[0]] + positions[c.q[1]] + positions[c.q[2]] + positions[c.q[3]]);
    if (tool && distance_to_axis(*tool, centroid) < tool->radius) continue;
    outside_.push_back(k);
    const double volume = tet_volume(positions[c.q[0]], positions[c.q[1]], positions[c.q[2]], positions[c.q[3]]);
    scale += volume;
    if (c.dihedral < min_dihedral_deg - kAngleTolerance) after += volume;
  }
  if (after == 0.0) return;
  // Before: a lower bound from the removed tets each created one shares a vertex with or sits in
  // (every pair a split or a flip makes), and only if that falls short, every removed tet.
  const double tolerance = kVolumeTolerance * scale;
  double before = 0.0;
  for (std::uint32_t k : outside_) before += bad_volume_under(created_[k], old_positions, positions, min_dihedral_deg, false);
  if (after <= before + tolerance) return;
  before = 0.0;
  for (std::uint32_t k : outside_) before += bad_volume_under(created_[k], old_positions, positions, min_dihedral_deg, true);
  if (after <= before + tolerance) return;
  report.add(Invariant::kI7Quality, {}, {}, [&] {
    // Name the largest created tets below theta.
    std::vector<std::pair<double, std::uint32_t>> bad;
    for (std::uint32_t k : outside_) {
      const Created& c = created_[k];
      if (c.dihedral < min_dihedral_deg - kAngleTolerance)
        bad.push_back({tet_volume(positions[c.q[0]], positions[c.q[1]], positions[c.q[2]], positions[c.q[3]]), k});
    }
    std::sort(bad.begin(), bad.end(), std::greater<>());
    std::string named;
    for (std::size_t i = 0; i < bad.size() && i < 5; ++i) {
      const std::uint32_t k = bad[i].second;
      const Created& c = created_[k];
      std::string hosts_text;
      for (std::uint32_t h = host_begin_[k]; h < host_begin_[k + 1]; ++h) {
        Removed& r = removed_[hosts_[h]];
        measure(r, old_positions);
        hosts_text += (hosts_text.empty() ? "" : ", ") + str(r.id) + " (" + num(r.dihedral) + " deg)";
      }
      named += (named.empty() ? "" : "; ") + str(c.id) + " (" + num(c.dihedral) + " deg, volume " + num(bad[i].first) +
               ", its hosts: " + (hosts_text.empty() ? std::string("none holds its centroid") : hosts_text) + ")";
    }
    return "the volume of tets below " + num(min_dihedral_deg) + " deg outside the tool grew from " + num(before) +
           " to " + num(after) + " over the operation; its created tets below theta, the largest first: " + named;
  });
}

}  // namespace tetcut::invariants::detail
