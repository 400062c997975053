#include "tetcut/mechanics/reaction_force.hpp"

#include <algorithm>

namespace tetcut::mechanics {

namespace {

// The squared distance from p to the segment a-b (to a when a == b).
double squared_distance_to_segment(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double length2 = dot(ab, ab);
  const double t = length2 > 0 ? std::clamp(dot(p - a, ab) / length2, 0.0, 1.0) : 0.0;
  const Vec3 d = p - (a + t * ab);
  return dot(d, d);
}

}  // namespace

Vec3 reaction_force(const TetMesh& mesh, const TensorMassModel& model, const Vec3& a, const Vec3& b, double radius,
                    std::vector<Vec3>& forces) {
  model.elastic_forces(forces);
  const double to_mesh = 1.0 / model.params().length_unit;
  const std::uint32_t vertices = std::min<std::uint32_t>(mesh.vertex_capacity(), model.vertex_capacity());
  Vec3 sum{};
  for (std::uint32_t v = 0; v < vertices; ++v) {
    const VertId id{v};
    if (!mesh.is_live(id)) continue;
    const Vec3 now = mesh.position(id) + to_mesh * model.displacement(id);
    if (squared_distance_to_segment(now, a, b) <= radius * radius) sum = sum + forces[v];
  }
  return sum;
}

}  // namespace tetcut::mechanics
