// Small hand-built meshes for the generator and repair tests.
#pragma once

#include <cstdint>

#include "tetcut/box_mesh.hpp"
#include "tetcut/raw_mesh.hpp"
#include "tetcut/vec3.hpp"

namespace tetcut::test {

// Appends `b` to `a`, identifying every vertex of `b` whose position equals one of `a`'s.
inline RawMesh glue(const RawMesh& a, const RawMesh& b) {
  RawMesh out = a;
  std::vector<std::uint32_t> map(b.positions.size());
  for (std::size_t i = 0; i < b.positions.size(); ++i) {
    map[i] = static_cast<std::uint32_t>(out.positions.size());
    for (std::size_t j = 0; j < a.positions.size(); ++j)
      if (a.positions[j] == b.positions[i]) map[i] = static_cast<std::uint32_t>(j);
    if (map[i] == out.positions.size()) out.positions.push_back(b.positions[i]);
  }
  for (const auto& t : b.tets) out.tets.push_back({map[t[0]], map[t[1]], map[t[2]], map[t[3]]});
  return out;
}

inline std::uint32_t vertex_at(const RawMesh& m, Vec3 p) {
  for (std::size_t i = 0; i < m.positions.size(); ++i)
    if (m.positions[i] == p) return static_cast<std::uint32_t>(i);
  return 0xFFFFFFFFu;
}

inline bool contains(const std::array<std::uint32_t, 4>& t, std::uint32_t v) {
  return t[0] == v || t[1] == v || t[2] == v || t[3] == v;
}

// A 2x2x2 box whose centre (1,1,1) is reached by two conical holes, from the top and from the
// bottom: the centre's shell stays face-connected but its link is an annulus (design I5).
inline RawMesh pinched_box() {
  RawMesh box = make_box_mesh(2, 2, 2, {0, 0, 0}, {2, 2, 2});
  const auto centre = vertex_at(box, {1, 1, 1});
  const auto top = vertex_at(box, {1, 1, 2});
  const auto bottom = vertex_at(box, {1, 1, 0});
  RawMesh out;
  out.positions = box.positions;
  for (const auto& t : box.tets) {
    const bool on_axis = contains(t, centre) && (contains(t, top) || contains(t, bottom));
    if (!on_axis) out.tets.push_back(t);
  }
  return out;
}

}  // namespace tetcut::test
