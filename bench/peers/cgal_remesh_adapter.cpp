// CGAL 5.5 "remesh, then remove and classify" behind engine.h: the peer that does the same work as
// tetcut's refine-then-remove, locally. A cut
//   1. selects the tets that meet the tool's ball (a corner inside it, or the centroid within the
//      radius plus the tet's own reach);
//   2. hands CGAL that selection (grown until its boundary is a 2-manifold, neighbourhood.hpp:
//      CGAL's remeshing passes over whatever it is given, so it is given no more, as
//      tetcut_quality_peer does) and remeshes it with CGAL::tetrahedral_isotropic_remeshing towards
//      an edge of half the tool's diameter, the selection's boundary and the mesh surface kept
//      (cgal_peer.hpp);
//   3. puts the remeshed cells in the selection's place;
//   4. hands CGAL the new cells whose centroid is in the ball with a ring of tets around them,
//      and removes them one by one, each removal undone when C3T3::face_status finds a vertex or
//      an edge SINGULAR (the star of every vertex of a removed cell lies inside that part, so the
//      classification is the whole mesh's).
// The mesh's bookkeeping between cuts (adjacency, rings) is a tetcut::TetMesh, the remeshing
// and the classification are CGAL's. No change log: the remeshing replaces vertices and the
// harness checks the whole mesh after every cut. A CGAL failure or a kept vertex that moved is
// TETCUT_ENGINE_ERROR, the mesh as it was before the cut.
#include <tetcut/harness/engine.h>

#include <algorithm>
#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "cgal_peer.hpp"
#include "neighbourhood.hpp"
#include "adapters/tet_mesh_adapter.hpp"
#include "tetcut/mesh.hpp"

