// The force the tissue exerts on the tool, what a haptic loop renders (paper section 4: the
// haptic loop returns the force from the deformable model at the tool's position).
//
// The tool holds the vertices within it displaced; the tissue pushes back on it by the elastic
// forces at those vertices, -K u, summed. So the reaction is that sum: a tool pressed into the
// tissue in +x feels a force in -x. Vertices count where they are now (the deformed position,
// rest + displacement), as the tool is in the world. Summed over every vertex of the tissue,
// the elastic forces cancel (each tet's forces sum to zero), which the tests hold it to.
#pragma once

#include <vector>

#include "tetcut/mechanics/tensor_mass.hpp"
#include "tetcut/mesh.hpp"
#include "tetcut/vec3.hpp"

namespace tetcut::mechanics {

// In newtons. The tool is the capsule of `radius` around the segment a-b in mesh units (a ball
// when a == b). O(#V + #E): one product K u. `forces` is scratch (sized to the vertex capacity),
// kept by the caller so that a loop allocates nothing after its first call.
Vec3 reaction_force(const TetMesh& mesh, const TensorMassModel& model, const Vec3& a, const Vec3& b, double radius,
                    std::vector<Vec3>& forces);

}  // namespace tetcut::mechanics
