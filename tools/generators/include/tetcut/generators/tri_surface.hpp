// A closed triangle surface, the input of the TetGen path (design: `gen surface FILE`, and the
// surfaces we construct for cylinder, sheet and box).
#pragma once

#include <optional>
#include <string>

#include "tetcut/io.hpp"

namespace tetcut::generators {

// The same arrays the surface readers produce (io.hpp: read_surface): #V positions, #F by 3
// vertex indices, 0-based, each triangle counter-clockwise seen from outside.
using TriSurface = SurfaceMesh;

// Why `surface` cannot bound a volume, or nullopt: a non-finite position, a dangling index, a
// triangle repeating a vertex, or an edge not shared by exactly two triangles (open or
// non-manifold). Orientation and self-intersection are left to TetGen, which reports them.
std::optional<std::string> closed_surface_problem(const TriSurface& surface);

}  // namespace tetcut::generators
