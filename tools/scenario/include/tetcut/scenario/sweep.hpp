// A cautery sweep's cut centres: one cut every STEP from FROM towards TO. The one definition
// that `tetcut cut`, a scenario's `sweep` line, `tetcut simulate --sweep` and Python's
// Cutter.sweep all use, so that the same three values cut the same mesh everywhere.
//
// The centres are FROM + k STEP (TO - FROM) / |TO - FROM| for k = 0 .. n, with
//   n = floor(|TO - FROM| / STEP + kSweepEndTolerance):
// TO is the last centre when it is a whole number of steps away, to within a billionth of a
// step. Without the tolerance a length the decimal inputs make whole but their doubles do not
// (1.4 / 0.05 is 27.999999999999996) would drop the end. A billionth of a step is far above the
// quotient's rounding (a few 1e-16 of it, times at most kMaxSweepCuts) and far below anything a
// person means by a step. When TO is not a whole number of steps away, the sweep stops short of
// it (it is not added as an extra, shorter step). FROM == TO: one cut, at FROM.
//
// A swept sweep (sweep_cuts(..., swept = true): a scenario's `sweep ... swept`, `tetcut cut
// --swept`, `tetcut simulate --swept`, Python's Cutter.sweep(..., swept=True)) takes the same
// centres and joins them: one capsule cut (Cutter::cut_segment) from each centre to the next,
// so the tissue between two samples goes whatever STEP is; a sweep of one centre is one ball.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "tetcut/vec3.hpp"

namespace tetcut::scenario {

inline constexpr double kSweepEndTolerance = 1e-9;  // in steps
inline constexpr double kMaxSweepCuts = 100000;     // a longer sweep is refused as a typo

// n + 1 above: how many cuts the sweep makes. `step` > 0 and finite.
[[nodiscard]] std::uint64_t sweep_cut_count(const Vec3& from, const Vec3& to, double step);

// The centres, in order.
[[nodiscard]] std::vector<Vec3> sweep_centres(const Vec3& from, const Vec3& to, double step);

// One cut's tool: the ball at `centre` (Cutter::cut), or, when `end` is set, the capsule the
// tool sweeps from `centre` to `end` (Cutter::cut_segment).
struct CutTool {
  Vec3 centre;
  std::optional<Vec3> end;
};

// The sweep's cuts, in order: a ball at each of sweep_centres(), or, swept, a capsule from each
// centre to the next (one fewer cut; a single centre stays a ball).
[[nodiscard]] std::vector<CutTool> sweep_cuts(const Vec3& from, const Vec3& to, double step, bool swept);

}  // namespace tetcut::scenario
