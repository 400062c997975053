#include "tetcut/box_mesh.hpp"

#include <array>
#include <utility>

namespace tetcut {

RawMesh make_box_mesh(std::uint32_t nx, std::uint32_t ny, std::uint32_t nz, Vec3 origin, Vec3 size) {
  RawMesh mesh;
  const std::uint32_t sx = nx + 1, sy = ny + 1, sz = nz + 1;
  mesh.positions.reserve(std::size_t{sx} * sy * sz);
  for (std::uint32_t k = 0; k < sz; ++k)
    for (std::uint32_t j = 0; j < sy; ++j)
      for (std::uint32_t i = 0; i < sx; ++i)
        mesh.positions.push_back({origin.x + size.x * i / nx, origin.y + size.y * j / ny,
                                  origin.z + size.z * k / nz});
  auto id = [&](std::uint32_t i, std::uint32_t j, std::uint32_t k) { return i + sx * (j + sy * k); };

  // The 6 monotone paths from corner 000 to 111, one per permutation of the axes; the odd
  // permutations give negatively ordered tets, fixed by swapping the two middle vertices.
  constexpr std::array<std::array<int, 3>, 6> kAxisOrders = {
      {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {2, 1, 0}, {1, 0, 2}}};
  mesh.tets.reserve(std::size_t{6} * nx * ny * nz);
  for (std::uint32_t k = 0; k < nz; ++k)
    for (std::uint32_t j = 0; j < ny; ++j)
      for (std::uint32_t i = 0; i < nx; ++i)
        for (std::size_t p = 0; p < kAxisOrders.size(); ++p) {
          std::uint32_t c[3] = {i, j, k};
          std::array<std::uint32_t, 4> tet{};
          tet[0] = id(c[0], c[1], c[2]);
          for (int step = 0; step < 3; ++step) {
            ++c[kAxisOrders[p][step]];
            tet[step + 1] = id(c[0], c[1], c[2]);
          }
          if (p >= 3) std::swap(tet[1], tet[2]);
          mesh.tets.push_back(tet);
        }
  return mesh;
}

}  // namespace tetcut
