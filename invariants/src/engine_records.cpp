#include "engine_records.hpp"

#include <string>

namespace tetcut::invariants::detail {
namespace {

// Out of range reads as "no record": a mismatch to report, never a read past the arrays.
TetFace neighbour(const EngineRecordsView& engine, const TetFace& from) {
  if (from.tet >= engine.neighbours.size()) return {};
  const std::uint32_t packed = engine.neighbours[from.tet][from.face];
  if (packed == kNoRawRef) return {};
  return {packed >> 2, static_cast<std::uint8_t>(packed & 3u)};
}

std::uint32_t incident_tet(const EngineRecordsView& engine, std::uint32_t v) {
  return v < engine.vertex_tet.size() ? engine.vertex_tet[v] : kNoRawRef;
}

std::uint32_t boundary_count(const EngineRecordsView& engine, std::uint32_t v) {
  return v < engine.boundary_faces.size() ? engine.boundary_faces[v] : 0;
}

std::string describe(const TetFace& f) {
  return f.valid() ? "tet " + str(f.tet) + " face " + str(f.face) : std::string("the boundary");
}

std::string face_name(std::uint32_t v, std::uint32_t a, std::uint32_t b) {
  return "face (" + str(v) + ", " + str(a) + ", " + str(b) + ")";
}

}  // namespace

const EngineRecordsView* usable_records(const RawMeshView& mesh, ReportBuilder& report) {
  if (!mesh.engine) return nullptr;
  const EngineRecordsView& engine = *mesh.engine;
  const std::size_t nt = mesh.tets.size(), nv = mesh.positions.size();
  if (engine.neighbours.size() == nt && engine.vertex_tet.size() == nv && engine.boundary_faces.size() == nv)
    return &engine;
  report.add(Invariant::kI8Bookkeeping, {}, {}, [&] {
    return "the engine's records have " + str(engine.neighbours.size()) + " neighbour rows for " + str(nt) +
           " tets and " + str(engine.vertex_tet.size()) + " incident tets, " + str(engine.boundary_faces.size()) +
           " boundary counts for " + str(nv) + " vertices; not compared";
  });
  return nullptr;
}

void compare_face(const EngineRecordsView& engine, std::span<const TetFace> faces, std::uint32_t v,
                  std::uint32_t a, std::uint32_t b, ReportBuilder& report) {
  if (faces.size() == 1) {
    const TetFace got = neighbour(engine, faces[0]);
    if (!got.valid()) return;
    report.add(Invariant::kI2Adjacency, {faces[0].tet, got.tet}, {v, a, b}, [&] {
      return face_name(v, a, b) + " of tet " + str(faces[0].tet) +
             " belongs to no other tet, but the engine gives it neighbour " + describe(got);
    });
  } else if (faces.size() == 2) {
    for (int side = 0; side < 2; ++side) {
      const TetFace& from = faces[side];
      const TetFace& want = faces[1 - side];
      const TetFace got = neighbour(engine, from);
      if (got == want) continue;
      report.add(Invariant::kI2Adjacency, {faces[0].tet, faces[1].tet}, {v, a, b}, [&] {
        return face_name(v, a, b) + " is shared by tets " + str(faces[0].tet) + " and " + str(faces[1].tet) +
               ", but the engine's neighbour of tet " + str(from.tet) + " there is " + describe(got) +
               " instead of " + describe(want);
      });
      return;  // one offence per face
    }
  }
}

void compare_vertex(const EngineRecordsView& engine, std::span<const RawTet> tets, std::uint32_t v,
                    std::uint32_t boundary_faces, ReportBuilder& report) {
  const std::uint32_t claimed = boundary_count(engine, v);
  if (claimed != boundary_faces) {
    report.add(Invariant::kI8Bookkeeping, {}, {v}, [&] {
      return "vertex " + str(v) + ": the engine counts " + str(claimed) + " boundary faces, the tets give " +
             str(boundary_faces);
    });
  }
  const std::uint32_t seed = incident_tet(engine, v);
  bool seed_ok = seed < tets.size();
  if (seed_ok) {
    const RawTet& q = tets[seed];
    seed_ok = q[0] != kDeadTetMarker && (q[0] == v || q[1] == v || q[2] == v || q[3] == v);
  }
  if (!seed_ok) {
    report.add(Invariant::kI8Bookkeeping, {seed}, {v}, [&] {
      return "vertex " + str(v) + ": the engine's incident tet " +
             (seed != kNoRawRef ? str(seed) : std::string("(none)")) + " is not a live tet containing it";
    });
  }
}

void compare_unused_vertex(const EngineRecordsView& engine, std::uint32_t v, ReportBuilder& report) {
  const std::uint32_t seed = incident_tet(engine, v);
  const std::uint32_t boundary = boundary_count(engine, v);
  if (seed == kNoRawRef && boundary == 0) return;
  report.add(Invariant::kI8Bookkeeping, {}, {v}, [&] {
    return "vertex " + str(v) + " is in no live tet, but the engine keeps it live (incident tet " +
           (seed != kNoRawRef ? str(seed) : std::string("none")) + ", " + str(boundary) + " boundary faces)";
  });
}

void compare_counts(const EngineRecordsView& engine, std::uint64_t live_tets, std::uint64_t live_vertices,
                    std::uint64_t vertex_ids, ReportBuilder& report) {
  auto compare = [&](const char* what, std::uint64_t claimed, std::uint64_t actual) {
    if (claimed == actual) return;
    report.add(Invariant::kI8Bookkeeping, {}, {}, [&] {
      return std::string("the engine's ") + what + " is " + str(claimed) + ", the checker counts " + str(actual);
    });
  };
  compare("tet count", engine.live_tets, live_tets);
  compare("vertex count", engine.live_vertices, live_vertices);
  compare("attribute array size", engine.attribute_rows, vertex_ids);
}

}  // namespace tetcut::invariants::detail
