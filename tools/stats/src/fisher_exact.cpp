#include "tetcut/stats/fisher_exact.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

namespace tetcut::stats {

namespace {

double log_choose(double n, double k) { return std::lgamma(n + 1) - std::lgamma(k + 1) - std::lgamma(n - k + 1); }

}  // namespace

double fisher_exact_p(std::uint64_t k1, std::uint64_t n1, std::uint64_t k2, std::uint64_t n2) {
  if (n1 == 0 || n2 == 0) return std::numeric_limits<double>::quiet_NaN();
  assert(k1 <= n1 && k2 <= n2);
  // Margins: the first row's n1 trials, the first column's K = k1 + k2 events, N in all. The
  // first cell x ranges over [max(0, K - n2), min(K, n1)], hypergeometric:
  //   P(x) = C(n1, x) C(n2, K - x) / C(N, K).
  const double N = static_cast<double>(n1 + n2), K = static_cast<double>(k1 + k2);
  const double a = static_cast<double>(n1), b = static_cast<double>(n2);
  const double log_total = log_choose(N, K);
  auto log_p = [&](double x) { return log_choose(a, x) + log_choose(b, K - x) - log_total; };
  const std::uint64_t lo = k1 + k2 > n2 ? k1 + k2 - n2 : 0;
  const std::uint64_t hi = std::min<std::uint64_t>(k1 + k2, n1);
  // scipy's rule: tables whose probability is at most the observed one's times (1 + 1e-7).
  const double bound = log_p(static_cast<double>(k1)) + std::log1p(1e-7);
  double p = 0;
  for (std::uint64_t x = lo; x <= hi; ++x) {
    const double l = log_p(static_cast<double>(x));
    if (l <= bound) p += std::exp(l);
  }
  return std::min(p, 1.0);
}

double fisher_vs_paper(const CellEstimate& ours, const PaperCount& paper) {
  if (ours.of == 0) return std::numeric_limits<double>::quiet_NaN();
  double p = 0;
  for (int k = paper.k_lo; k <= paper.k_hi; ++k)
    for (int n = paper.n_lo; n <= paper.n_hi; ++n)
      p = std::max(p, fisher_exact_p(ours.count, ours.of, static_cast<std::uint64_t>(k), static_cast<std::uint64_t>(n)));
  return p;
}

}  // namespace tetcut::stats
