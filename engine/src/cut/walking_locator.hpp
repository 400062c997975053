// Locate (paper 3.1) by walking through faces: the tets a tool meets, found from seeds and grown
// face by face, without an index entry per tet.
//
// Why the walk finds them all. In a manifold mesh the tets around a point, an edge or a vertex
// are face-connected, so the tets meeting a convex tool K that lie in one connected component of
// K ∩ |M| are face-connected through tets meeting K. A walk from one tet of each component, that
// steps to every face neighbour meeting the tool, reaches them all. And every component of
// K ∩ |M| either meets the mesh's boundary, or it is open and closed in K and so all of K: the
// tool lies inside the mesh. The seeds are therefore
//
//   - the boundary tets meeting the tool (kept in a SpatialIndex of the tets with a boundary
//     face, a small part of the mesh, updated from what each operation rewired), which covers a
//     tool that spans a cavity or meets two pieces: each part it meets has boundary there;
//   - when no boundary tet meets it, the tet holding the tool's first end, found by walking
//     from the last answer (consecutive tools overlap) or from a coarse grid of vertices built
//     with the locator (the first cut, a jump), or no tet when that end is outside the mesh
//     (then K ∩ |M| is empty).
//
// Rounding. The test of a tet against the tool (intersects(), plain floating point) may
// disagree about a point two tets share, within rounding. So the walk steps through tets meeting
// the tool grown by a margin far above that rounding, and answers the tets meeting the tool
// itself: a tet the test says meets the tool truly meets the tool grown by half the margin, whose
// components the argument above covers with tets the test then says meet the grown tool.
//
// Point location. A visibility walk (to a neighbour across a face the point is beyond, by the
// exact orientation predicate) ends in the tet holding the point, or is blocked by the boundary
// of a mesh that is not convex. Then the segment from the blocked tet's centroid to the point is
// tested against the boundary faces near it (the boundary index again): past its last crossing
// it stays inside or outside the mesh, as the crossing's side says, and a straight walk along it
// from the tet behind that crossing reaches the point. A segment through a boundary edge or
// vertex is a degenerate case the walk does not decide; it then scans the mesh, and counts it
// (scans()): no test or benchmark input has needed one, and the tests assert so.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "core/tool.hpp"
#include "cut/spatial_index.hpp"
#include "tetcut/detail/stamped_property.hpp"
#include "tetcut/mesh.hpp"

namespace tetcut {

class WalkingLocator {
 public:
  // Indexes the boundary tets in cells of `cell_size` (about the mean edge length) and lays the
  // coarse grid of starting vertices: O(#T), once.
  void build(const TetMesh& mesh, double cell_size);
  // Room for a cut's working size, so that a cut's walk allocates nothing.
  void reserve(std::uint32_t tets);
  // After an operation: the tets it removed and made (net) and those it rewired
  // (TetMesh::rewired_tets()); repeats and dead ids are fine.
  void update(const TetMesh& mesh, std::span<const TetId> removed, std::span<const TetId> created,
              std::span<const TetId> rewired);

  // The live tets meeting the tool (exact closest-point test, as scan_tets_meeting() decides
  // each), sorted by id.
  void query(const TetMesh& mesh, const Tool& tool, std::vector<TetId>& out);
  // A live tet holding p (closed), walking from `start` (a live tet), or kNoTet when p is
  // outside the mesh. Public for the tests, which start walks where they must be blocked.
  TetId locate_point(const TetMesh& mesh, const Vec3& p, TetId start);

  // Point locations that could not be decided by walking and scanned the mesh instead.
  [[nodiscard]] std::uint64_t scans() const { return scans_; }
  // Point locations that the boundary blocked, decided by the segment to the last crossing.
  [[nodiscard]] std::uint64_t blocked_walks() const { return blocked_walks_; }

 private:
  enum class Walk : std::uint8_t { kArrived, kBlocked, kLost };
  Walk visibility_walk(const TetMesh& mesh, const Vec3& p, TetId& t) const;
  Walk straight_walk(const TetMesh& mesh, const Vec3& from, const Vec3& p, TetId& t) const;
  TetId past_last_crossing(const TetMesh& mesh, const Vec3& p, TetId blocked);
  TetId scan_for_point(const TetMesh& mesh, const Vec3& p);
  TetId start_for(const TetMesh& mesh, const Vec3& p) const;
  [[nodiscard]] std::uint64_t coarse_key(const Vec3& p) const;
  [[nodiscard]] double margin(const Tool& tool) const;

  SpatialIndex boundary_;  // the live tets with a boundary face
  double cell_size_ = 1.0;  // the boundary index's cell: the mesh's mean edge length
  // The coarse grid of starts: a vertex per cell of 4 x 4 x 4 index cells, by key, sorted.
  std::vector<std::pair<std::uint64_t, VertId>> starts_;
  TetId last_ = kNoTet;  // the last answer's first tet: where the next walk starts
  StampedSet<TetId> seen_;
  std::vector<TetId> queue_, seeds_, crossings_;
  std::uint64_t scans_ = 0, blocked_walks_ = 0;
};

}  // namespace tetcut
