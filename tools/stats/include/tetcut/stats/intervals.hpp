// 95 % intervals for the cells of Tables 1 and 2 over a mesh's seeded sweeps.
//
// Rates (% removable, % vertex, % unresolved, ...) pool the events of every sweep and take the
// Wilson score interval of the pooled count: unlike the normal (Wald) interval it stays inside
// [0, 1] and keeps close to its nominal cover with few events or a rate near 0 or 1, which is
// the edge rows' case (1-25 events per mesh and run, 0 to 100 % unresolved); at k = 0 it is
// [0, a few %], not the Wald interval's [0, 0].
//
// Mean set sizes (tets removed per set) are ratios whose denominators (sets resolved) are
// small and differ between sweeps, and an edge row's may be 0 in one sweep: there is no
// per-sweep mean to put a t interval on, and 10 means of 0-3 sets each are far from normal. So
// the sweeps are resampled whole (a cluster bootstrap: the sets of one sweep share its mesh
// and tool path) and the pooled ratio recomputed per resample; the interval is the 2.5th and
// 97.5th percentile of those ratios. Seeded (std::mt19937_64, whose output the standard fixes),
// indices drawn by multiply-shift rather than a library distribution (whose algorithm is not
// fixed): the same sweeps give the same bits on every compiler and platform.
#pragma once

#include <cstdint>
#include <span>

namespace tetcut::stats {

struct Interval {
  double lo = 0, hi = 0;  // NaN when there is nothing to estimate from
};

// The normal quantile for a two-sided 95 % interval.
inline constexpr double kZ95 = 1.959963984540054;

// Wilson score interval of a proportion: k successes in n trials, as fractions (x 100 for %).
// NaN for n == 0.
Interval wilson_interval(std::uint64_t k, std::uint64_t n, double z = kZ95);

struct BootstrapOptions {
  int resamples = 2000;
  std::uint64_t seed = 20020901;  // any fixed value; documented in docs/paper.md
};

// Percentile-bootstrap 95 % interval of sum(num) / sum(den) over clusters (here the sweeps),
// resampling clusters with replacement. Resamples whose denominators sum to 0 have no ratio and
// are left out; NaN when every one is (no cluster has a denominator). num and den: one entry
// per cluster, the same length.
Interval bootstrap_ratio_interval(std::span<const std::uint64_t> num, std::span<const std::uint64_t> den,
                                  const BootstrapOptions& options = {});

}  // namespace tetcut::stats
