#include "core/host_location.hpp"

namespace tetcut::detail {
namespace {

double signed_volume6(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) { return dot(b - a, cross(c - a, d - a)); }

}  // namespace

void DeepestTet::offer(TetId t, const TetMesh::TetVerts& corners, const std::array<Vec3, 4>& x) {
  const double whole = signed_volume6(x[0], x[1], x[2], x[3]);
  if (!(whole > 0.0)) return;
  std::array<double, 4> w{};
  for (std::size_t i = 0; i < 4; ++i) {
    std::array<Vec3, 4> y = x;
    y[i] = p_;
    w[i] = signed_volume6(y[0], y[1], y[2], y[3]) / whole;
  }
  const double lowest = std::min(std::min(w[0], w[1]), std::min(w[2], w[3]));
  if (!(lowest > depth_)) return;
  tet_ = t;
  corners_ = corners;
  weights_ = w;
  depth_ = lowest;
}

DeepestTet deepest_at_start(TetMesh& mesh, std::span<const TetId> candidates, const Vec3& p) {
  DeepestTet deepest(p);
  for (TetId t : candidates) {
    const TetMesh::TetVerts c = mesh.tet_at_start(t);
    deepest.offer(t, c, {mesh.position_at_start(c[0]), mesh.position_at_start(c[1]), mesh.position_at_start(c[2]), mesh.position_at_start(c[3])});
  }
  return deepest;
}

}  // namespace tetcut::detail
