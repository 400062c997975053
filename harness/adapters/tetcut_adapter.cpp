// tetcut itself behind the engine interface (tetcut/harness/engine.h): the harness drives it as it
// drives any other engine, so that what it says of tetcut and of a peer is measured the same way.
// Every cut goes through the Cutter with its default parameters but the tool's diameter; a cut
// the Cutter refuses leaves the mesh bit-identical (plan, then apply), which is engine.h's
// TETCUT_ENGINE_REFUSED. The mesh keeps tombstones, so tet ids are stable and the change log is
// the Cutter's own net change. When the improvement pass cannot lift a cut's new tets to the
// 15 degree floor, the Cutter holds them to 10 degrees, then to none (CutReport::
// min_dihedral_held_deg); the change log says so (angle_floor_lowered), as engine.h asks.
#include <tetcut/harness/engine.h>

#include <cstdio>
#include <exception>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "tet_mesh_adapter.hpp"
#include "tetcut/cut.hpp"

namespace {

using tetcut::Vec3;

struct TetcutEngine {
  tetcut::TetMesh mesh;
  std::optional<tetcut::Cutter> cutter;
  std::vector<double> points;
  std::vector<std::uint32_t> tets;
  std::vector<std::uint32_t> removed, created, left;
  std::vector<tetcut_engine_moved_vertex> moved;
  double d_ref = 0.0;
  double angle_floor_held = 180.0;
  std::string error;
};

TetcutEngine* engine_of(tetcut_engine* engine) { return reinterpret_cast<TetcutEngine*>(engine); }

template <class Ids>
void copy_ids(const Ids& from, std::vector<std::uint32_t>& to) {
  to.clear();
  for (const auto& id : from) to.push_back(id.value);
}

// Keeps the last operation's net change for changes(); a refused one changed nothing.
int finish(TetcutEngine& e, const tetcut::CutReport& report, bool is_cut) {
  e.removed.clear();
  e.created.clear();
  e.left.clear();
  e.moved.clear();
  e.d_ref = 0.0;
  e.angle_floor_held = 180.0;
  if (!report.ok) return TETCUT_ENGINE_REFUSED;
  e.angle_floor_held = e.cutter->last_min_dihedral_held();
  copy_ids(e.cutter->last_removed(), e.removed);
  copy_ids(e.cutter->last_created(), e.created);
  for (const tetcut::RawMovedVertex& m : e.cutter->last_moved()) {
    tetcut_engine_moved_vertex out{m.vertex, m.count, {}, {}};
    for (std::size_t k = 0; k < m.count; ++k) {
      out.from[k] = m.from[k];
      out.weight[k] = m.weight[k];
    }
    e.moved.push_back(out);
  }
  if (is_cut) {
    copy_ids(e.cutter->last_left_in_tool(), e.left);
    e.d_ref = e.cutter->params().d_ref();
  }
  return TETCUT_ENGINE_OK;
}

// The tool's diameter, the one parameter the interface carries.
bool set_diameter(TetcutEngine& e, double diameter) {
  if (e.cutter->params().tool_diameter == diameter) return true;
  tetcut::CutParams params = e.cutter->params();
  params.tool_diameter = diameter;
  if (std::optional<std::string> why = e.cutter->set_params(params)) {
    e.error = "diameter " + std::to_string(diameter) + ": " + *why;
    return false;
  }
  return true;
}

tetcut_engine* create(const tetcut_engine_mesh* input, char* error, std::size_t error_size) {
  std::optional<tetcut::TetMesh> mesh = tetcut::adapters::build_from(input, error, error_size);
  if (!mesh) return nullptr;
  auto e = std::make_unique<TetcutEngine>();
  e->mesh = std::move(*mesh);
  e->cutter.emplace(e->mesh, tetcut::CutParams{});
  return reinterpret_cast<tetcut_engine*>(e.release());
}

void destroy(tetcut_engine* engine) { delete engine_of(engine); }

int remove_tet(tetcut_engine* engine, std::uint32_t tet) {
  TetcutEngine& e = *engine_of(engine);
  return finish(e, e.cutter->remove(tetcut::TetId{tet}), false);
}

int cut_capsule(tetcut_engine* engine, const double* a, const double* b, double diameter) {
  TetcutEngine& e = *engine_of(engine);
  if (!set_diameter(e, diameter)) return TETCUT_ENGINE_ERROR;
  return finish(e, e.cutter->cut_segment(Vec3{a[0], a[1], a[2]}, Vec3{b[0], b[1], b[2]}), true);
}

int cut_ball(tetcut_engine* engine, const double* centre, double diameter) {
  TetcutEngine& e = *engine_of(engine);
  if (!set_diameter(e, diameter)) return TETCUT_ENGINE_ERROR;
  return finish(e, e.cutter->cut(Vec3{centre[0], centre[1], centre[2]}), true);
}

int mesh(tetcut_engine* engine, tetcut_engine_mesh* out) {
  TetcutEngine& e = *engine_of(engine);
  tetcut::adapters::export_mesh(e.mesh, e.points, e.tets, out);
  return TETCUT_ENGINE_OK;
}

int changes(tetcut_engine* engine, tetcut_engine_changes* out) {
  const TetcutEngine& e = *engine_of(engine);
  *out = {e.removed.data(), static_cast<std::uint32_t>(e.removed.size()),
          e.created.data(), static_cast<std::uint32_t>(e.created.size()),
          e.moved.data(), static_cast<std::uint32_t>(e.moved.size()),
          e.d_ref, e.left.data(), static_cast<std::uint32_t>(e.left.size()),
          e.angle_floor_held < e.cutter->params().min_dihedral_deg ? 1u : 0u, e.angle_floor_held};
  return TETCUT_ENGINE_OK;
}

const char* last_error(tetcut_engine* engine) { return engine_of(engine)->error.c_str(); }

const tetcut_engine_api kApi = {
    TETCUT_ENGINE_ABI_VERSION,
    TETCUT_ENGINE_CAPSULE | TETCUT_ENGINE_CHANGE_LOG | TETCUT_ENGINE_QUALITY_FLOOR | TETCUT_ENGINE_TISSUE_RULE,
    "tetcut", TETCUT_ADAPTER_VERSION,
    create, destroy, remove_tet, cut_ball, cut_capsule, mesh, changes, last_error};

}  // namespace

extern "C" const tetcut_engine_api* tetcut_engine_adapter(void) { return &kApi; }
