// A mesh's boundary surface as triangles, each marked as original surface or cut surface: what
// the surface picture draws in two colours.
#pragma once

#include <vector>

#include "tetcut/mesh.hpp"
#include "tetcut/vec3.hpp"

namespace tetcut::render {

struct SurfaceTriangle {
  Vec3 a, b, c;      // counter-clockwise seen from outside the mesh
  bool cut = false;  // exposed by a cut: not on the surface of the mesh before cutting
};

// Every boundary face of `mesh` (live tets in id order, faces in local order), none marked cut.
std::vector<SurfaceTriangle> boundary_surface(const TetMesh& mesh);

// The boundary faces of `mesh` in the same order as boundary_surface(), a face marked `cut` when
// it does not lie on the boundary surface of `original` (the mesh before cutting).
//
// Refinement splits original boundary faces into smaller ones that still lie on the original
// surface, and vertex ids mean nothing across meshes, so the test is geometric: a face is
// original surface when some boundary face F of `original` touching the face's centroid (found
// by a ball query of radius tol on a SpatialIndex of `original`) has all three of the face's
// vertices within tol of F's plane, the centroid inside F (within tol of each edge line), and the
// same outward side. tol = 1e-9 x the diagonal of `original`'s bounding box: far above the
// rounding of split positions (a few ulps), far below any feature of a real mesh. A face exposed
// by a cut lies inside the original volume, so it fails the test. Cost: O(#T) to index
// `original`, then a few tet tests per boundary face (16k tets: a few milliseconds).
std::vector<SurfaceTriangle> classify_surface(const TetMesh& mesh, const TetMesh& original);

}  // namespace tetcut::render
