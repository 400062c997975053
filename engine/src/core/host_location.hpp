// Where a point lies among the tets that were there when the open transaction began: the one
// search for a host, shared by everything that asks which old tet holds a point of the new mesh
// (the improvement pass's floor, I7: a made tet's host holds its centroid; the journal's origin of
// a moved vertex, in the ChangeLog).
//
// The host is the candidate in which the point lies deepest: the largest smallest barycentric
// coordinate, so a point inside one tet (>= 0) beats every tet it is outside of, and a point on a
// shared face or just outside by rounding still gets the nearest one. Flat or inverted
// candidates never win; ties go to the candidate offered first, so the answer follows the order
// the caller offers them in (sorted ids, for ancestors_at_start()): deterministic.
#pragma once

#include <array>
#include <limits>
#include <span>

#include "tetcut/ids.hpp"
#include "tetcut/mesh.hpp"
#include "tetcut/vec3.hpp"

namespace tetcut::detail {

class DeepestTet {
 public:
  explicit DeepestTet(const Vec3& p) : p_(p) {}
  // Offers tet t, its corners `corners` at positions x; it becomes the host when p lies deeper
  // in it than in every tet offered before.
  void offer(TetId t, const TetMesh::TetVerts& corners, const std::array<Vec3, 4>& x);

  // Whether some tet offered was positively oriented (else tet() is kNoTet).
  [[nodiscard]] bool found() const { return tet_.valid(); }
  [[nodiscard]] TetId tet() const { return tet_; }
  [[nodiscard]] const TetMesh::TetVerts& corners() const { return corners_; }
  // p's barycentric coordinates in the host, weight i for corner i (they sum to 1), and their
  // smallest: >= 0 when p is inside it.
  [[nodiscard]] const std::array<double, 4>& weights() const { return weights_; }
  [[nodiscard]] double depth() const { return depth_; }

 private:
  Vec3 p_;
  TetId tet_ = kNoTet;
  TetMesh::TetVerts corners_{};
  std::array<double, 4> weights_{};
  double depth_ = -std::numeric_limits<double>::infinity();
};

// The host of p among `candidates`, tets live at begin_transaction(), at their shape then
// (TetMesh::tet_at_start, their corners at TetMesh::position_at_start: those vertices were there
// before the transaction, and a move since does not change where the tet was).
DeepestTet deepest_at_start(TetMesh& mesh, std::span<const TetId> candidates, const Vec3& p);

}  // namespace tetcut::detail
