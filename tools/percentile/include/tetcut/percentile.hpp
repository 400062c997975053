// The one percentile of the project: per-cut latencies in `tetcut cut`/`run` reports, `tetcut
// stats`, and the benchmarks the budget gate reads all use it, so that a "p99" means one thing.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace tetcut {

// Nearest-rank percentile of `values` for q in [0, 1]: the smallest sample with at least a
// fraction q of the samples at or below it (q = 0 gives the minimum, q = 1 the maximum). A
// percentile is always one of the samples, never an interpolation between two, so "p99 of 252
// cuts" is a cut that happened. With no samples it is NaN: there is no such cut, and a NaN
// fails every comparison with a budget (nlohmann-json writes it as null).
inline double percentile(std::vector<double> values, double q) {
  if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(values.begin(), values.end());
  const auto rank = static_cast<std::size_t>(std::ceil(q * static_cast<double>(values.size())));
  return values[std::clamp<std::size_t>(rank, 1, values.size()) - 1];
}

}  // namespace tetcut
