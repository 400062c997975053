#include "remove/tissue_removal.hpp"

#include <cmath>

namespace tetcut::detail {

void TissueRemoval::begin(const Tool* tool, double reach_radius) {
  removed_ = {};
  has_tool_ = tool != nullptr;
  if (has_tool_) {
    tool_ = *tool;
    reach_ = Tool{tool->a, tool->b, reach_radius};
  }
}

bool TissueRemoval::within_reach(const TetMesh& mesh, std::span<const TetId> set) const {
  if (!has_tool_) return true;
  const double r2 = reach_.radius * reach_.radius;
  for (TetId t : set)
    for (VertId v : mesh.tet(t)) {
      if (squared_distance_to_axis(reach_, mesh.position(v)) > r2) return false;
    }
  return true;
}

void TissueRemoval::remove(TetMesh& mesh, std::span<const TetId> set) {
  for (TetId t : set) {
    const TetMesh::TetVerts v = mesh.tet(t);
    const Vec3 a = mesh.position(v[0]), b = mesh.position(v[1]), c = mesh.position(v[2]), d = mesh.position(v[3]);
    const double volume = std::abs(dot(b - a, cross(c - a, d - a))) / 6.0;
    ++removed_.tets;
    removed_.volume += volume;
    if (!has_tool_) {
      ++removed_.tets_beyond_tool;
      removed_.volume_beyond_tool += volume;
      continue;
    }
    const Vec3 centroid = 0.25 * (a + b + c + d);
    const bool beyond = distance_to_axis(tool_, centroid) > tool_.radius;
    removed_.tets_beyond_tool += beyond ? 1 : 0;
    // A tet whose centroid is in the ball meets it: the estimate need not test that again.
    const double share = beyond ? share_in_tool(tool_, a, b, c, d) : share_in_tool_meeting(tool_, a, b, c, d);
    removed_.volume_beyond_tool += volume * (1.0 - share);
    if (!within_reach(mesh, std::span<const TetId>(&t, 1))) ++removed_.tets_beyond_reach;
  }
  mesh.remove_tets(set);
}

}  // namespace tetcut::detail
