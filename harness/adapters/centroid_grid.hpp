// The tets whose centroid lies in a tool (a ball, or a capsule around a segment), found through a
// uniform grid of the centroids built once: how the blind-removal peers locate what to remove.
// Their tets never move and they never make new ones, so the grid never changes; tetcut locates
// through its own index, and the peers' timings should not be a scan of the mesh beside it.
// Header-only and free of tetcut, as the adapters that use it are.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace tetcut::adapters {

class CentroidGrid {
 public:
  using Point = std::array<double, 3>;

  // `points`: 3 per vertex; `tets`: 4 per tet. Cells of about the mean edge length.
  CentroidGrid(const double* points, const std::uint32_t* tets, std::size_t tet_count) {
    centroids_.resize(tet_count);
    double edge_sum = 0;
    for (std::size_t t = 0; t < tet_count; ++t) {
      Point c{0, 0, 0};
      for (int i = 0; i < 4; ++i) {
        for (int k = 0; k < 3; ++k) c[k] += points[3 * tets[4 * t + i] + k] / 4;
      }
      centroids_[t] = c;
      edge_sum += distance(points + 3 * tets[4 * t], points + 3 * tets[4 * t + 1]);
    }
    cell_ = tet_count > 0 && edge_sum > 0 ? edge_sum / tet_count : 1.0;
    low_ = high_ = tet_count > 0 ? centroids_[0] : Point{0, 0, 0};
    for (const Point& c : centroids_) {
      for (int k = 0; k < 3; ++k) {
        low_[k] = std::min(low_[k], c[k]);
        high_[k] = std::max(high_[k], c[k]);
      }
    }
    for (int k = 0; k < 3; ++k) size_[k] = 1 + static_cast<std::size_t>((high_[k] - low_[k]) / cell_);
    start_.assign(size_[0] * size_[1] * size_[2] + 1, 0);
    for (const Point& c : centroids_) ++start_[index(cell_of(c)) + 1];
    for (std::size_t i = 1; i < start_.size(); ++i) start_[i] += start_[i - 1];
    ids_.resize(tet_count);
    std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
    for (std::size_t t = 0; t < tet_count; ++t) ids_[fill[index(cell_of(centroids_[t]))]++] = static_cast<std::uint32_t>(t);
  }

  [[nodiscard]] const Point& centroid(std::uint32_t tet) const { return centroids_[tet]; }

  // Appends to `out` every tet (by its index at construction) whose centroid is within
  // diameter / 2 of the segment a-b (a ball when a == b), in grid order.
  void within(const double* a, const double* b, double diameter, std::vector<std::uint32_t>& out) const {
    const double r = diameter / 2;
    std::array<std::size_t, 3> from{}, to{};
    for (int k = 0; k < 3; ++k) {
      const double lo = std::min(a[k], b[k]) - r, hi = std::max(a[k], b[k]) + r;
      if (hi < low_[k] || lo > high_[k]) return;
      from[k] = clamp_cell(lo, k);
      to[k] = clamp_cell(hi, k);
    }
    for (std::size_t x = from[0]; x <= to[0]; ++x) {
      for (std::size_t y = from[1]; y <= to[1]; ++y) {
        for (std::size_t z = from[2]; z <= to[2]; ++z) {
          const std::size_t cell = index({x, y, z});
          for (std::uint32_t i = start_[cell]; i < start_[cell + 1]; ++i) {
            if (squared_distance_to_segment(centroids_[ids_[i]], a, b) <= r * r) out.push_back(ids_[i]);
          }
        }
      }
    }
  }

  static double squared_distance_to_segment(const Point& p, const double* a, const double* b) {
    double ab_ab = 0, ap_ab = 0;
    for (int k = 0; k < 3; ++k) {
      ab_ab += (b[k] - a[k]) * (b[k] - a[k]);
      ap_ab += (p[k] - a[k]) * (b[k] - a[k]);
    }
    const double t = ab_ab > 0 ? std::clamp(ap_ab / ab_ab, 0.0, 1.0) : 0.0;
    double d2 = 0;
    for (int k = 0; k < 3; ++k) {
      const double d = p[k] - (a[k] + t * (b[k] - a[k]));
      d2 += d * d;
    }
    return d2;
  }

 private:
  static double distance(const double* p, const double* q) {
    return std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]));
  }
  [[nodiscard]] std::size_t clamp_cell(double v, int k) const {
    const double cell = std::floor((v - low_[k]) / cell_);
    return static_cast<std::size_t>(std::clamp(cell, 0.0, static_cast<double>(size_[k] - 1)));
  }
  [[nodiscard]] std::array<std::size_t, 3> cell_of(const Point& c) const {
    return {clamp_cell(c[0], 0), clamp_cell(c[1], 1), clamp_cell(c[2], 2)};
  }
  [[nodiscard]] std::size_t index(const std::array<std::size_t, 3>& c) const {
    return (c[0] * size_[1] + c[1]) * size_[2] + c[2];
  }

  std::vector<Point> centroids_;
  double cell_ = 1.0;
  Point low_{}, high_{};
  std::array<std::size_t, 3> size_{1, 1, 1};
  std::vector<std::uint32_t> start_, ids_;
};

}  // namespace tetcut::adapters
