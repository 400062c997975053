// An adapter that misbehaves on request, for the harness's tests: the environment variable
// TETCUT_FAULTY_ADAPTER picks the fault (read when the harness loads the library, in the child).
// Its engine otherwise does nothing: every cut and removal succeeds and changes nothing.
//   abort-on-cut-N   abort() in the N-th cut (a crash the harness must survive and name)
//   hang             the first cut never returns (the harness's timeout)
//   error            every cut fails, with a reason in last_error()
//   status-7         every cut returns 7, a status engine.h does not have
//   bad-vertex       after the first cut mesh() gives a tet a vertex one past the points
//   null-points      after the first cut mesh() gives the points as NULL
//   bad-removed      after the first cut changes() lists a removed tet one past the tets
//   abi-99           the table says abi_version 99
//   no-mesh          the table's mesh function is NULL
//   create-fails     create() returns NULL with a reason
#include <tetcut/harness/engine.h>

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace {

std::string fault() {
  const char* mode = std::getenv("TETCUT_FAULTY_ADAPTER");
  return mode != nullptr ? mode : "";
}

struct FaultyEngine {
  std::vector<double> points;
  std::vector<std::uint32_t> tets;
  std::uint32_t removed_past_end = 0;
  int cuts = 0;
  std::string mode;
};

FaultyEngine* engine_of(tetcut_engine* engine) { return reinterpret_cast<FaultyEngine*>(engine); }

tetcut_engine* create(const tetcut_engine_mesh* mesh, char* error, std::size_t error_size) {
  if (fault() == "create-fails") {
    std::snprintf(error, error_size, "the faulty engine refuses every mesh");
    return nullptr;
  }
  auto* e = new FaultyEngine;
  e->points.assign(mesh->points, mesh->points + 3 * static_cast<std::size_t>(mesh->point_count));
  e->tets.assign(mesh->tets, mesh->tets + 4 * static_cast<std::size_t>(mesh->tet_count));
  e->mode = fault();
  return reinterpret_cast<tetcut_engine*>(e);
}

void destroy(tetcut_engine* engine) { delete engine_of(engine); }

int remove_tet(tetcut_engine*, std::uint32_t) { return TETCUT_ENGINE_OK; }

int cut(tetcut_engine* engine) {
  FaultyEngine& e = *engine_of(engine);
  ++e.cuts;
  if (e.mode.rfind("abort-on-cut-", 0) == 0 && e.cuts == std::atoi(e.mode.c_str() + 13)) std::abort();
  if (e.mode == "hang") {
    for (;;) pause();
  }
  if (e.mode == "error") return TETCUT_ENGINE_ERROR;
  if (e.mode == "status-7") return 7;
  return TETCUT_ENGINE_OK;
}

int cut_ball(tetcut_engine* engine, const double*, double) { return cut(engine); }

int mesh(tetcut_engine* engine, tetcut_engine_mesh* out) {
  FaultyEngine& e = *engine_of(engine);
  const auto points = static_cast<std::uint32_t>(e.points.size() / 3);
  if (e.cuts > 0 && e.mode == "bad-vertex") e.tets[1] = points;
  *out = {e.points.data(), points, e.tets.data(), static_cast<std::uint32_t>(e.tets.size() / 4)};
  if (e.cuts > 0 && e.mode == "null-points") out->points = nullptr;
  return TETCUT_ENGINE_OK;
}

int changes(tetcut_engine* engine, tetcut_engine_changes* out) {
  FaultyEngine& e = *engine_of(engine);
  *out = {};
  if (e.cuts > 0 && e.mode == "bad-removed") {
    e.removed_past_end = static_cast<std::uint32_t>(e.tets.size() / 4);
    out->removed = &e.removed_past_end;
    out->removed_count = 1;
  }
  return TETCUT_ENGINE_OK;
}

const char* last_error(tetcut_engine*) { return "the tool left the workspace"; }

tetcut_engine_api api = {TETCUT_ENGINE_ABI_VERSION, TETCUT_ENGINE_CHANGE_LOG, "faulty", "0",
                         create, destroy, remove_tet, cut_ball, nullptr, mesh, changes, last_error};

}  // namespace

extern "C" const tetcut_engine_api* tetcut_engine_adapter(void) {
  if (fault() == "abi-99") api.abi_version = 99;
  if (fault() == "no-mesh") api.mesh = nullptr;
  return &api;
}
