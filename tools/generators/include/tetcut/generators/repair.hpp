// Bringing a real, imperfect tet mesh into a state the engine accepts: conformal, positively
// oriented, 3-manifold (design: `tetcut repair`). The smallest change we know how to make:
// reorient inverted tets instead of removing them; around a singular edge keep the largest
// face-connected component of its shell; around a singular vertex keep the largest component and,
// if its link is still not a disk or a sphere (a pinched tunnel), the largest disk we can grow in
// the link; repeat until no singularity is left. Every change is reported with the input index of
// the tet it concerns.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "tetcut/raw_mesh.hpp"

namespace tetcut::generators {

enum class RepairAction : std::uint8_t {
  kReoriented,             // two vertices swapped: the tet was inverted
  kRemovedInvalid,         // repeated vertex, dangling index or non-finite position
  kRemovedFlat,            // zero volume by the exact predicate
  kRemovedDuplicate,       // same four vertices as an earlier tet
  kRemovedOverSharedFace,  // a third tet on one side of a face (overlap)
  kRemovedSingularEdge,    // outside the kept component of a singular edge's shell
  kRemovedSingularVertex,  // outside the kept disk of a singular vertex's link
};

const char* to_string(RepairAction action);

inline constexpr std::uint32_t kNoIndex = 0xFFFFFFFFu;

struct RepairChange {
  RepairAction action;
  std::uint32_t tet = kNoIndex;  // input tet index
  // The singular vertex (at_a), or the singular edge (at_a, at_b), in input vertex indices.
  std::uint32_t at_a = kNoIndex;
  std::uint32_t at_b = kNoIndex;
};

struct RepairReport {
  std::vector<RepairChange> changes;            // in the order they were made
  std::vector<std::uint32_t> dropped_vertices;  // input vertices no kept tet uses
  std::uint32_t singular_edges_fixed = 0;
  std::uint32_t singular_vertices_fixed = 0;
  std::uint32_t rounds = 0;  // singularity sweeps, the last one finding none

  [[nodiscard]] std::uint64_t count(RepairAction action) const;
  [[nodiscard]] std::uint64_t removed_tets() const;
  [[nodiscard]] bool unchanged() const { return changes.empty() && dropped_vertices.empty(); }
};

struct RepairResult {
  std::optional<RawMesh> mesh;  // set iff error is empty; kept vertices and tets in input order
  RepairReport report;          // filled in either case
  std::string error;

  [[nodiscard]] bool ok() const { return mesh.has_value(); }
};

RepairResult repair_mesh(const RawMesh& mesh);

}  // namespace tetcut::generators
