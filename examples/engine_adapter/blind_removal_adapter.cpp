// The template engine adapter: copy this file to drive your own engine with tetcut's harness
// (`tetcut check-engine --engine libtetcut_engine_blind.so`); docs/engines.md walks through it.
//
// The engine here is the simplest one the field uses: blind removal. A cut deletes every tet
// whose centroid lies in the tool and nothing else: no refinement, no manifold test (what a
// simulator does when it deletes the cells a tool touches). It is here to be replaced, and to be
// caught: the harness's checker finds the singular vertices and edges it leaves.
//
// It needs nothing of tetcut but tetcut/harness/engine.h, and exports one C function.
#include <tetcut/harness/engine.h>

#include <array>
#include <cstdint>
#include <cstdio>
#include <new>
#include <vector>

namespace {

using Point = std::array<double, 3>;
using Tet = std::array<std::uint32_t, 4>;

// Your engine's state goes here; the harness sees only a pointer to it.
struct BlindEngine {
  std::vector<double> points;           // 3 per vertex, never renumbered
  std::vector<std::uint32_t> tets;      // 4 per tet; a removed tet keeps its slot, marked dead
  std::vector<std::uint32_t> removed;   // what the last operation removed (the change log)
};

BlindEngine* engine_of(tetcut_engine* engine) { return reinterpret_cast<BlindEngine*>(engine); }

Point centroid(const BlindEngine& e, std::size_t tet) {
  Point c{0, 0, 0};
  for (std::size_t i = 0; i < 4; ++i) {
    const std::size_t v = e.tets[4 * tet + i];
    for (std::size_t k = 0; k < 3; ++k) c[k] += e.points[3 * v + k] / 4;
  }
  return c;
}

double squared_distance_to_segment(const Point& p, const double* a, const double* b) {
  Point ab{}, ap{};
  double ab_ab = 0, ap_ab = 0;
  for (int k = 0; k < 3; ++k) {
    ab[k] = b[k] - a[k];
    ap[k] = p[k] - a[k];
    ab_ab += ab[k] * ab[k];
    ap_ab += ap[k] * ab[k];
  }
  const double t = ab_ab > 0 ? (ap_ab < 0 ? 0 : (ap_ab > ab_ab ? 1 : ap_ab / ab_ab)) : 0;
  double d2 = 0;
  for (int k = 0; k < 3; ++k) {
    const double d = ap[k] - t * ab[k];
    d2 += d * d;
  }
  return d2;
}

// Removes every live tet whose centroid is within diameter / 2 of the segment a-b (a ball when
// a == b). A scan of every tet, as a blind removal does.
int cut(tetcut_engine* engine, const double* a, const double* b, double diameter) {
  BlindEngine& e = *engine_of(engine);
  e.removed.clear();
  const double r2 = diameter * diameter / 4;
  for (std::size_t t = 0; 4 * t < e.tets.size(); ++t) {
    if (e.tets[4 * t] == TETCUT_ENGINE_DEAD_TET) continue;
    if (squared_distance_to_segment(centroid(e, t), a, b) <= r2) {
      e.tets[4 * t] = TETCUT_ENGINE_DEAD_TET;
      e.removed.push_back(static_cast<std::uint32_t>(t));
    }
  }
  return TETCUT_ENGINE_OK;
}

tetcut_engine* create(const tetcut_engine_mesh* mesh, char* error, std::size_t error_size) {
  auto* e = new (std::nothrow) BlindEngine;
  if (e == nullptr) {
    std::snprintf(error, error_size, "out of memory");
    return nullptr;
  }
  e->points.assign(mesh->points, mesh->points + 3 * static_cast<std::size_t>(mesh->point_count));
  e->tets.assign(mesh->tets, mesh->tets + 4 * static_cast<std::size_t>(mesh->tet_count));
  return reinterpret_cast<tetcut_engine*>(e);
}

void destroy(tetcut_engine* engine) { delete engine_of(engine); }

int remove_tet(tetcut_engine* engine, std::uint32_t tet) {
  BlindEngine& e = *engine_of(engine);
  e.removed.clear();
  if (4 * static_cast<std::size_t>(tet) >= e.tets.size() || e.tets[4 * tet] == TETCUT_ENGINE_DEAD_TET) {
    return TETCUT_ENGINE_REFUSED;
  }
  e.tets[4 * tet] = TETCUT_ENGINE_DEAD_TET;
  e.removed.push_back(tet);
  return TETCUT_ENGINE_OK;
}

int cut_ball(tetcut_engine* engine, const double* centre, double diameter) {
  return cut(engine, centre, centre, diameter);
}

int mesh(tetcut_engine* engine, tetcut_engine_mesh* out) {
  const BlindEngine& e = *engine_of(engine);
  *out = {e.points.data(), static_cast<std::uint32_t>(e.points.size() / 3), e.tets.data(),
          static_cast<std::uint32_t>(e.tets.size() / 4)};
  return TETCUT_ENGINE_OK;
}

int changes(tetcut_engine* engine, tetcut_engine_changes* out) {
  const BlindEngine& e = *engine_of(engine);
  *out = {};
  out->removed = e.removed.data();
  out->removed_count = static_cast<std::uint32_t>(e.removed.size());
  return TETCUT_ENGINE_OK;  // nothing created, nothing moved
}

const char* last_error(tetcut_engine*) { return ""; }

// Capsules and a change log: tet ids stay stable (dead tets keep their slots), so the harness
// checks each cut locally. No quality floor or tissue rule is promised: none is kept.
const tetcut_engine_api kApi = {
    TETCUT_ENGINE_ABI_VERSION, TETCUT_ENGINE_CAPSULE | TETCUT_ENGINE_CHANGE_LOG, "blind", "1.0",
    create, destroy, remove_tet, cut_ball, cut, mesh, changes, last_error};

}  // namespace

extern "C" const tetcut_engine_api* tetcut_engine_adapter(void) { return &kApi; }
