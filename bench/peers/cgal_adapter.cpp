// CGAL 5.5 "remove then classify" behind engine.h (cgal_peer.hpp): the mesh loaded into a
// Mesh_complex_3_in_triangulation_3, a cut removing the cells whose centroid is in the tool one by
// one, each removal undone when C3T3::face_status finds a vertex or an edge SINGULAR (and a
// refused cell tried again once a neighbour is gone). It keeps the mesh manifold by refusing
// tissue, not by refining: what it leaves in the tool is its answer. Cells keep their input
// index, so a removed one stays as a tombstone and the change log is the cells removed. The
// locate step is a centroid grid (harness/adapters/centroid_grid.hpp), as for the other peers.
#include <tetcut/harness/engine.h>

#include <array>
#include <cstdio>
#include <exception>
#include <memory>
#include <string>
#include <vector>

#include "adapters/centroid_grid.hpp"
#include "cgal_peer.hpp"

namespace {

struct CgalEngine {
  tetcut::peers::CgalTetMesh mesh;
  std::vector<double> points;
  std::vector<std::uint32_t> tets;  // 4 per cell, removed ones marked dead
  std::unique_ptr<tetcut::adapters::CentroidGrid> grid;
  std::vector<std::uint32_t> hit, removed;
  std::string error;
};

CgalEngine* engine_of(tetcut_engine* engine) { return reinterpret_cast<CgalEngine*>(engine); }

int remove_cells(CgalEngine& e, const std::vector<std::uint32_t>& cells) {
  e.removed.clear();
  try {
    e.mesh.remove_cells(cells, e.removed);
  } catch (const std::exception& failure) {
    e.error = failure.what();
    return TETCUT_ENGINE_ERROR;
  }
  for (std::uint32_t cell : e.removed) e.tets[4 * static_cast<std::size_t>(cell)] = TETCUT_ENGINE_DEAD_TET;
  return e.removed.empty() && !cells.empty() ? TETCUT_ENGINE_REFUSED : TETCUT_ENGINE_OK;
}

tetcut_engine* create(const tetcut_engine_mesh* input, char* error, std::size_t error_size) {
  auto e = std::make_unique<CgalEngine>();
  e->points.assign(input->points, input->points + 3 * static_cast<std::size_t>(input->point_count));
  e->tets.assign(input->tets, input->tets + 4 * static_cast<std::size_t>(input->tet_count));
  std::vector<tetcut::Vec3> positions(input->point_count);
  for (std::uint32_t v = 0; v < input->point_count; ++v) {
    positions[v] = {input->points[3 * v], input->points[3 * v + 1], input->points[3 * v + 2]};
  }
  std::vector<std::array<std::uint32_t, 4>> tets(input->tet_count);
  for (std::uint32_t t = 0; t < input->tet_count; ++t) {
    for (int i = 0; i < 4; ++i) tets[t][i] = input->tets[4 * t + i];
  }
  const tetcut::peers::CgalLoadResult loaded = e->mesh.load(positions, tets);
  if (!loaded.ok) {
    std::snprintf(error, error_size, "CGAL cannot load the mesh: %s", loaded.error.c_str());
    return nullptr;
  }
  e->grid = std::make_unique<tetcut::adapters::CentroidGrid>(input->points, input->tets, input->tet_count);
  return reinterpret_cast<tetcut_engine*>(e.release());
}

void destroy(tetcut_engine* engine) { delete engine_of(engine); }

int remove_tet(tetcut_engine* engine, std::uint32_t tet) {
  CgalEngine& e = *engine_of(engine);
  if (4 * static_cast<std::size_t>(tet) >= e.tets.size() || e.tets[4 * static_cast<std::size_t>(tet)] == TETCUT_ENGINE_DEAD_TET) {
    e.removed.clear();
    return TETCUT_ENGINE_REFUSED;
  }
  return remove_cells(e, {tet});
}

int cut_capsule(tetcut_engine* engine, const double* a, const double* b, double diameter) {
  CgalEngine& e = *engine_of(engine);
  e.hit.clear();
  e.grid->within(a, b, diameter, e.hit);
  std::vector<std::uint32_t> live;
  for (std::uint32_t cell : e.hit) {
    if (e.tets[4 * static_cast<std::size_t>(cell)] != TETCUT_ENGINE_DEAD_TET) live.push_back(cell);
  }
  if (live.empty()) {
    e.removed.clear();
    return TETCUT_ENGINE_OK;
  }
  return remove_cells(e, live);
}

int cut_ball(tetcut_engine* engine, const double* centre, double diameter) {
  return cut_capsule(engine, centre, centre, diameter);
}

int mesh(tetcut_engine* engine, tetcut_engine_mesh* out) {
  const CgalEngine& e = *engine_of(engine);
  *out = {e.points.data(), static_cast<std::uint32_t>(e.points.size() / 3), e.tets.data(),
          static_cast<std::uint32_t>(e.tets.size() / 4)};
  return TETCUT_ENGINE_OK;
}

int changes(tetcut_engine* engine, tetcut_engine_changes* out) {
  const CgalEngine& e = *engine_of(engine);
  *out = {};
  out->removed = e.removed.data();
  out->removed_count = static_cast<std::uint32_t>(e.removed.size());
  return TETCUT_ENGINE_OK;
}

const char* last_error(tetcut_engine* engine) { return engine_of(engine)->error.c_str(); }

const tetcut_engine_api kApi = {TETCUT_ENGINE_ABI_VERSION, TETCUT_ENGINE_CAPSULE | TETCUT_ENGINE_CHANGE_LOG,
                                "cgal", "CGAL C3T3 remove then classify",
                                create, destroy, remove_tet, cut_ball, cut_capsule, mesh, changes, last_error};

}  // namespace

extern "C" const tetcut_engine_api* tetcut_engine_adapter(void) { return &kApi; }
