// The only place the checker reads the engine's own records (EngineRecordsView): to compare them
// with what it recomputed from the tets. I2 (neighbours across faces) and I8 (vertex->tet
// references, boundary counts, counts), for the full and the local level alike.
#pragma once

#include <array>
#include <cstdint>
#include <span>

#include "report_builder.hpp"
#include "tetcut/raw_mesh_view.hpp"

namespace tetcut::invariants::detail {

using RawTet = std::array<std::uint32_t, 4>;

// A face of a tet as the engine names it: the face opposite local vertex `face`.
struct TetFace {
  std::uint32_t tet = kNoRawRef;
  std::uint8_t face = 0;

  [[nodiscard]] bool valid() const { return tet != kNoRawRef; }
  bool operator==(const TetFace&) const = default;
};

// The view's engine records, or null when it has none. Records whose arrays do not match the
// tets and vertices in size are reported (I8) and not used.
const EngineRecordsView* usable_records(const RawMeshView& mesh, ReportBuilder& report);

// I2 on the face {v, a, b}: `faces` are the tets that have it, each with the local face it is
// (one: a boundary face, the engine must give no neighbour; two: the engine must pair them,
// reciprocally; more is I3, not compared).
void compare_face(const EngineRecordsView& engine, std::span<const TetFace> faces, std::uint32_t v,
                  std::uint32_t a, std::uint32_t b, ReportBuilder& report);

// I8 at vertex v, used by some live tet: the engine's boundary face count and incident tet.
void compare_vertex(const EngineRecordsView& engine, std::span<const RawTet> tets, std::uint32_t v,
                    std::uint32_t boundary_faces, ReportBuilder& report);

// I8 at vertex v, in no live tet: the engine must not keep it live or on the boundary.
void compare_unused_vertex(const EngineRecordsView& engine, std::uint32_t v, ReportBuilder& report);

// I8: the engine's counts against the checker's (`vertex_ids`: the number of vertex ids, which
// is also the number of attribute rows).
void compare_counts(const EngineRecordsView& engine, std::uint64_t live_tets, std::uint64_t live_vertices,
                    std::uint64_t vertex_ids, ReportBuilder& report);

}  // namespace tetcut::invariants::detail
