// Test helper: runs the independent checker and turns its report into a test failure that
// names every violated invariant.
#pragma once

#include <gtest/gtest.h>

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

}  // namespace tetcut::testing
