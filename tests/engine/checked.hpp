// Test helper: runs the independent checker and turns its report into a test failure that
// names every violated invariant.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>

#include "tetcut/cut.hpp"
#include "tetcut/invariants/check.hpp"
#include "tetcut/mesh.hpp"

namespace tetcut::testing {

inline ::testing::AssertionResult mesh_is_valid(const TetMesh& mesh,
                                                invariants::CheckLevel level = invariants::CheckLevel::kFull,
                                                std::optional<double> expected_volume = std::nullopt) {
  invariants::CheckOptions options;
  options.level = level;
  options.expected_volume = expected_volume;
  options.volume_rel_tolerance = 1e-12;
  const invariants::CheckReport report = invariants::check_mesh(mesh.raw_view(), options);
  if (report.ok()) return ::testing::AssertionSuccess();
  auto failure = ::testing::AssertionFailure();
  for (const invariants::Violation& v : report.violations)
    failure << invariants::id_string(v.id) << " (" << invariants::description(v.id) << "): " << v.detail << "; ";
  return failure;
}

// What the local checker holds the cut `cutter` just made at `centre` to: the default rules and
// I10 with the cut's tool, D_ref and the tets it reports left, I8 with the vertices it moved (views:
// use them before the next cut).
inline invariants::CheckOptions cut_check(const Cutter& cutter, const Vec3& centre) {
  invariants::CheckOptions options;
  options.min_dihedral_deg = std::min(cutter.params().min_dihedral_deg, cutter.last_min_dihedral_held());
  options.quality_floor = cutter.params().quality_floor;
  options.tool = invariants::ToolRule{.centre = centre, .radius = cutter.params().tool_diameter / 2,
                                      .d_ref = cutter.params().d_ref(), .left = cutter.last_left_in_tool()};
  options.moved = cutter.last_moved();
  return options;
}

// After Cutter::undo(): its moves back held to the undone cut's reach, quality reported and not
// judged (the tets that come back were held to the floors when they were made).
inline invariants::CheckOptions undo_check(const Cutter& cutter) {
  invariants::CheckOptions options;
  options.quality_rule = invariants::QualityRule::kReportOnly;
  options.moved = cutter.last_moved();
  if (const auto r = cutter.last_undone_reach())
    options.reach = invariants::ToolRule{.centre = r->a, .radius = r->radius, .d_ref = r->d_ref, .left = {}, .end = r->b};
  return options;
}

}  // namespace tetcut::testing
