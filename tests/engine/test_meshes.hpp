// Small hand-built meshes shared by the engine tests.
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "tetcut/bounding_box.hpp"
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

// `cuts` tool centres along the longest axis of the box, through its middle (the paper's lancet).
inline std::vector<Vec3> lancet_sweep(const BoundingBox& b, int cuts) {
  std::vector<Vec3> out;
  const Vec3 size = b.hi - b.lo, mid = 0.5 * (b.lo + b.hi);
  const int axis = size.x >= size.y && size.x >= size.z ? 0 : size.y >= size.z ? 1 : 2;
  for (int i = 0; i < cuts; ++i) {
    Vec3 p = mid;
    const double s = cuts == 1 ? 0.5 : 0.1 + 0.8 * i / (cuts - 1);
    if (axis == 0) p.x = b.lo.x + s * size.x;
    if (axis == 1) p.y = b.lo.y + s * size.y;
    if (axis == 2) p.z = b.lo.z + s * size.z;
    out.push_back(p);
  }
  return out;
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
