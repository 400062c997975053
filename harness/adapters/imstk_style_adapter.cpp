// Blind removal as iMSTK's PbdObjectCellRemoval does it (iMSTK 7), behind engine.h: a cut removes
// the cells whose centroid is in the tool, and nothing makes the result manifold. What it costs is
// what iMSTK pays for each removal:
//   - removeCellOnApply() queues the cells, apply() removes them;
//   - the cell's constraints go: apply() scans every constraint of the object (one volume
//     constraint per cell and one distance constraint per edge, as a PBD tissue has them) and
//     drops those whose particles all belong to a removed cell;
//   - the removed cell is not erased: its vertex ids all point at a dummy vertex iMSTK adds to
//     the mesh, so cell ids stay stable (hence a change log here);
//   - the surface (iMSTK's collision and visual meshes) is updated: each face of a removed cell
//     that was on the surface leaves it, and each that was interior joins it.
// This is our model of that algorithm, not iMSTK's code (no iMSTK package on Debian); the locate
// step is a centroid grid (centroid_grid.hpp), as the other peers locate.
#include <tetcut/harness/engine.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <map>
#include <new>
#include <vector>

#include "centroid_grid.hpp"

namespace {

using Face = std::array<std::uint32_t, 3>;

struct Constraint {
  std::array<std::uint32_t, 4> particles;
  std::uint32_t count;  // 2: distance, 4: volume
};

struct ImstkStyleEngine {
  std::vector<double> points;                 // the mesh's, then the dummy vertex
  std::uint32_t dummy = 0;
  std::vector<std::array<std::uint32_t, 4>> cells;
  std::vector<Constraint> constraints;
  std::map<Face, std::uint32_t> surface;      // the surface triangles (sorted ids -> owning cell)
  std::vector<std::uint32_t> queued, removed;
  std::vector<std::uint32_t> exported;        // 4 per cell, removed ones marked dead
  tetcut::adapters::CentroidGrid* grid = nullptr;