namespace {

using tetcut::TetId;
using tetcut::TetMesh;
using tetcut::Vec3;
using tetcut::VertId;
using tetcut::adapters::TetMeshEngine;

std::vector<std::array<std::uint32_t, 4>> corners_of(const TetMesh& mesh, const std::vector<TetId>& tets) {
  std::vector<std::array<std::uint32_t, 4>> out;
  out.reserve(tets.size());
  for (TetId t : tets) {
    const TetMesh::TetVerts v = mesh.tet(t);
    out.push_back({v[0].value, v[1].value, v[2].value, v[3].value});
  }
  return out;
}

// The indices of `subset` in the sorted `part`.
std::vector<std::uint32_t> places(const std::vector<TetId>& part, const std::vector<TetId>& subset) {
  std::vector<std::uint32_t> out;
  for (TetId t : subset) {
    const auto it = std::lower_bound(part.begin(), part.end(), t, [](TetId a, TetId b) { return a.value < b.value; });
    out.push_back(static_cast<std::uint32_t>(it - part.begin()));
  }
  return out;
}

// `tets` and `rings` rings of tets around them, grown until the part's boundary is a 2-manifold
// (CGAL's loading needs it); the whole mesh if the growth does not settle.
std::vector<TetId> part_around(const TetMesh& mesh, const std::vector<TetId>& tets, int rings) {
  std::optional<std::vector<TetId>> part = tetcut::peers::manifold_neighbourhood(mesh, tets, rings);
  if (!part) part = tetcut::peers::manifold_neighbourhood(mesh, tets, -1);
  return *part;
}

int cut_tool(TetMeshEngine& e, const Vec3& a, const Vec3& b, double diameter) {
  const double radius = diameter / 2;
  const auto positions = e.mesh.positions();
  // 1. The tets meeting the ball (or capsule), conservatively.
  const std::vector<TetId> selection = tetcut::adapters::tets_meeting_tool(e.mesh, a, b, radius);
  if (selection.empty()) return TETCUT_ENGINE_OK;
  // 2. CGAL remeshes the selection inside its neighbourhood.
  const std::vector<TetId> part = part_around(e.mesh, selection, 0);
  tetcut::peers::CgalTetMesh cgal;
  const tetcut::peers::CgalLoadResult loaded = cgal.load(positions, corners_of(e.mesh, part));
  if (!loaded.ok) {
    e.error = "CGAL cannot load the neighbourhood: " + loaded.error;
    return TETCUT_ENGINE_ERROR;
  }
  const tetcut::peers::RemeshResult remeshed =
      cgal.remesh(places(part, selection), {.target_edge_length = diameter / 2, .iterations = 1});
  if (!remeshed.ok || remeshed.frozen_vertices_moved > 0) {
    e.error = remeshed.ok ? "CGAL moved " + std::to_string(remeshed.frozen_vertices_moved) + " vertices it was told to keep"
                          : "CGAL's remeshing failed: " + remeshed.error;
    return TETCUT_ENGINE_ERROR;
  }
  // 3. The remeshed cells in the selection's place: a kept vertex is found by its position
  // (CGAL keeps it to the bit), every other one is new.
  std::map<std::array<double, 3>, VertId> kept;
  for (TetId t : selection) {
    for (VertId v : e.mesh.tet(t)) kept.emplace(std::array<double, 3>{positions[v.value].x, positions[v.value].y, positions[v.value].z}, v);
  }
  std::vector<VertId> vertex_of(remeshed.region.positions.size());
  for (std::size_t i = 0; i < vertex_of.size(); ++i) {
    const Vec3& p = remeshed.region.positions[i];
    const auto it = kept.find({p.x, p.y, p.z});
    vertex_of[i] = it != kept.end() ? it->second : e.mesh.add_vertex(p);
  }
  std::vector<TetMesh::TetVerts> added;
  for (const auto& t : remeshed.region.tets) added.push_back({vertex_of[t[0]], vertex_of[t[1]], vertex_of[t[2]], vertex_of[t[3]]});
  std::vector<TetId> created;
  e.mesh.replace_tets(selection, added, &created);
  // 4. The new cells in the tool, removed and classified by CGAL.
  std::vector<TetId> in_tool = tetcut::adapters::centroids_in_tool(e.mesh, created, a, b, radius);
  if (in_tool.empty()) return TETCUT_ENGINE_OK;
  std::sort(in_tool.begin(), in_tool.end(), [](TetId x, TetId y) { return x.value < y.value; });
  const std::vector<TetId> around = part_around(e.mesh, in_tool, 1);
  tetcut::peers::CgalTetMesh classify;
  const tetcut::peers::CgalLoadResult reloaded = classify.load(e.mesh.positions(), corners_of(e.mesh, around));
  if (!reloaded.ok) {
    e.error = "CGAL cannot load the remeshed neighbourhood: " + reloaded.error;
    return TETCUT_ENGINE_ERROR;
  }
  std::vector<std::uint32_t> removed_places;
  classify.remove_cells(places(around, in_tool), removed_places);
  std::vector<TetId> removed;
  for (std::uint32_t i : removed_places) removed.push_back(around[i]);
  e.mesh.remove_tets(removed);
  return TETCUT_ENGINE_OK;
}

// One tet, removed and classified by CGAL with a ring around it.
int remove_one(TetMeshEngine& e, TetId t) {
  const std::vector<TetId> one{t};
  const std::vector<TetId> around = part_around(e.mesh, one, 1);
  tetcut::peers::CgalTetMesh classify;
  if (!classify.load(e.mesh.positions(), corners_of(e.mesh, around)).ok) return TETCUT_ENGINE_REFUSED;
  std::vector<std::uint32_t> removed_places;
  classify.remove_cells(places(around, one), removed_places);
  if (removed_places.empty()) return TETCUT_ENGINE_REFUSED;
  e.mesh.remove_tets(one);
  return TETCUT_ENGINE_OK;
}

const tetcut_engine_api kApi = tetcut::adapters::TetMeshEntries<cut_tool, remove_one>::api(
    "cgal-remesh", "CGAL tetrahedral_isotropic_remeshing of the tool's neighbourhood, then remove and classify");

}  // namespace

extern "C" const tetcut_engine_api* tetcut_engine_adapter(void) { return &kApi; }
