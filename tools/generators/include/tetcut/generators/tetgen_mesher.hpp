// Tetrahedralizing a closed triangle surface with TetGen 1.5 through its library interface
// (tetgenio + tetrahedralize). TetGen is deterministic for a given input and switch string; its
// output is converted to tetcut's orientation (positive det(v1-v0, v2-v0, v3-v0)).
#pragma once

#include <string>

#include "tetcut/generators/gen_result.hpp"
#include "tetcut/generators/tri_surface.hpp"

namespace tetcut::generators {

struct TetgenOptions {
  // TetGen's -q: radius-edge ratio bound (>= 1.0; TetGen's own default is 2.0) and, when
  // positive, a minimum dihedral angle in degrees. 0 disables quality refinement.
  double radius_edge_ratio = 1.4;
  double min_dihedral_deg = 0.0;
  // TetGen's -a: a maximum tet volume; 0 means unconstrained.
  double max_volume = 0.0;
  // TetGen's -Y: keep the input triangles as they are (no Steiner points on the boundary).
  bool preserve_boundary = false;
};

// The switch string used for `options` (always "p", quiet "Q", zero-based "z"), for the record.
std::string tetgen_switches(const TetgenOptions& options);

GenResult tetrahedralize_surface(const TriSurface& surface, const TetgenOptions& options);

}  // namespace tetcut::generators