  ~ImstkStyleEngine() { delete grid; }
};

ImstkStyleEngine* engine_of(tetcut_engine* engine) { return reinterpret_cast<ImstkStyleEngine*>(engine); }

Face sorted_face(const std::array<std::uint32_t, 4>& cell, int opposite) {
  Face f{};
  int n = 0;
  for (int i = 0; i < 4; ++i) {
    if (i != opposite) f[n++] = cell[i];
  }
  std::sort(f.begin(), f.end());
  return f;
}

bool is_removed(const ImstkStyleEngine& e, std::uint32_t cell) { return e.cells[cell][0] == e.dummy; }

// PbdObjectCellRemoval::apply(): constraints, then the cells, then the surface.
void apply(ImstkStyleEngine& e) {
  e.removed.clear();
  for (std::uint32_t cell : e.queued) {
    if (is_removed(e, cell) || std::find(e.removed.begin(), e.removed.end(), cell) != e.removed.end()) continue;
    e.removed.push_back(cell);
  }
  e.queued.clear();
  for (std::uint32_t cell : e.removed) {
    const auto& v = e.cells[cell];
    auto in_cell = [&](std::uint32_t p) { return std::find(v.begin(), v.end(), p) != v.end(); };
    e.constraints.erase(std::remove_if(e.constraints.begin(), e.constraints.end(),
                                       [&](const Constraint& c) {
                                         return std::all_of(c.particles.begin(), c.particles.begin() + c.count, in_cell);
                                       }),
                        e.constraints.end());
    for (int f = 0; f < 4; ++f) {
      const Face face = sorted_face(v, f);
      if (e.surface.erase(face) == 0) e.surface.emplace(face, cell);
    }
  }
  for (std::uint32_t cell : e.removed) {
    e.cells[cell] = {e.dummy, e.dummy, e.dummy, e.dummy};
    e.exported[4 * cell] = TETCUT_ENGINE_DEAD_TET;
  }
}

tetcut_engine* create(const tetcut_engine_mesh* mesh, char* error, std::size_t error_size) {
  auto* e = new (std::nothrow) ImstkStyleEngine;
  if (e == nullptr) {
    std::snprintf(error, error_size, "out of memory");
    return nullptr;
  }
  e->points.assign(mesh->points, mesh->points + 3 * static_cast<std::size_t>(mesh->point_count));
  e->dummy = mesh->point_count;
  e->points.insert(e->points.end(), {0.0, 0.0, 0.0});
  e->exported.assign(mesh->tets, mesh->tets + 4 * static_cast<std::size_t>(mesh->tet_count));
  e->cells.resize(mesh->tet_count);
  std::map<Face, std::uint32_t> faces;
  for (std::uint32_t t = 0; t < mesh->tet_count; ++t) {
    auto& cell = e->cells[t];
    std::copy(mesh->tets + 4 * t, mesh->tets + 4 * t + 4, cell.begin());
    e->constraints.push_back({cell, 4});
    for (int i = 0; i < 4; ++i) {
      for (int j = i + 1; j < 4; ++j) e->constraints.push_back({{cell[i], cell[j], 0, 0}, 2});
      // (an edge shared by several cells has a constraint per cell, as a PBD mesh built per cell)
    }
    for (int f = 0; f < 4; ++f) {
      const Face face = sorted_face(cell, f);
      if (faces.erase(face) == 0) faces.emplace(face, t);
    }
  }
  e->surface = std::move(faces);
  e->grid = new tetcut::adapters::CentroidGrid(mesh->points, mesh->tets, mesh->tet_count);
  return reinterpret_cast<tetcut_engine*>(e);
}

void destroy(tetcut_engine* engine) { delete engine_of(engine); }

int remove_tet(tetcut_engine* engine, std::uint32_t tet) {
  ImstkStyleEngine& e = *engine_of(engine);
  if (tet >= e.cells.size() || is_removed(e, tet)) {
    e.removed.clear();
    return TETCUT_ENGINE_REFUSED;
  }
  e.queued.push_back(tet);
  apply(e);
  return TETCUT_ENGINE_OK;
}

int cut_capsule(tetcut_engine* engine, const double* a, const double* b, double diameter) {
  ImstkStyleEngine& e = *engine_of(engine);
  std::vector<std::uint32_t> hit;
  e.grid->within(a, b, diameter, hit);
  for (std::uint32_t cell : hit) {
    if (!is_removed(e, cell)) e.queued.push_back(cell);  // removeCellOnApply()
  }
  apply(e);
  return TETCUT_ENGINE_OK;
}

int cut_ball(tetcut_engine* engine, const double* centre, double diameter) {
  return cut_capsule(engine, centre, centre, diameter);
}

int mesh(tetcut_engine* engine, tetcut_engine_mesh* out) {
  const ImstkStyleEngine& e = *engine_of(engine);
  // The dummy vertex is iMSTK's bookkeeping, not tissue: the exported points end before it.
  *out = {e.points.data(), e.dummy, e.exported.data(), static_cast<std::uint32_t>(e.cells.size())};
  return TETCUT_ENGINE_OK;
}

int changes(tetcut_engine* engine, tetcut_engine_changes* out) {
  const ImstkStyleEngine& e = *engine_of(engine);
  *out = {};
  out->removed = e.removed.data();
  out->removed_count = static_cast<std::uint32_t>(e.removed.size());
  return TETCUT_ENGINE_OK;
}

const char* last_error(tetcut_engine*) { return ""; }

const tetcut_engine_api kApi = {TETCUT_ENGINE_ABI_VERSION,
                                TETCUT_ENGINE_CAPSULE | TETCUT_ENGINE_CHANGE_LOG,
                                "imstk-style",
                                "model of iMSTK 7 PbdObjectCellRemoval",
                                create, destroy, remove_tet, cut_ball, cut_capsule, mesh, changes, last_error};

}  // namespace

extern "C" const tetcut_engine_api* tetcut_engine_adapter(void) { return &kApi; }
