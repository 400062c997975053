#include "cut/tissue_selection.hpp"

#include <algorithm>
#include <cmath>

#include "tetcut/detail/local_tables.hpp"
#include "tetcut/detail/reserve_touched.hpp"

namespace tetcut::detail {

void TissueSelection::reserve(std::uint32_t tets) {
  selected_.reserve(tets);
  tissue_.reserve(tets);
  reserve_touched(removal_, 16384);
}

void TissueSelection::begin(const Tool* tool) {
  tool_ = tool ? std::optional<Tool>(*tool) : std::nullopt;
  selected_.clear();
  tissue_.clear();
  removal_.clear();
}

bool TissueSelection::centroid_in_tool(const std::array<Vec3, 4>& corners) const {
  if (!tool_) return false;
  Vec3 centroid{};
  for (const Vec3& p : corners) centroid = centroid + 0.25 * p;
  return !(distance_to_axis(*tool_, centroid) > tool_->radius);
}

bool TissueSelection::selectable(const TetMesh& mesh, TetId t) const {
  if (!tool_) return false;
  const auto v = mesh.tet(t);
  // The centroid as centroid_in_tool() sums it, corner by corner.
  Vec3 centroid{};
  for (VertId x : v) centroid = centroid + 0.25 * mesh.position(x);
  if (distance_to_axis(*tool_, centroid) > tool_->radius) return false;
  // |e| > D_ref by the squares, without a square root, where they decide it with a margin far
  // above their rounding (1e-12 relative, against a few 2^-53): between the two the root does,
  // so the answer is norm()'s to the bit.
  const double d_ref = params_.d_ref(), d_ref2 = d_ref * d_ref;
  const double longer = d_ref2 * (1.0 + 1e-12), shorter = d_ref2 * (1.0 - 1e-12);
  for (int e = 0; e < 6; ++e) {
    const Vec3 edge = mesh.position(v[kEdgeVerts[e][1]]) - mesh.position(v[kEdgeVerts[e][0]]);
    const double length2 = dot(edge, edge);
    if (length2 > longer) return false;
    if (!(length2 < shorter) && std::sqrt(length2) > d_ref) return false;
  }
  return true;
}

void TissueSelection::select(TetMesh& mesh, std::span<const TetId> region, const UncuttableTets& uncuttable,
                             std::uint32_t& uncuttable_in_tool) {
  for (TetId t : region) {
    // Each region tet is tested once. Nothing is tissue before this, so there is nothing to
    // follow() yet.
    if (!selectable(mesh, t)) continue;
    if (uncuttable.contains(mesh, t)) {
      ++uncuttable_in_tool;
      continue;
    }
    select_request(t);
  }
}

void TissueSelection::select_request(TetId t) {
  selected_.insert(t);
  tissue_.insert(t);
  removal_.push_back(t);
}

void TissueSelection::follow(const TetMesh& mesh, const TetMesh::Savepoint& point) {
  for (const TetMesh::TetBirth& birth : mesh.tets_made_since(point)) {
    // The journal lists parents before children, so a parent's marks are set when its children
    // are seen.
    const auto parents = mesh.parents(birth);
    if (!std::any_of(parents.begin(), parents.end(), [&](TetId p) { return tissue_.contains(p); })) continue;
    tissue_.insert(birth.tet);
    if (mesh.is_live(birth.tet) && selectable(mesh, birth.tet)) {
      selected_.insert(birth.tet);
      removal_.push_back(birth.tet);
    }
  }
}

bool TissueSelection::piece_in_tool(TetMesh& mesh, TetId t, const UncuttableTets& uncuttable) const {
  // A piece of an uncuttable tet is not tissue to take, however it lies.
  return mesh.is_live(t) && !tissue_.contains(t) && selectable(mesh, t) && !uncuttable.contains(mesh, t);
}

}  // namespace tetcut::detail
