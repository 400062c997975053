#include "tissue_rule.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace tetcut::invariants::detail {

namespace {

constexpr double kMargin = 1e-9;  // relative: decisions this close to the radius or D_ref are not judged

double dist(const Vec3& a, const Vec3& b) { return norm(b - a); }

// Distance from p to the segment ab.
double distance_to_segment(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double length2 = dot(ab, ab);
  if (!(length2 > 0.0)) return dist(p, a);
  const double s = std::clamp(dot(p - a, ab) / length2, 0.0, 1.0);
  return dist(p, a + s * ab);
}

// Distance from p to the triangle abc: to its plane when p projects inside it, else to its
// nearest edge.
double distance_to_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 n = cross(b - a, c - a);
  const double n2 = dot(n, n);
  const double edges = std::min({distance_to_segment(p, a, b), distance_to_segment(p, b, c), distance_to_segment(p, c, a)});
  if (!(n2 > 0.0)) return edges;
  const Vec3 q = p - (dot(p - a, n) / n2) * n;  // p projected on the plane
  // q's barycentric coordinates as signed areas against the normal.
  const double u = dot(cross(c - b, q - b), n), v = dot(cross(a - c, q - c), n), w = dot(cross(b - a, q - a), n);
  if (u >= 0.0 && v >= 0.0 && w >= 0.0) return dist(p, q);
  return edges;
}

double volume6(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) { return dot(b - a, cross(c - a, d - a)); }

struct Corners {
  Vec3 p[4];
};

bool in_range(const RawTet& q, std::span<const Vec3> positions) {
  return q[0] < positions.size() && q[1] < positions.size() && q[2] < positions.size() && q[3] < positions.size();
}

Corners corners(const RawTet& q, std::span<const Vec3> positions) {
  return {{positions[q[0]], positions[q[1]], positions[q[2]], positions[q[3]]}};
}

double longest_edge(const Corners& c) {
  double longest = 0.0;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) longest = std::max(longest, dist(c.p[i], c.p[j]));
  return longest;
}

}  // namespace

double distance_to_tet(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  if (tet_contains(p, a, b, c, d)) return 0.0;
  return std::min({distance_to_triangle(p, b, c, d), distance_to_triangle(p, a, c, d), distance_to_triangle(p, a, b, d),
                   distance_to_triangle(p, a, b, c)});
}

bool tet_contains(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const double whole = volume6(a, b, c, d);
  const double eps = -1e-12 * std::abs(whole);
  const double sign = whole < 0.0 ? -1.0 : 1.0;
  return sign * volume6(p, b, c, d) >= eps && sign * volume6(a, p, c, d) >= eps && sign * volume6(a, b, p, d) >= eps &&
         sign * volume6(a, b, c, p) >= eps;
}

std::int64_t TetGrid::cell_of(double x) const {
  const double c = std::floor(x / cell_);
  // Far-off coordinates (never a mesh's) clamp: still a valid, if crowded, cell.
  return static_cast<std::int64_t>(std::clamp(c, -1e6, 1e6));
}

std::uint64_t TetGrid::key(std::int64_t x, std::int64_t y, std::int64_t z) {
  constexpr std::int64_t kOffset = 1 << 20;  // cells within +-1e6 fit 21 bits each
  return (static_cast<std::uint64_t>(x + kOffset) << 42) | (static_cast<std::uint64_t>(y + kOffset) << 21) |
         static_cast<std::uint64_t>(z + kOffset);
}

std::int64_t TetGrid::cells_in(const Box& box) {
  return (box[3] - box[0] + 1) * (box[4] - box[1] + 1) * (box[5] - box[2] + 1);
}

void TetGrid::build(std::span<const RawTet> tets, std::span<const Vec3> positions) {
  double edges = 0.0;
  std::uint64_t count = 0;
  for (const RawTet& q : tets) {
    if (q[0] == kDeadTetMarker || !in_range(q, positions)) continue;
    const Corners c = corners(q, positions);
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) {
        edges += dist(c.p[i], c.p[j]);
        ++count;
      }
  }
  cell_ = count > 0 && edges > 0.0 ? edges / static_cast<double>(count) : 1.0;
  cells_.clear();
  oversized_.clear();
  box_.assign(tets.size(), Box{});
  in_.assign(tets.size(), 0);
  seen_.assign(tets.size(), 0);
  stamp_ = 0;
  built_ = true;
  for (std::uint32_t t = 0; t < tets.size(); ++t)
    if (tets[t][0] != kDeadTetMarker && in_range(tets[t], positions)) insert(t, tets[t], positions);
}

