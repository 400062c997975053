#include "tetcut/scenario/sweep.hpp"

#include <cmath>

namespace tetcut::scenario {

std::uint64_t sweep_cut_count(const Vec3& from, const Vec3& to, double step) {
  return static_cast<std::uint64_t>(std::floor(norm(to - from) / step + kSweepEndTolerance)) + 1;
}

std::vector<Vec3> sweep_centres(const Vec3& from, const Vec3& to, double step) {
  const double length = norm(to - from);
  const std::uint64_t count = sweep_cut_count(from, to, step);
  std::vector<Vec3> centres;
  centres.reserve(count);
  // The same expression as every sweep before the tolerance existed, so that the centres of a
  // sweep that already reached its end (and the pinned hashes of its mesh) do not move.
  for (std::uint64_t k = 0; k < count; ++k)
    centres.push_back(length == 0 ? from : from + (static_cast<double>(k) * step / length) * (to - from));
  return centres;
}

std::vector<CutTool> sweep_cuts(const Vec3& from, const Vec3& to, double step, bool swept) {
  const std::vector<Vec3> centres = sweep_centres(from, to, step);
  std::vector<CutTool> cuts;
  if (!swept || centres.size() == 1) {
    cuts.reserve(centres.size());
    for (const Vec3& c : centres) cuts.push_back({c, std::nullopt});
    return cuts;
  }
  cuts.reserve(centres.size() - 1);
  for (std::size_t k = 0; k + 1 < centres.size(); ++k) cuts.push_back({centres[k], centres[k + 1]});
  return cuts;
}

}  // namespace tetcut::scenario
