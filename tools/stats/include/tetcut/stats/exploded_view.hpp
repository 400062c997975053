// Pulls the pieces of a cut mesh apart for a picture, so that the surfaces a resection exposed
// face the viewer instead of each other across a slot a few millimetres wide.
#pragma once

#include <vector>

#include "tetcut/mesh.hpp"
#include "tetcut/render/surface.hpp"

namespace tetcut::stats {

// `triangles` are the boundary faces of `mesh` in render::boundary_surface()'s order (live tets
// by id, faces in local order). Every face-connected piece but the largest (most boundary
// faces; lowest first tet on a tie) is moved by `gap` away from the largest, along the line
// from the largest piece's centre to its own (centres: mean of their boundary faces' centroids).
// A mesh in one piece is left as it is.
void explode_pieces(const TetMesh& mesh, std::vector<render::SurfaceTriangle>& triangles, double gap);

}  // namespace tetcut::stats
