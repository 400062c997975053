// What every generator returns: a mesh, or a message a user can act on (style: errors a user can
// cause are values). Generated meshes are positively oriented (tetcut's convention) and manifold.
#pragma once

#include <optional>
#include <string>
#include <utility>

#include "tetcut/raw_mesh.hpp"

namespace tetcut::generators {

struct GenResult {
  std::optional<RawMesh> mesh;  // set iff error is empty
  std::string error;            // one line, for people

  [[nodiscard]] bool ok() const { return mesh.has_value(); }

  static GenResult success(RawMesh m) { return GenResult{std::move(m), {}}; }
  static GenResult failure(std::string message) { return GenResult{std::nullopt, std::move(message)}; }
};

}  // namespace tetcut::generators
