// CGAL 5.5 as tetcut's peer ("CGAL, remove then classify"): a
// tet mesh given as plain arrays is loaded into a CGAL Mesh_complex_3_in_triangulation_3 over a
// Tetrahedral_remeshing::Remeshing_triangulation_3, and CGAL's own operations run on it.
//
// This header names no CGAL type: everything CGAL is in cgal_peer.cpp, the one translation unit
// of the benchmarks that includes CGAL (it compiles in about a minute; nothing else should pay
// for that, or for CGAL's usage requirements).
//
// The complex, as CGAL's mesh generators leave it and as the classification needs it:
// every tet a cell of subdomain 1, every boundary face a facet of the complex (surface patch 1).
// CGAL::build_triangulation (Mesh_3/tet_soup_to_c3t3.h) takes the mesh as it is, non-convex
// included: each boundary face gets an infinite cell behind it, so the triangulation is not
// Delaunay, which nothing here needs.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "tetcut/raw_mesh.hpp"
#include "tetcut/vec3.hpp"

namespace tetcut::peers {

struct CgalLoadResult {
  bool ok = true;
  std::string error;
  std::uint32_t cells = 0, vertices = 0, boundary_facets = 0;
  double seconds = 0;  // arrays -> C3T3, everything included (vertex compaction, adjacency, complex)
};

struct RemeshOptions {
  // CGAL splits edges longer than 4/3 of it and collapses those shorter than 4/5 of it. 0: the
  // mean edge length of the selected cells (an edge counted once per cell, as
  // TetMesh::mean_edge_length counts), so that the region keeps its density and what changes is
  // the shape of its cells, which is what the peer compares.
  double target_edge_length = 0;
  // CGAL's number_of_iterations: each is split, collapse, flip, smooth; CGAL then adds 3
  // flip-and-smooth passes of its own whatever the count.
  unsigned iterations = 1;
};

struct RemeshResult {
  bool ok = true;
  std::string error;
  std::uint32_t cells_selected = 0;   // before remeshing
  double target_edge_length = 0;      // the one used
  // The selected cells after remeshing (CGAL keeps the selection through splits and flips),
  // vertices renumbered densely, cells as CGAL orients them (positive, as tetcut's).
  RawMesh region;
  // Vertices of the region that it shares with the rest of the mesh or with the outside (the
  // selection's boundary and the mesh surface): CGAL must not move them (below). How many did
  // not keep their position: 0 unless CGAL changed what it was told to keep.
  std::uint32_t frozen_vertices = 0;
  std::uint32_t frozen_vertices_moved = 0;
  double seconds = 0;  // CGAL::tetrahedral_isotropic_remeshing alone
};

struct CgalRemovalResult {
  std::uint32_t removed = 0;  // cells taken out of the complex
  std::uint32_t refused = 0;  // cells left in it: every attempt made a vertex or an edge SINGULAR
};

// The CGAL release this was compiled against ("5.5.1"), for reports.
const char* cgal_version();

// One mesh in CGAL. Not copyable (a CGAL triangulation's handles point into it); movable.
class CgalTetMesh {
 public:
  CgalTetMesh();
  ~CgalTetMesh();
  CgalTetMesh(CgalTetMesh&&) noexcept;
  CgalTetMesh& operator=(CgalTetMesh&&) noexcept;

  // Replaces the loaded mesh with `tets` (#T by 4 ids into `positions`, positively oriented as
  // tetcut orients them, which is CGAL's orientation too). Positions no tet uses are left out, so
  // a TetMesh's positions() can be passed as they are with its live tets. Tet i of `tets` is
  // "cell i" for remesh(). Fails, with the reason, when an id is out of range or a face is shared
  // by more than two tets. O(#T) (CGAL hashes every face).
  CgalLoadResult load(std::span<const Vec3> positions, std::span<const std::array<std::uint32_t, 4>> tets);

  // CGAL::tetrahedral_isotropic_remeshing restricted to the cells `selected` (indices into the
  // tets last loaded; repeats are ignored), with remesh_boundaries(false): the mesh surface and
  // the selection's boundary are kept as they are, so that nothing outside the selection
  // changes and CGAL improves exactly the cells it is given, in place. The boundary faces are in
  // the complex and the selected cells are a subdomain of their own (2, CGAL's own example of
  // remeshing one subdomain), so both are surfaces of the complex, which CGAL then protects.
  //
  // Leaves the loaded mesh remeshed, the selection still marked: load() again before another
  // remesh(). Fails (the mesh untouched) when nothing is loaded or an index is out of range.
  RemeshResult remesh(std::span<const std::uint32_t> selected, const RemeshOptions& options = {});

  // "remove then classify", as CGAL's meshers keep their output manifold: each of the
  // cells `cells` (indices into the tets last loaded) still in the complex is taken out of it,
  // its four facets updated (a facet that was on the boundary leaves the complex, one shared
  // with a cell still in it joins it: removing a cell changes no facet by itself), and its four
  // vertices and six edges classified with C3T3::face_status; when one is SINGULAR the removal
  // is undone. A cell refused may become removable once a neighbour is gone, so the list is
  // passed over again while a pass removes something. `removed_out` receives the cells taken
  // out, in order. Needs a load() and no remesh() since; repeats and cells already out are
  // skipped. Allocates inside CGAL (its edge counter is a std::map) and while its list of
  // pending cells grows to the largest selection.
  CgalRemovalResult remove_cells(std::span<const std::uint32_t> cells, std::vector<std::uint32_t>& removed_out);

 private:
  struct Impl;  // the C3T3 and the cell handles by input index (cgal_peer.cpp)
  std::unique_ptr<Impl> impl_;
};

}  // namespace tetcut::peers
