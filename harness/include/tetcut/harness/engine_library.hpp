// An engine adapter (tetcut/harness/engine.h) loaded at run time, and one engine it creates,
// called through wrappers that validate every answer before the harness reads it: a null array,
// an index out of range or an unknown status becomes an EngineError naming the adapter, the
// operation and what was wrong, never a read of bad memory in the checker.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "tetcut/harness/engine.h"
#include "tetcut/raw_mesh.hpp"
#include "tetcut/raw_mesh_view.hpp"
#include "tetcut/vec3.hpp"

namespace tetcut::harness {

// What an adapter did wrong, or what the engine said went wrong: "adapter 'blind'
// (/path/libblind.so), cut 3 at (0.1, 0.2, 0.3): mesh() returned tet 7 with vertex 902 of 900".
class EngineError : public std::runtime_error {
 public:
  EngineError(const std::string& adapter, const std::string& operation, const std::string& reason);
  [[nodiscard]] const std::string& adapter() const { return adapter_; }
  [[nodiscard]] const std::string& operation() const { return operation_; }
  [[nodiscard]] const std::string& reason() const { return reason_; }

 private:
  std::string adapter_, operation_, reason_;
};

// The capability bits of engine.h, by name ("capsule", "change log", ...), comma-separated.
std::string capability_names(std::uint32_t capabilities);

class EngineLibrary {
 public:
  // Loads the shared library at `path`, finds tetcut_engine_adapter() and validates its table
  // (version, name, the required functions, a function for every capability claimed). Throws
  // EngineError (operation "load") with dlerror()'s text or what the table lacks.
  explicit EngineLibrary(const std::string& path);
  ~EngineLibrary();
  EngineLibrary(const EngineLibrary&) = delete;
  EngineLibrary& operator=(const EngineLibrary&) = delete;

  [[nodiscard]] const tetcut_engine_api& api() const { return *api_; }
  [[nodiscard]] const std::string& path() const { return path_; }
  [[nodiscard]] const std::string& name() const { return name_; }
  [[nodiscard]] const std::string& version() const { return version_; }
  [[nodiscard]] bool has(tetcut_engine_capability capability) const {
    return (api_->capabilities & static_cast<std::uint32_t>(capability)) != 0;
  }
  // "adapter 'NAME' (PATH)": how errors name it.
  [[nodiscard]] std::string label() const;

 private:
  std::string path_, name_, version_;
  void* handle_ = nullptr;
  const tetcut_engine_api* api_ = nullptr;
};

enum class EngineStatus : std::uint8_t { kOk, kRefused };

// The mesh an engine holds, copied out of its arrays once they are validated.
struct EngineMesh {
  std::vector<Vec3> positions;
  std::vector<std::array<std::uint32_t, 4>> tets;  // tombstones: first entry kDeadTetMarker
  std::uint64_t live_tets = 0;

  [[nodiscard]] RawMeshView view() const { return {positions, tets, /*has_tombstones=*/true}; }
};

// What the engine's last operation changed (engine.h's tetcut_engine_changes), validated.
struct EngineChanges {
  std::vector<std::uint32_t> removed, created;
  std::vector<RawMovedVertex> moved;
  double d_ref = 0.0;
  std::vector<std::uint32_t> left_in_tool;
  std::optional<double> angle_floor_deg;  // set when the engine lowered the angle floor
};

// One engine, created on a mesh; destroyed with this object. Every call names its operation,
// for the errors it may throw.
class EngineInstance {
 public:
  EngineInstance(const EngineLibrary& library, const RawMesh& mesh);
  ~EngineInstance();
  EngineInstance(const EngineInstance&) = delete;
  EngineInstance& operator=(const EngineInstance&) = delete;

  EngineStatus remove_tet(std::uint32_t tet, const std::string& operation);
  // A ball at `a`, or the capsule a-b when `b` is set (the adapter must offer capsules).
  EngineStatus cut(const Vec3& a, const std::optional<Vec3>& b, double diameter, const std::string& operation);

  // The engine's mesh now (mesh()), validated: every live tet's indices within the points, the
  // points finite, the arrays non-null. Replaces the previous read.
  const EngineMesh& read(const std::string& operation);
  [[nodiscard]] const EngineMesh& last_read() const { return mesh_; }
  // changes() after an operation, validated against the tet counts before (`tets_before`) and
  // after it (the last read). The adapter must offer a change log.
  EngineChanges changes(std::size_t tets_before, const std::string& operation);

 private:
  EngineStatus status_of(int status, const std::string& call, const std::string& operation);

  const EngineLibrary* library_;
  tetcut_engine* engine_ = nullptr;
  EngineMesh mesh_;
};

}  // namespace tetcut::harness
