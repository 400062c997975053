// The rendered surface: the boundary triangles of the mesh, outward, and one area-weighted
// normal per surface vertex (paper 2: a manifold mesh "allows to compute a normal for each
// surface vertex", which Gouraud shading, PN triangles and the force sent to a haptic device
// need). A cut updates it through its ChangeLog in O(changed): the boundary faces of the tets it
// removed go, those of the tets it created come, and so do the faces of untouched tets that a
// removal laid bare (found through the shell of one of their vertices).
//
// A normal is the normalised sum of its triangles' cross products (twice their area times
// their unit normal), kept as a running sum: like the tensors of tensor_mass.hpp, a sum updated
// by many cuts matches a rebuild's to its last bits, not bit for bit.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "tetcut/change_log.hpp"
#include "tetcut/ids.hpp"
#include "tetcut/mesh.hpp"
#include "tetcut/vec3.hpp"

namespace tetcut::mechanics {

class RenderedSurface {
 public:
  struct Triangle {
    std::array<VertId, 3> v;  // counter-clockwise seen from outside; all kNoVert: a free slot
    Vec3 area_vector{};       // cross(v1 - v0, v2 - v0): twice the area times the unit normal
  };

  // From scratch: every boundary face of the mesh (O(#T)).
  explicit RenderedSurface(const TetMesh& mesh);
  // Room for this many tet and vertex ids and twice as many triangles as vertices, so that cuts
  // up to there allocate nothing (the constructor makes room for half as much again).
  void reserve(std::uint32_t tets, std::uint32_t vertices);

  // The cut's net change, the mesh as it is after it. Returns how many entries did not fit
  // the surface (a removed tet it did not know): 0 for the mesh's own log.
  std::uint32_t apply(const TetMesh& mesh, const ChangeLog& log);

  [[nodiscard]] std::uint32_t triangle_count() const { return live_triangles_; }
  [[nodiscard]] std::span<const Triangle> triangle_slots() const { return triangles_; }
  // Does the surface hold this triangle (any rotation of it, same orientation)?
  [[nodiscard]] bool contains(const Triangle& t) const;
  // The unit normal at v (zero when v is not on the surface), and its unnormalised sum.
  [[nodiscard]] Vec3 normal(VertId v) const;
  [[nodiscard]] const Vec3& normal_sum(VertId v) const { return normal_sum_[v.value]; }
  // Number of surface triangles at v; the sum of their cross products' lengths (the scale of
  // normal_sum, for tolerances).
  [[nodiscard]] std::uint32_t triangles_at(VertId v) const { return vertex_triangles_[v.value]; }
  [[nodiscard]] double normal_scale(VertId v) const { return normal_scale_[v.value]; }
  [[nodiscard]] std::uint32_t vertex_capacity() const { return static_cast<std::uint32_t>(normal_sum_.size()); }
  // What the last apply() wrote: triangle slots (filled or freed) and vertices whose normal sum
  // changed, each possibly more than once, in no order; what a copy kept by another thread
  // (snapshot.hpp) must take to be current again, in O(changed).
  [[nodiscard]] std::span<const std::uint32_t> last_changed_triangles() const { return changed_triangles_; }
  [[nodiscard]] std::span<const VertId> last_changed_vertices() const { return changed_vertices_; }

 private:
  static constexpr std::uint32_t kEmpty = 0xFFFFFFFFu;
  static constexpr std::uint32_t kDead = 0xFFFFFFFFu;
  using Key = std::array<std::uint32_t, 3>;  // sorted vertex ids

  void grow(std::uint32_t tets, std::uint32_t vertices);
  void grow_index(std::size_t capacity);
  [[nodiscard]] std::uint32_t find(const Key& key) const;
  void insert(const TetMesh& mesh, TetId t, int face);
  void erase(std::uint32_t slot);
  void account(const Triangle& t, double sign);

  std::vector<std::array<std::uint32_t, 4>> tets_;  // the model's copy: removed tets lose theirs
  std::vector<Vec3> normal_sum_;
  std::vector<double> normal_scale_;
  std::vector<std::uint32_t> vertex_triangles_;
  std::vector<Triangle> triangles_;
  std::vector<std::uint32_t> free_triangles_;
  std::vector<std::uint32_t> index_;  // open addressing by sorted key -> slot, homed by its smallest vertex
  std::uint32_t live_triangles_ = 0;
  std::vector<Key> candidates_, created_faces_;
  std::vector<TetId> shell_;
  std::vector<std::uint32_t> changed_triangles_;
  std::vector<VertId> changed_vertices_;
};

}  // namespace tetcut::mechanics
