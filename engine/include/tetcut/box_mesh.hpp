// A structured tetrahedral box: nx * ny * nz cubes, each cut into 6 tets around its main
// diagonal (Kuhn / Freudenthal subdivision), which is conformal across cubes because every cube
// uses the same diagonal direction. Manifold and positively oriented by construction: the
// dependable synthetic mesh for tests and benchmarks of any size.
#pragma once

#include <cstdint>

#include "tetcut/raw_mesh.hpp"
#include "tetcut/vec3.hpp"

namespace tetcut {

// 6 * nx * ny * nz tets, (nx+1)(ny+1)(nz+1) vertices, spanning [origin, origin + size].
RawMesh make_box_mesh(std::uint32_t nx, std::uint32_t ny, std::uint32_t nz,
                      Vec3 origin = {0, 0, 0}, Vec3 size = {1, 1, 1});

}  // namespace tetcut
