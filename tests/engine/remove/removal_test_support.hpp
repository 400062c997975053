// Helpers shared by the removal tests (removal_*_test.cpp).
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <span>
#include <string>
#include <vector>

#include "checked.hpp"
#include "tetcut/boundary_tet_picker.hpp"
#include "remove/removal.hpp"
#include "test_meshes.hpp"
#include "tetcut/invariants/check.hpp"
#include "tetcut/predicates.hpp"

namespace tetcut::testing {

inline TetMesh box(std::uint32_t nx, std::uint32_t ny, std::uint32_t nz) {
  return build_or_fail(make_box_mesh(nx, ny, nz));
}

// What the independent checker says about the mesh once `set` is removed from a copy: true iff
// it is still valid (the engine's remove_tets keeps a non-manifold result consistent enough for
// the checker to name the broken vertex or edge).
inline bool still_valid_without(const TetMesh& mesh, std::span<const TetId> set) {
  TetMesh copy = mesh;
  copy.remove_tets(set);
  return invariants::check_mesh(copy.raw_view()).ok();
}

inline std::string describe(const invariants::CheckReport& report) { return invariants::to_string(report); }

// A cone over a flat n x n grid of squares (two triangles each) in the plane z = 0, apex above
// its centre: every tet is (apex, grid triangle). The apex is a boundary vertex whose shell is
// the whole mesh; from a tet in the middle the border of that shell (the side faces) is about
// n / 2 squares, i.e. about n tets, away.
inline RawMesh cone_over_grid(std::uint32_t n) {
  RawMesh raw;
  for (std::uint32_t j = 0; j <= n; ++j)
    for (std::uint32_t i = 0; i <= n; ++i) raw.positions.push_back({double(i), double(j), 0.0});
  const std::uint32_t apex = static_cast<std::uint32_t>(raw.positions.size());
  raw.positions.push_back({n / 2.0, n / 2.0, 2.0});
  auto id = [n](std::uint32_t i, std::uint32_t j) { return j * (n + 1) + i; };
  auto add = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    std::array<std::uint32_t, 4> t = {apex, a, b, c};
    if (orientation(raw.positions[t[0]], raw.positions[t[1]], raw.positions[t[2]], raw.positions[t[3]]) < 0)
      std::swap(t[2], t[3]);
    raw.tets.push_back(t);
  };
  for (std::uint32_t j = 0; j < n; ++j)
    for (std::uint32_t i = 0; i < n; ++i) {
      add(id(i, j), id(i + 1, j), id(i + 1, j + 1));
      add(id(i, j), id(i + 1, j + 1), id(i, j + 1));
    }
  return raw;
}

// The live tet containing point p (centroid test by exact orientation), or kNoTet.
inline TetId tet_containing(const TetMesh& mesh, const Vec3& p) {
  for (std::uint32_t i = 0; i < mesh.tet_capacity(); ++i) {
    const TetId t{i};
    if (!mesh.is_live(t)) continue;
    const auto v = mesh.tet(t);
    bool inside = true;
    for (int f = 0; f < 4 && inside; ++f) {
      std::array<Vec3, 4> q = {mesh.position(v[0]), mesh.position(v[1]), mesh.position(v[2]), mesh.position(v[3])};
      q[f] = p;
      inside = orientation(q[0], q[1], q[2], q[3]) > 0;
    }
    if (inside) return t;
  }
  return kNoTet;
}

inline Vec3 centroid(const TetMesh& mesh, TetId t) {
  Vec3 c{};
  for (VertId v : mesh.tet(t)) c = c + 0.25 * mesh.position(v);
  return c;
}

// One request through the Remover, then the local checker on exactly what it says it changed.
inline ::testing::AssertionResult remove_checked(Remover& remover, TetMesh& mesh, TetId t,
                                                 invariants::LocalChecker& local, RemovalResult* out = nullptr) {
  const RemovalResult result = remover.remove(mesh, t);
  if (out) *out = result;
  invariants::CheckOptions options;
  options.operation = "remove tet " + std::to_string(t.value);
  // A raw request: the improvement pass that meets I7's floor is the Cutter's, after it.
  options.quality_rule = invariants::QualityRule::kReportOnly;
  const invariants::CheckReport report =
      local.after_operation(mesh.raw_view(), remover.last_removed(), remover.last_created(), options);
  if (!report.ok()) return ::testing::AssertionFailure() << describe(report);
  return ::testing::AssertionSuccess();
}

}  // namespace tetcut::testing
