// What the improvement pass's tests start from: a refinement of a bundled mesh inside an open
// transaction, whose children (some of them slivers) are the tets a pass has to lift.
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/tool.hpp"
#include "refine/refine.hpp"
#include "test_meshes.hpp"
#include "tetcut/io.hpp"
#include "tetcut/mesh.hpp"

namespace tetcut::testing {

inline TetMesh corpus_mesh(const std::string& name) {
  ReadResult read = read_mesh(std::string(TETCUT_CORPUS_DIR) + "/meshes/" + name);
  if (!read.mesh) {
    ADD_FAILURE() << "cannot read " << name;
    return {};
  }
  return build_or_fail(*read.mesh);
}

// The tets the open transaction made since `point` that are still live.
inline std::vector<TetId> made_since(const TetMesh& mesh, const TetMesh::Savepoint& point) {
  std::vector<TetId> out;
  for (const TetMesh::TetBirth& b : mesh.tets_made_since(point))
    if (mesh.is_live(b.tet)) out.push_back(b.tet);
  return out;
}

// A refinement around a small ball of the coarse liver inside an open transaction: children of
// vertex-order templates, some of them slivers, to improve.
struct Refined {
  TetMesh mesh;
  TetMesh::Savepoint start;
};
inline Refined refined_liver(const Vec3& centre, double radius) {
  Refined r{corpus_mesh("liver-coarse.msh"), {}};
  r.mesh.begin_transaction();
  r.start = r.mesh.savepoint();
  std::vector<TetId> hit, region;
  for (std::uint32_t t = 0; t < r.mesh.tet_capacity(); ++t) {
    const auto v = r.mesh.tet(TetId{t});
    if (intersects(Tool::ball(centre, radius), r.mesh.position(v[0]), r.mesh.position(v[1]), r.mesh.position(v[2]),
                   r.mesh.position(v[3])))
      hit.push_back(TetId{t});
  }
  Refiner refiner;
  refiner.refine(r.mesh, hit, {.d_ref = 3.0 * radius, .focus = Tool::ball(centre, radius)}, region);
  return r;
}

}  // namespace tetcut::testing
