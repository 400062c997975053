// Building a TetMesh from a vertex array and a #T by 4 tet array, validating everything first.
//
// Every problem is reported with the elements involved, not only the first: a user fixing a mesh
// exported from another tool wants the whole list. Cost O(#T log #T) at worst (vertex-to-tet
// incidence by counting sort, face matching within the smallest vertex's incidence list).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "tetcut/mesh.hpp"
#include "tetcut/raw_mesh.hpp"

namespace tetcut {

enum class BuildProblemKind : std::uint8_t {
  kNonFinitePosition,  // a vertex coordinate is NaN or infinite
  kDanglingReference,  // a tet references a vertex index >= #V
  kRepeatedVertex,     // a tet lists the same vertex twice
  kDuplicateTet,       // two tets have the same four vertices
  kOverSharedFace,     // a face belongs to more than two tets
  kInvertedTet,        // negative orientation (fixable with reorient_inverted)
  kFlatTet,            // zero volume by the exact predicate
  kSingularVertex,     // vertex shell not one face-connected component, or link not disk/sphere
  kSingularEdge,       // edge shell not one face-connected component
  kTooLarge,           // more tets than packed references address
};

const char* to_string(BuildProblemKind kind);

struct BuildProblem {
  BuildProblemKind kind;
  std::vector<std::uint32_t> tets;      // input tet indices involved
  std::vector<std::uint32_t> vertices;  // input vertex indices involved
  std::string message;                  // one line, for people
};

struct BuildOptions {
  // Inverted tets are an error unless this is set; then they are reoriented (two vertices
  // swapped) and counted in BuildResult::reoriented.
  bool reorient_inverted = false;
  // Singular vertices and edges are an error unless this is cleared (repair needs to load such
  // meshes; the cutting operations assume a manifold).
  bool require_manifold = true;
};

struct BuildResult {
  std::optional<TetMesh> mesh;        // set iff problems is empty
  std::vector<BuildProblem> problems;
  std::uint32_t reoriented = 0;

  [[nodiscard]] bool ok() const { return mesh.has_value(); }
};

BuildResult build_mesh(const RawMesh& raw, const BuildOptions& options = {});

}  // namespace tetcut
