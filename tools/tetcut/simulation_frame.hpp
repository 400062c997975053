// One frame of `tetcut simulate` as a VTK XML unstructured grid (.vtu, ASCII) for ParaView:
// the rest positions, the tets, the displacement of every vertex (point data "displacement", in
// the mesh's units: ParaView's "Warp By Vector" shows the deformed tissue) and each tet's label
// (cell data "label"). tetcut::io's writer carries no point data, hence this one; meshio reads
// it (tests/cli/simulate_frames.py).
#pragma once

#include <optional>
#include <string>

#include "tetcut/mechanics/tensor_mass.hpp"
#include "tetcut/mesh.hpp"

namespace tetcut::cli {

// Through a temporary file and a rename; the error with the path when it cannot.
std::optional<std::string> write_simulation_frame(const std::string& path, const TetMesh& mesh,
                                                  const mechanics::TensorMassModel& model);

}  // namespace tetcut::cli
