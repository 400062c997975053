// The meshes a sequence input starts from (its second value chooses one; its version byte,
// sequence_target.hpp, chooses the set): where they are found, read and built once per process.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "operations/mesh_edits.hpp"
#include "tetcut/mesh.hpp"

namespace tetcut::fuzz {

// The meshes an input chooses from with one value, per version.
inline constexpr std::array<std::string_view, 3> kBundledMeshes = {"cylinder.msh", "sheet.msh", "liver-coarse.msh"};
inline constexpr std::array<std::string_view, 3> kFuzzMeshes = {"cylinder-small.msh", "sheet-small.msh",
                                                                "liver-small.msh"};
inline constexpr std::size_t kSequenceMeshCount = 3;

struct BundledMesh {
  std::string path;        // absolute
  TetMesh mesh;
  Box box;
  double mean_edge = 1.0;
};

// The folder of the bundled meshes: $TETCUT_MESH_DIR when set, else corpus/meshes of the source
// tree the harness was built from, else tetcut_meshes/ next to the executable (OSS-Fuzz).
std::string sequence_mesh_dir();
// The folder of the small fuzz meshes: $TETCUT_FUZZ_MESH_DIR when set, else corpus/fuzz/meshes
// of the source tree, else tetcut_meshes/ next to the executable (OSS-Fuzz).
std::string fuzz_mesh_dir();
// Mesh `index` (mod kSequenceMeshCount) of input version `version`, read and built once per
// process, then copied per input. An unreadable or invalid mesh is a harness failure
// ("bundled-mesh").
const BundledMesh& sequence_mesh(std::uint8_t version, std::size_t index);

}  // namespace tetcut::fuzz
