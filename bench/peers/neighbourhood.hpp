// The part of a mesh a peer is given around a set of tets, when it need not be given the whole
// mesh: the set, a few rings of tets around it, and whatever more it takes for the part's own
// boundary to be a 2-manifold.
//
// Why the last: CGAL::build_triangulation closes a tet soup with one infinite vertex joined to
// every boundary face, which needs every boundary edge in exactly two boundary faces; and CGAL
// walks a vertex's star from one cell, which finds all of it only when the boundary faces around
// the vertex form one fan. A part cut out of a manifold mesh can fail both where it touches itself
// (two rings that meet along an edge or at a vertex). Such a vertex's whole shell then joins the
// part, which makes it an interior vertex of the part (or leaves it on the mesh's own surface,
// manifold there), until no offending vertex is left.
#pragma once

#include <optional>
#include <vector>

#include "tetcut/ids.hpp"
#include "tetcut/mesh.hpp"

namespace tetcut::peers {

// `selection`: live tets. Returns the live tets sharing a vertex with `selection`, then with
// those, `rings` times (`selection` itself for 0), grown until the part's boundary is a
// 2-manifold; sorted by id. Every live tet when `rings` is negative. nullopt if the growth has not
// settled after `max_repairs` rounds (the caller can then take the whole mesh). O(part x shell).
std::optional<std::vector<TetId>> manifold_neighbourhood(const TetMesh& mesh, const std::vector<TetId>& selection,
                                                         int rings, int max_repairs = 16);

}  // namespace tetcut::peers
