// Small hand-built meshes shared by the engine tests.
#pragma once

#include <gtest/gtest.h>

#include <string>

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

// A bundled mesh's file name as a test name: "liver-coarse.msh" -> "liver_coarse".
inline std::string test_name_of_mesh(std::string file) {
  file = file.substr(0, file.find('.'));
  for (char& c : file)
    if (c == '-') c = '_';
  return file;
}

// A live tet drawn from `rng` (a SplitMix64): ids are drawn until one is live.
template <class Rng>
TetId random_live_tet(const TetMesh& mesh, Rng& rng) {
  TetId t;
  do t = TetId{rng.below(mesh.tet_capacity())};
  while (!mesh.is_live(t));
  return t;
}

}  // namespace tetcut::testing
