// Blind removal as SOFA's carving does it (TetrahedronSetTopologyModifier::removeTetrahedra),
// behind engine.h: a cut removes the tets whose centroid is in the tool, and nothing makes the
// result manifold. What it costs is what SOFA pays for each removal:
//   - a removed tet's slot is filled by the last tet (SOFA keeps its arrays dense), so tet ids
//     change: no change log, and the harness checks the whole mesh after every cut;
//   - the boundary triangles are updated: a face of a removed tet that was shared becomes a
//     boundary triangle, one that was on the boundary goes (SOFA's TriangleSetTopology under the
//     tetrahedra, removeIsolatedItems); the triangle array is kept dense the same way.
// This is our model of that algorithm, not SOFA's code (no SOFA package on Debian); the locate
// step is a centroid grid over the tets as loaded (centroid_grid.hpp), with each tet's current
// slot kept beside it.
#include <tetcut/harness/engine.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <map>
#include <new>
#include <vector>

#include "centroid_grid.hpp"

namespace {

using Face = std::array<std::uint32_t, 3>;
constexpr std::uint32_t kGone = 0xFFFFFFFFu;

struct SofaStyleEngine {
  std::vector<double> points;
  std::vector<std::uint32_t> tets;           // 4 per tet, dense
  std::vector<std::uint32_t> original_of;    // per slot: the tet's index as loaded
  std::vector<std::uint32_t> slot_of;        // per tet as loaded: its slot now, kGone when removed
  std::map<Face, std::uint32_t> face_tets;   // tets around each face (1: a boundary triangle)
  std::vector<Face> triangles;               // the boundary triangles, dense
  std::map<Face, std::uint32_t> triangle_slot;
  tetcut::adapters::CentroidGrid* grid = nullptr;

  ~SofaStyleEngine() { delete grid; }
};

SofaStyleEngine* engine_of(tetcut_engine* engine) { return reinterpret_cast<SofaStyleEngine*>(engine); }

Face face_of(const std::uint32_t* tet, int opposite) {
  Face f{};
  int n = 0;
  for (int i = 0; i < 4; ++i) {
    if (i != opposite) f[n++] = tet[i];
  }
  std::sort(f.begin(), f.end());
  return f;
}

void add_triangle(SofaStyleEngine& e, const Face& f) {
  e.triangle_slot.emplace(f, static_cast<std::uint32_t>(e.triangles.size()));
  e.triangles.push_back(f);
}

void remove_triangle(SofaStyleEngine& e, const Face& f) {
  const auto it = e.triangle_slot.find(f);
  if (it == e.triangle_slot.end()) return;
  const std::uint32_t slot = it->second;
  e.triangle_slot.erase(it);
  if (slot + 1 != e.triangles.size()) {
    e.triangles[slot] = e.triangles.back();
    e.triangle_slot[e.triangles[slot]] = slot;
  }
  e.triangles.pop_back();
}

// removeTetrahedra(): highest slot first, each filled by the last tet.
void remove_tetrahedra(SofaStyleEngine& e, std::vector<std::uint32_t>& slots) {
  std::sort(slots.begin(), slots.end(), std::greater<>());
  slots.erase(std::unique(slots.begin(), slots.end()), slots.end());
  for (std::uint32_t slot : slots) {
    const std::uint32_t* tet = e.tets.data() + 4 * static_cast<std::size_t>(slot);
    for (int f = 0; f < 4; ++f) {
      const Face face = face_of(tet, f);
      const auto it = e.face_tets.find(face);
      if (--it->second == 0) {
        e.face_tets.erase(it);
        remove_triangle(e, face);
      } else {
        add_triangle(e, face);
      }
    }
    const std::size_t last = e.tets.size() / 4 - 1;
    e.slot_of[e.original_of[slot]] = kGone;
    if (slot != last) {
      std::copy(e.tets.begin() + 4 * last, e.tets.begin() + 4 * last + 4, e.tets.begin() + 4 * slot);
      e.original_of[slot] = e.original_of[last];
      e.slot_of[e.original_of[slot]] = slot;
    }
    e.tets.resize(4 * last);
    e.original_of.pop_back();
  }
}

tetcut_engine* create(const tetcut_engine_mesh* mesh, char* error, std::size_t error_size) {
  auto* e = new (std::nothrow) SofaStyleEngine;
  if (e == nullptr) {
    std::snprintf(error, error_size, "out of memory");
    return nullptr;
  }
  e->points.assign(mesh->points, mesh->points + 3 * static_cast<std::size_t>(mesh->point_count));
  e->tets.assign(mesh->tets, mesh->tets + 4 * static_cast<std::size_t>(mesh->tet_count));
  e->original_of.resize(mesh->tet_count);
  e->slot_of.resize(mesh->tet_count);
  for (std::uint32_t t = 0; t < mesh->tet_count; ++t) {
    e->original_of[t] = e->slot_of[t] = t;
    for (int f = 0; f < 4; ++f) ++e->face_tets[face_of(mesh->tets + 4 * t, f)];
  }
  for (const auto& [face, count] : e->face_tets) {
    if (count == 1) add_triangle(*e, face);
  }
  e->grid = new tetcut::adapters::CentroidGrid(mesh->points, mesh->tets, mesh->tet_count);
  return reinterpret_cast<tetcut_engine*>(e);
}

void destroy(tetcut_engine* engine) { delete engine_of(engine); }

int remove_tet(tetcut_engine* engine, std::uint32_t tet) {
  SofaStyleEngine& e = *engine_of(engine);
  if (tet >= e.tets.size() / 4) return TETCUT_ENGINE_REFUSED;
  std::vector<std::uint32_t> slots{tet};
  remove_tetrahedra(e, slots);
  return TETCUT_ENGINE_OK;
}

int cut_capsule(tetcut_engine* engine, const double* a, const double* b, double diameter) {
  SofaStyleEngine& e = *engine_of(engine);
  std::vector<std::uint32_t> hit;
  e.grid->within(a, b, diameter, hit);
  std::vector<std::uint32_t> slots;
  for (std::uint32_t original : hit) {
    if (e.slot_of[original] != kGone) slots.push_back(e.slot_of[original]);
  }
  remove_tetrahedra(e, slots);
  return TETCUT_ENGINE_OK;
}

int cut_ball(tetcut_engine* engine, const double* centre, double diameter) {
  return cut_capsule(engine, centre, centre, diameter);
}

int mesh(tetcut_engine* engine, tetcut_engine_mesh* out) {
  const SofaStyleEngine& e = *engine_of(engine);
  *out = {e.points.data(), static_cast<std::uint32_t>(e.points.size() / 3), e.tets.data(),
          static_cast<std::uint32_t>(e.tets.size() / 4)};
  return TETCUT_ENGINE_OK;
}

const char* last_error(tetcut_engine*) { return ""; }

const tetcut_engine_api kApi = {TETCUT_ENGINE_ABI_VERSION,
                                TETCUT_ENGINE_CAPSULE,
                                "sofa-style",
                                "model of SOFA TetrahedronSetTopologyModifier::removeTetrahedra",
                                create, destroy, remove_tet, cut_ball, cut_capsule, mesh, nullptr, last_error};

}  // namespace

extern "C" const tetcut_engine_api* tetcut_engine_adapter(void) { return &kApi; }
