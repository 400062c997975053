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
#include <cmath>
#include <cstdio>
#include <cstring>
#include <exception>
#include <map>
#include <memory>
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
using tetcut::adapters::centroid;
using tetcut::adapters::squared_distance_to_segment;

struct RemeshEngine {
  TetMesh mesh;
  std::vector<double> points;
  std::vector<std::uint32_t> tets;
  std::string error;
};

RemeshEngine* engine_of(tetcut_engine* engine) { return reinterpret_cast<RemeshEngine*>(engine); }

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

int cut_tool(RemeshEngine& e, const Vec3& a, const Vec3& b, double diameter) {
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
  std::vector<TetId> in_tool;
  for (TetId t : created) {
    if (squared_distance_to_segment(centroid(e.mesh, t), a, b) <= radius * radius) in_tool.push_back(t);
  }
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

tetcut_engine* create(const tetcut_engine_mesh* input, char* error, std::size_t error_size) {
  std::optional<TetMesh> mesh = tetcut::adapters::build_from(input, error, error_size);
  if (!mesh) return nullptr;
  auto e = std::make_unique<RemeshEngine>();
  e->mesh = std::move(*mesh);
  return reinterpret_cast<tetcut_engine*>(e.release());
}

void destroy(tetcut_engine* engine) { delete engine_of(engine); }

int remove_tet(tetcut_engine* engine, std::uint32_t tet) {
  RemeshEngine& e = *engine_of(engine);
  const TetId t{tet};
  if (!e.mesh.is_live(t)) return TETCUT_ENGINE_REFUSED;
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

int cut_capsule(tetcut_engine* engine, const double* a, const double* b, double diameter) {
  RemeshEngine& e = *engine_of(engine);
  try {
    return cut_tool(e, {a[0], a[1], a[2]}, {b[0], b[1], b[2]}, diameter);
  } catch (const std::exception& failure) {
    e.error = failure.what();
    return TETCUT_ENGINE_ERROR;
  }
}

int cut_ball(tetcut_engine* engine, const double* centre, double diameter) {
  return cut_capsule(engine, centre, centre, diameter);
}

int mesh(tetcut_engine* engine, tetcut_engine_mesh* out) {
  RemeshEngine& e = *engine_of(engine);
  tetcut::adapters::export_mesh(e.mesh, e.points, e.tets, out);
  return TETCUT_ENGINE_OK;
}

const char* last_error(tetcut_engine* engine) { return engine_of(engine)->error.c_str(); }

const tetcut_engine_api kApi = {TETCUT_ENGINE_ABI_VERSION, TETCUT_ENGINE_CAPSULE, "cgal-remesh",
                                "CGAL tetrahedral_isotropic_remeshing of the tool's neighbourhood, then remove and classify",
                                create, destroy, remove_tet, cut_ball, cut_capsule, mesh, nullptr, last_error};

}  // namespace

extern "C" const tetcut_engine_api* tetcut_engine_adapter(void) { return &kApi; }
