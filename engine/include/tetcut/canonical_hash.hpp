// A hash of a mesh that does not depend on how vertices and tets are numbered: two meshes with
// the same tets over the same vertex positions hash alike, whatever their ids (design:
// determinism; printed by every command that changes a mesh).
#pragma once

#include <cstdint>
#include <string>

#include "tetcut/mesh.hpp"
#include "tetcut/raw_mesh.hpp"

namespace tetcut {

// Each tet is keyed by the bit patterns of its four positions in sorted order plus the parity
// of that sort (so orientation counts); the tet keys are sorted and folded. O(#T log #T).
std::uint64_t canonical_hash(const RawMesh& mesh);
std::uint64_t canonical_hash(const TetMesh& mesh);

// 16 lowercase hex digits.
std::string hash_to_hex(std::uint64_t hash);

}  // namespace tetcut