void TetGrid::insert(std::uint32_t t, const RawTet& q, std::span<const Vec3> positions) {
  if (t >= box_.size()) {
    box_.resize(t + 1 + t / 4);
    in_.resize(box_.size(), 0);
    seen_.resize(box_.size(), 0);
  }
  const Corners c = corners(q, positions);
  Box box{};
  for (int axis = 0; axis < 3; ++axis) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const Vec3& p : c.p) {
      const double x = axis == 0 ? p.x : axis == 1 ? p.y : p.z;
      lo = std::min(lo, x);
      hi = std::max(hi, x);
    }
    box[axis] = cell_of(lo);
    box[axis + 3] = cell_of(hi);
  }
  box_[t] = box;
  if (cells_in(box) > kMaxCellsPerTet) {
    oversized_.push_back(t);
    in_[t] = 2;
    return;
  }
  for (std::int64_t x = box[0]; x <= box[3]; ++x)
    for (std::int64_t y = box[1]; y <= box[4]; ++y)
      for (std::int64_t z = box[2]; z <= box[5]; ++z) cells_[key(x, y, z)].push_back(t);
  in_[t] = 1;
}

void TetGrid::erase(std::uint32_t t) {
  if (t >= in_.size() || in_[t] == 0) return;
  auto drop = [t](std::vector<std::uint32_t>& list) {
    const auto it = std::find(list.begin(), list.end(), t);
    if (it == list.end()) return;
    *it = list.back();
    list.pop_back();
  };
  if (in_[t] == 2) {
    drop(oversized_);
  } else {
    const Box& box = box_[t];
    for (std::int64_t x = box[0]; x <= box[3]; ++x)
      for (std::int64_t y = box[1]; y <= box[4]; ++y)
        for (std::int64_t z = box[2]; z <= box[5]; ++z) {
          const auto cell = cells_.find(key(x, y, z));
          if (cell != cells_.end()) drop(cell->second);
        }
  }
  in_[t] = 0;
}

void TetGrid::candidates(const Vec3& centre, double radius, std::vector<std::uint32_t>& out) {
  out.clear();
  if (++stamp_ == 0) {
    std::fill(seen_.begin(), seen_.end(), 0u);
    stamp_ = 1;
  }
  auto add = [&](std::uint32_t t) {
    if (seen_[t] == stamp_) return;
    seen_[t] = stamp_;
    out.push_back(t);
  };
  for (std::uint32_t t : oversized_) add(t);
  const Box box{cell_of(centre.x - radius), cell_of(centre.y - radius), cell_of(centre.z - radius),
                cell_of(centre.x + radius), cell_of(centre.y + radius), cell_of(centre.z + radius)};
  if (cells_in(box) > static_cast<std::int64_t>(cells_.size())) {
    // A tool larger than the mesh: every occupied cell.
    for (const auto& [k, list] : cells_)
      for (std::uint32_t t : list) add(t);
  } else {
    for (std::int64_t x = box[0]; x <= box[3]; ++x)
      for (std::int64_t y = box[1]; y <= box[4]; ++y)
        for (std::int64_t z = box[2]; z <= box[5]; ++z)
          if (const auto cell = cells_.find(key(x, y, z)); cell != cells_.end())
            for (std::uint32_t t : cell->second) add(t);
  }
  std::sort(out.begin(), out.end());
}

double distance_to_axis(const ToolRule& tool, const Vec3& p) {
  return tool.end ? distance_to_segment(p, tool.centre, *tool.end) : dist(p, tool.centre);
}

double distance_from_axis_to_tet(const ToolRule& tool, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  if (!tool.end || *tool.end == tool.centre) return distance_to_tet(tool.centre, a, b, c, d);
  const Vec3 from = tool.centre, along = *tool.end - tool.centre;
  auto f = [&](double s) { return distance_to_tet(from + s * along, a, b, c, d); };
  // 0.618^70 < 1e-14 of the segment: far below the checker's margins.
  constexpr double kGolden = 0.6180339887498949;
  double lo = 0.0, hi = 1.0;
  double x1 = hi - kGolden * (hi - lo), x2 = lo + kGolden * (hi - lo);
  double f1 = f(x1), f2 = f(x2);
  for (int i = 0; i < 70 && f1 > 0.0 && f2 > 0.0; ++i) {
    if (f1 <= f2) {
      hi = x2, x2 = x1, f2 = f1;
      x1 = hi - kGolden * (hi - lo), f1 = f(x1);
    } else {
      lo = x1, x1 = x2, f1 = f2;
      x2 = lo + kGolden * (hi - lo), f2 = f(x2);
    }
  }
  return std::min({f1, f2, f(0.0), f(1.0)});
}

