// Small hand-built meshes shared by the engine tests.
#pragma once

#include <gtest/gtest.h>

#include "tetcut/box_mesh.hpp"
#include "tetcut/mesh_builder.hpp"

namespace tetcut::testing {

// Builds and asserts success, listing the builder's problems otherwise.
inline TetMesh build_or_fail(const RawMesh& raw, const BuildOptions& options = {}) {
  BuildResult result = build_mesh(raw, options);
  for (const BuildProblem& p : result.problems) ADD_FAILURE() << to_string(p.kind) << ": " << p.message;
  if (!result.ok()) return TetMesh{};
  return std::move(*result.mesh);
}

// One positive tet: the corner of the unit cube.
inline RawMesh single_tet() {
  return {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {{0, 1, 2, 3}}};
}

}  // namespace tetcut::testing
