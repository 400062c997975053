#include "tetcut/stats/intervals.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "tetcut/percentile.hpp"

namespace tetcut::stats {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
}

Interval wilson_interval(std::uint64_t k, std::uint64_t n, double z) {
  if (n == 0) return {kNaN, kNaN};
  // Wilson (1927): the p whose score test |p_hat - p| / sqrt(p (1 - p) / n) <= z, solved:
  //   centre = (p_hat + z^2 / 2n) / (1 + z^2 / n)
  //   half   = z / (1 + z^2 / n) * sqrt(p_hat (1 - p_hat) / n + z^2 / 4n^2)
  // (scipy.stats.binomtest(k, n).proportion_ci(method="wilson") is the same formula; the ctest
  // stats.report_renders_in_chromium compares every rate cell with it.)
  const double nn = static_cast<double>(n);
  const double p = static_cast<double>(k) / nn;
  const double z2 = z * z;
  const double denominator = 1.0 + z2 / nn;
  const double centre = (p + z2 / (2.0 * nn)) / denominator;
  const double half = z / denominator * std::sqrt(p * (1.0 - p) / nn + z2 / (4.0 * nn * nn));
  // At k == 0 or k == n the formula's bound is 0 or 1 up to rounding: say so exactly.
  return {k == 0 ? 0.0 : std::max(0.0, centre - half), k == n ? 1.0 : std::min(1.0, centre + half)};
}

Interval bootstrap_ratio_interval(std::span<const std::uint64_t> num, std::span<const std::uint64_t> den,
                                  const BootstrapOptions& options) {
  assert(num.size() == den.size());
  const std::size_t n = num.size();
  if (n == 0) return {kNaN, kNaN};
  std::mt19937_64 rng(options.seed);
  std::vector<double> ratios;
  ratios.reserve(static_cast<std::size_t>(options.resamples));
  for (int b = 0; b < options.resamples; ++b) {
    std::uint64_t sum_num = 0, sum_den = 0;
    for (std::size_t i = 0; i < n; ++i) {
      // An index in [0, n) from the top 32 bits (multiply-shift): portable, unlike
      // std::uniform_int_distribution, and its bias (n / 2^32) is far below the resampling noise.
      const std::uint64_t j = ((rng() >> 32) * static_cast<std::uint64_t>(n)) >> 32;
      sum_num += num[j];
      sum_den += den[j];
    }
    if (sum_den != 0) ratios.push_back(static_cast<double>(sum_num) / static_cast<double>(sum_den));
  }
  if (ratios.empty()) return {kNaN, kNaN};
  return {percentile(ratios, 0.025), percentile(ratios, 0.975)};
}

}  // namespace tetcut::stats