void check_tissue_rule(const ToolRule& rule, std::span<const std::uint32_t> candidates, std::span<const RawTet> tets,
                       std::span<const Vec3> positions, std::span<const std::uint8_t> uncuttable,
                       ReportBuilder& report) {
  const double r = rule.radius, d_ref = rule.d_ref;
  auto cuttable = [&](std::uint32_t t) { return t >= uncuttable.size() || uncuttable[t] == 0; };
  // Live with its references in range (I1 reports those that are not).
  auto live = [&](std::uint32_t t) { return t < tets.size() && tets[t][0] != kDeadTetMarker && in_range(tets[t], positions); };

  // The reported tets, sorted, for lookup; each must be tissue the rule takes.
  std::vector<std::uint32_t> left(rule.left.begin(), rule.left.end());
  std::sort(left.begin(), left.end());
  for (std::size_t i = 0; i < left.size(); ++i) {
    const std::uint32_t t = left[i];
    if (i > 0 && left[i - 1] == t) {
      report.add(Invariant::kI10Tissue, {t}, {}, [&] { return "tet " + str(t) + " is reported left in the tool twice"; });
      continue;
    }
    if (!live(t)) {
      report.add(Invariant::kI10Tissue, {t}, {}, [&] { return "tet " + str(t) + " is reported left in the tool but is not live"; });
      continue;
    }
    const Corners c = corners(tets[t], positions);
    const Vec3 centroid = 0.25 * (c.p[0] + c.p[1] + c.p[2] + c.p[3]);
    const double from_centre = distance_to_axis(rule, centroid), longest = longest_edge(c);
    if (!cuttable(t) || from_centre > r * (1 + kMargin) || longest > d_ref * (1 + kMargin))
      report.add(Invariant::kI10Tissue, {t}, {}, [&] {
        return "tet " + str(t) + " is reported left in the tool but is not tissue the cut takes: " +
               (cuttable(t) ? "its centroid is " + num(from_centre) + " from the tool's axis (radius " + num(r) +
                                  "), its longest edge " + num(longest) + " (D_ref " + num(d_ref) + ")"
                            : std::string("it is uncuttable"));
      });
  }

  for (std::uint32_t t : candidates) {
    if (!live(t) || !cuttable(t)) continue;
    const Corners c = corners(tets[t], positions);
    const double longest = longest_edge(c);
    if (longest > d_ref * (1 + kMargin)) {
      // Only a tet that meets the tool: the distance last, as it is the dearest.
      if (distance_from_axis_to_tet(rule, c.p[0], c.p[1], c.p[2], c.p[3]) < r * (1 - kMargin))
        report.add(Invariant::kI10Tissue, {t}, {}, [&] {
          return "tet " + str(t) + " meets the tool (centre " + num(rule.centre.x) + "," + num(rule.centre.y) + "," +
                 num(rule.centre.z) +
                 (rule.end ? " to " + num(rule.end->x) + "," + num(rule.end->y) + "," + num(rule.end->z) : std::string()) +
                 ", radius " + num(r) + ") with an edge of " + num(longest) +
                 ", longer than D_ref " + num(d_ref) + ": the tool's neighbourhood is not refined";
        });
      continue;
    }
    if (longest > d_ref * (1 - kMargin)) continue;
    const Vec3 centroid = 0.25 * (c.p[0] + c.p[1] + c.p[2] + c.p[3]);
    const double from_centre = distance_to_axis(rule, centroid);
    if (from_centre <= r * (1 - kMargin) && !std::binary_search(left.begin(), left.end(), t))
      report.add(Invariant::kI10Tissue, {t}, {}, [&] {
        return "tet " + str(t) + " is tissue the cut takes (centroid " + num(from_centre) + " from the tool's axis, radius " +
               num(r) + "; longest edge " + num(longest) + ", D_ref " + num(d_ref) +
               ") and is still there, and the cut does not report it left";
      });
  }
}

}  // namespace tetcut::invariants::detail
