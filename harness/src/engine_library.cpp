#include "tetcut/harness/engine_library.hpp"

#include <dlfcn.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <sstream>

namespace tetcut::harness {

namespace {

constexpr std::size_t kMaxNameLength = 64;

std::string describe_status(int status) {
  return "an unknown status " + std::to_string(status) + " (engine.h has 0 ok, 1 refused, 2 error)";
}

bool valid_name(const char* name) {
  if (name == nullptr) return false;
  const std::size_t length = std::strlen(name);
  if (length == 0 || length > kMaxNameLength) return false;
  for (std::size_t i = 0; i < length; ++i) {
    const char c = name[i];
    if (!((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '-')) return false;
  }
  return true;
}

}  // namespace

EngineError::EngineError(const std::string& adapter, const std::string& operation, const std::string& reason)
    : std::runtime_error(adapter + ", " + operation + ": " + reason),
      adapter_(adapter),
      operation_(operation),
      reason_(reason) {}

std::string capability_names(std::uint32_t capabilities) {
  static constexpr std::pair<std::uint32_t, const char*> kNames[] = {
      {TETCUT_ENGINE_CAPSULE, "capsule"},
      {TETCUT_ENGINE_CHANGE_LOG, "change log"},
      {TETCUT_ENGINE_QUALITY_FLOOR, "quality floor"},
      {TETCUT_ENGINE_TISSUE_RULE, "tissue rule"}};
  std::string names;
  for (const auto& [bit, name] : kNames) {
    if ((capabilities & bit) == 0) continue;
    if (!names.empty()) names += ", ";
    names += name;
  }
  return names.empty() ? "none" : names;
}

EngineLibrary::EngineLibrary(const std::string& path) : path_(path) {
  const std::string unnamed = "adapter (" + path + ")";
  // RTLD_LOCAL: two adapters (or an adapter and tetcut itself) may define the same symbols.
  handle_ = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (handle_ == nullptr) {
    const char* why = dlerror();
    throw EngineError(unnamed, "load", why != nullptr ? why : "dlopen failed");
  }
  auto fail = [&](const std::string& reason) {
    dlclose(handle_);
    handle_ = nullptr;
    throw EngineError(name_.empty() ? unnamed : label(), "load", reason);
  };
  void* symbol = dlsym(handle_, TETCUT_ENGINE_ENTRY_POINT);
  if (symbol == nullptr) fail("no symbol " TETCUT_ENGINE_ENTRY_POINT " (extern \"C\", default visibility)");
  // POSIX guarantees that a dlsym() result converts to a function pointer.
  auto entry = reinterpret_cast<tetcut_engine_adapter_fn>(symbol);
  api_ = entry();
  if (api_ == nullptr) fail(TETCUT_ENGINE_ENTRY_POINT "() returned NULL");
  if (!valid_name(api_->name)) fail("its name is not 1 to 64 characters of [a-z0-9_-]");
  name_ = api_->name;
  version_ = api_->version != nullptr ? api_->version : "";
  if (api_->abi_version == 0 || api_->abi_version > TETCUT_ENGINE_ABI_VERSION) {
    fail("abi_version " + std::to_string(api_->abi_version) + ", this harness knows 1 to " +
         std::to_string(TETCUT_ENGINE_ABI_VERSION));
  }
  const std::pair<const void*, const char*> required[] = {
      {reinterpret_cast<const void*>(api_->create), "create"},
      {reinterpret_cast<const void*>(api_->destroy), "destroy"},
      {reinterpret_cast<const void*>(api_->remove_tet), "remove_tet"},
      {reinterpret_cast<const void*>(api_->cut_ball), "cut_ball"},
      {reinterpret_cast<const void*>(api_->mesh), "mesh"}};
  for (const auto& [function, what] : required) {
    if (function == nullptr) fail(std::string("the required function ") + what + " is NULL");
  }
  if (has(TETCUT_ENGINE_CAPSULE) && api_->cut_capsule == nullptr) fail("claims capsules but cut_capsule is NULL");
  if (has(TETCUT_ENGINE_CHANGE_LOG) && api_->changes == nullptr) fail("claims a change log but changes is NULL");
  if (has(TETCUT_ENGINE_TISSUE_RULE) && !has(TETCUT_ENGINE_CHANGE_LOG)) {
    fail("claims the tissue rule without a change log (d_ref and the left tets come with the changes)");
  }
  const std::uint32_t known = TETCUT_ENGINE_CAPSULE | TETCUT_ENGINE_CHANGE_LOG | TETCUT_ENGINE_QUALITY_FLOOR |
                              TETCUT_ENGINE_TISSUE_RULE;
  if ((api_->capabilities & ~known) != 0) {
    fail("unknown capability bits " + std::to_string(api_->capabilities & ~known));
  }
}

EngineLibrary::~EngineLibrary() {
  if (handle_ != nullptr) dlclose(handle_);
}

std::string EngineLibrary::label() const { return "adapter '" + name_ + "' (" + path_ + ")"; }

EngineInstance::EngineInstance(const EngineLibrary& library, const RawMesh& mesh) : library_(&library) {
  std::vector<double> points;
  points.reserve(3 * mesh.positions.size());
  for (const Vec3& p : mesh.positions) points.insert(points.end(), {p.x, p.y, p.z});
  std::vector<std::uint32_t> tets;
  tets.reserve(4 * mesh.tets.size());
  for (const auto& t : mesh.tets) tets.insert(tets.end(), t.begin(), t.end());
  const tetcut_engine_mesh input{points.data(), static_cast<std::uint32_t>(mesh.positions.size()), tets.data(),
                                 static_cast<std::uint32_t>(mesh.tets.size())};
  std::array<char, 512> error{};
  engine_ = library.api().create(&input, error.data(), error.size());
  if (engine_ == nullptr) {
    error.back() = '\0';
    throw EngineError(library.label(), "create",
                      error[0] != '\0' ? std::string(error.data()) : "create() returned NULL and wrote no error");
  }
}

EngineInstance::~EngineInstance() {
  if (engine_ != nullptr) library_->api().destroy(engine_);
}

EngineStatus EngineInstance::status_of(int status, const std::string& call, const std::string& operation) {
  if (status == TETCUT_ENGINE_OK) return EngineStatus::kOk;
  if (status == TETCUT_ENGINE_REFUSED) return EngineStatus::kRefused;
  if (status == TETCUT_ENGINE_ERROR) {
    const char* why = library_->api().last_error != nullptr ? library_->api().last_error(engine_) : nullptr;
    throw EngineError(library_->label(), operation,
                      call + "() failed: " + (why != nullptr && *why != '\0' ? why : "last_error() says nothing"));
  }
  throw EngineError(library_->label(), operation, call + "() returned " + describe_status(status));
}

EngineStatus EngineInstance::remove_tet(std::uint32_t tet, const std::string& operation) {
  return status_of(library_->api().remove_tet(engine_, tet), "remove_tet", operation);
}

EngineStatus EngineInstance::cut(const Vec3& a, const std::optional<Vec3>& b, double diameter,
                                 const std::string& operation) {
  const double from[3] = {a.x, a.y, a.z};
  if (!b) return status_of(library_->api().cut_ball(engine_, from, diameter), "cut_ball", operation);
  if (!library_->has(TETCUT_ENGINE_CAPSULE)) {
    throw EngineError(library_->label(), operation, "a capsule cut, and the adapter offers no cut_capsule");
  }
  const double to[3] = {b->x, b->y, b->z};
  return status_of(library_->api().cut_capsule(engine_, from, to, diameter), "cut_capsule", operation);
}

const EngineMesh& EngineInstance::read(const std::string& operation) {
  tetcut_engine_mesh out{};
  status_of(library_->api().mesh(engine_, &out), "mesh", operation);
  auto fail = [&](const std::string& reason) { throw EngineError(library_->label(), operation, "mesh() " + reason); };
  if (out.point_count > 0 && out.points == nullptr) fail("returned " + std::to_string(out.point_count) + " points and a NULL array");
  if (out.tet_count > 0 && out.tets == nullptr) fail("returned " + std::to_string(out.tet_count) + " tets and a NULL array");
  mesh_.positions.resize(out.point_count);
  for (std::uint32_t v = 0; v < out.point_count; ++v) {
    const Vec3 p{out.points[3 * v], out.points[3 * v + 1], out.points[3 * v + 2]};
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
      fail("returned point " + std::to_string(v) + " with a coordinate that is not finite");
    }
    mesh_.positions[v] = p;
  }
  mesh_.tets.resize(out.tet_count);
  mesh_.live_tets = 0;
  for (std::uint32_t t = 0; t < out.tet_count; ++t) {
    const std::uint32_t* tet = out.tets + 4 * static_cast<std::size_t>(t);
    std::copy(tet, tet + 4, mesh_.tets[t].begin());
    if (tet[0] == TETCUT_ENGINE_DEAD_TET) continue;
    ++mesh_.live_tets;
    for (int i = 0; i < 4; ++i) {
      if (tet[i] >= out.point_count) {
        std::ostringstream why;
        why << "returned tet " << t << " with vertex " << tet[i] << ", out of range (" << out.point_count
            << " points)";
        fail(why.str());
      }
    }
  }
  return mesh_;
}

EngineChanges EngineInstance::changes(std::size_t tets_before, const std::string& operation) {
  tetcut_engine_changes out{};
  status_of(library_->api().changes(engine_, &out), "changes", operation);
  auto fail = [&](const std::string& reason) {
    throw EngineError(library_->label(), operation, "changes() " + reason);
  };
  auto copy_ids = [&](const std::uint32_t* ids, std::uint32_t count, std::size_t limit, const char* what) {
    if (count > 0 && ids == nullptr) fail(std::string("returned ") + std::to_string(count) + " " + what + " and a NULL array");
    std::vector<std::uint32_t> copy(ids, ids + count);
    for (std::uint32_t id : copy) {
      if (id >= limit) fail(std::string("lists ") + what + " tet " + std::to_string(id) + ", out of range (" + std::to_string(limit) + " tets)");
    }
    return copy;
  };
  EngineChanges changes;
  changes.removed = copy_ids(out.removed, out.removed_count, tets_before, "removed");
  changes.created = copy_ids(out.created, out.created_count, mesh_.tets.size(), "created");
  for (std::uint32_t t : changes.created) {
    if (mesh_.tets[t][0] == kDeadTetMarker) fail("lists created tet " + std::to_string(t) + ", which mesh() gives as dead");
  }
  changes.left_in_tool = copy_ids(out.left_in_tool, out.left_in_tool_count, mesh_.tets.size(), "left in the tool");
  if (out.moved_count > 0 && out.moved == nullptr) fail("returned moved vertices and a NULL array");
  const std::size_t points = mesh_.positions.size();
  for (std::uint32_t i = 0; i < out.moved_count; ++i) {
    const tetcut_engine_moved_vertex& m = out.moved[i];
    if (m.vertex >= points || m.count < 1 || m.count > 4) {
      fail("lists a moved vertex " + std::to_string(m.vertex) + " with " + std::to_string(m.count) +
           " origins (a vertex below " + std::to_string(points) + ", 1 to 4 origins)");
    }
    RawMovedVertex raw{m.vertex, {}, {}, static_cast<std::uint8_t>(m.count)};
    for (std::uint32_t k = 0; k < m.count; ++k) {
      if (m.from[k] >= points) fail("moves vertex " + std::to_string(m.vertex) + " from vertex " + std::to_string(m.from[k]) + ", out of range");
      raw.from[k] = m.from[k];
      raw.weight[k] = m.weight[k];
    }
    changes.moved.push_back(raw);
  }
  if (!std::isfinite(out.d_ref) || out.d_ref < 0) fail("returned a d_ref that is negative or not finite");
  changes.d_ref = out.d_ref;
  if (out.angle_floor_lowered != 0) {
    if (!std::isfinite(out.angle_floor_deg) || out.angle_floor_deg < 0) fail("lowered the angle floor to a negative or not finite angle");
    changes.angle_floor_deg = out.angle_floor_deg;
  }
  return changes;
}

}  // namespace tetcut::harness
