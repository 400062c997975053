// The checker's tests reach the engine's private arrays through the engine's one seam under
// TetMesh (detail::MeshInternals, engine/src/detail/mesh_internals.hpp): they corrupt exactly
// one record to prove that the checker sees what it compares (I2, I8).
#pragma once

#include "core/mesh_internals.hpp"

namespace tetcut {
using TetMeshTestAccess = detail::MeshInternals;
}  // namespace tetcut
