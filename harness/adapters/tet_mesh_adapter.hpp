// What the adapters that keep their mesh in a tetcut::TetMesh share (tetcut's own, and the
// remeshing peers', which use it for adjacency and rings between cuts): building it from
// engine.h's arrays, giving it back as arrays with its tombstones, the geometry of the tool, and
// for the peers, whose whole state is the mesh, every table entry but their cut and removal.
// Header-only: each adapter is a module of its own.
#pragma once

#include <tetcut/harness/engine.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "tetcut/mesh.hpp"
#include "tetcut/mesh_builder.hpp"

namespace tetcut::adapters {

// The mesh create() was given, built and validated; none, with the builder's first problem (or
// the exception) written into `error`, when it cannot be.
inline std::optional<TetMesh> build_from(const tetcut_engine_mesh* input, char* error, std::size_t error_size) {
  try {
    RawMesh raw;
    raw.positions.resize(input->point_count);
    for (std::uint32_t v = 0; v < input->point_count; ++v) {
      raw.positions[v] = {input->points[3 * v], input->points[3 * v + 1], input->points[3 * v + 2]};
    }
    raw.tets.resize(input->tet_count);
    for (std::uint32_t t = 0; t < input->tet_count; ++t) {
      for (int i = 0; i < 4; ++i) raw.tets[t][i] = input->tets[4 * t + i];
    }
    BuildResult built = build_mesh(raw);
    if (!built.ok()) {
      std::snprintf(error, error_size, "%s", built.problems.front().message.c_str());
      return std::nullopt;
    }
    return std::move(*built.mesh);
  } catch (const std::exception& failure) {
    std::snprintf(error, error_size, "%s", failure.what());
    return std::nullopt;
  }
}

// The mesh as engine.h's arrays, tombstones kept (ids stable), in buffers the adapter owns until
// its next call.
inline void export_mesh(const TetMesh& mesh, std::vector<double>& points, std::vector<std::uint32_t>& tets,
                        tetcut_engine_mesh* out) {
  const RawMeshView view = mesh.raw_view();
  points.clear();
  for (const Vec3& p : view.positions) points.insert(points.end(), {p.x, p.y, p.z});
  tets.clear();
  for (const auto& t : view.tets) tets.insert(tets.end(), t.begin(), t.end());
  *out = {points.data(), static_cast<std::uint32_t>(view.positions.size()), tets.data(),
          static_cast<std::uint32_t>(view.tets.size())};
}

inline Vec3 centroid(const TetMesh& mesh, TetId t) {
  const TetMesh::TetVerts v = mesh.tet(t);
  const auto p = mesh.positions();
  return 0.25 * (p[v[0].value] + p[v[1].value] + p[v[2].value] + p[v[3].value]);
}

inline double squared_distance_to_segment(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double length2 = dot(ab, ab);
  const double t = length2 > 0 ? std::clamp(dot(p - a, ab) / length2, 0.0, 1.0) : 0.0;
  const Vec3 d = p - (a + t * ab);
  return dot(d, d);
}

// The live tets that may meet the tool (every point within `radius` of the segment a-b): those
// whose bounding sphere about the centroid does, in id order. A scan of the mesh: the remeshing
// peers' cuts cost milliseconds, beside which it is nothing.
inline std::vector<TetId> tets_meeting_tool(const TetMesh& mesh, const Vec3& a, const Vec3& b, double radius) {
  const auto positions = mesh.positions();
  std::vector<TetId> out;
  for (std::uint32_t i = 0; i < mesh.tet_capacity(); ++i) {
    const TetId t{i};
    if (!mesh.is_live(t)) continue;
    const Vec3 c = centroid(mesh, t);
    double reach2 = 0;
    for (VertId v : mesh.tet(t)) reach2 = std::max(reach2, dot(positions[v.value] - c, positions[v.value] - c));
    const double reach = radius + std::sqrt(reach2);
    if (squared_distance_to_segment(c, a, b) <= reach * reach) out.push_back(t);
  }
  return out;
}

// The tets among `tets` whose centroid lies within `radius` of the segment a-b: what a peer
// removes of the tets its remeshing made.
inline std::vector<TetId> centroids_in_tool(const TetMesh& mesh, std::span<const TetId> tets, const Vec3& a, const Vec3& b,
                                            double radius) {
  std::vector<TetId> out;
  for (TetId t : tets)
    if (squared_distance_to_segment(centroid(mesh, t), a, b) <= radius * radius) out.push_back(t);
  return out;
}

// The whole state of an adapter that keeps its mesh in a TetMesh and has no change log.
struct TetMeshEngine {
  TetMesh mesh;
  std::vector<double> points;       // mesh()'s arrays, valid until the next call
  std::vector<std::uint32_t> tets;
  std::string error;                // last_error()
};

// engine.h's table for such an adapter, named `name` (version `version`): it cuts with
// `Cut(engine, a, b, diameter)` (a ball is the capsule with a == b; an exception is
// TETCUT_ENGINE_ERROR with its message, the mesh as it was) and removes a live tet with
// `Remove(engine, tet)` (a dead one is refused here).
template <int (*Cut)(TetMeshEngine&, const Vec3&, const Vec3&, double), int (*Remove)(TetMeshEngine&, TetId)>
struct TetMeshEntries {
  static TetMeshEngine& of(tetcut_engine* engine) { return *reinterpret_cast<TetMeshEngine*>(engine); }
  static tetcut_engine* create(const tetcut_engine_mesh* input, char* error, std::size_t error_size) {
    std::optional<TetMesh> mesh = build_from(input, error, error_size);
    if (!mesh) return nullptr;
    auto e = std::make_unique<TetMeshEngine>();
    e->mesh = std::move(*mesh);
    return reinterpret_cast<tetcut_engine*>(e.release());
  }
  static void destroy(tetcut_engine* engine) { delete &of(engine); }
  static int remove_tet(tetcut_engine* engine, std::uint32_t tet) {
    TetMeshEngine& e = of(engine);
    return e.mesh.is_live(TetId{tet}) ? Remove(e, TetId{tet}) : TETCUT_ENGINE_REFUSED;
  }
  static int cut_capsule(tetcut_engine* engine, const double* a, const double* b, double diameter) {
    TetMeshEngine& e = of(engine);
    try {
      return Cut(e, {a[0], a[1], a[2]}, {b[0], b[1], b[2]}, diameter);
    } catch (const std::exception& failure) {
      e.error = failure.what();
      return TETCUT_ENGINE_ERROR;
    }
  }
  static int cut_ball(tetcut_engine* engine, const double* centre, double diameter) {
    return cut_capsule(engine, centre, centre, diameter);
  }
  static int mesh(tetcut_engine* engine, tetcut_engine_mesh* out) {
    TetMeshEngine& e = of(engine);
    export_mesh(e.mesh, e.points, e.tets, out);
    return TETCUT_ENGINE_OK;
  }
  static const char* last_error(tetcut_engine* engine) { return of(engine).error.c_str(); }
  static constexpr tetcut_engine_api api(const char* name, const char* version) {
    return {TETCUT_ENGINE_ABI_VERSION, TETCUT_ENGINE_CAPSULE, name,       version, create, destroy, remove_tet,
            cut_ball,                  cut_capsule,           mesh,       nullptr, last_error};
  }
};

}  // namespace tetcut::adapters
