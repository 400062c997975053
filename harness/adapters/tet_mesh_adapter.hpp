// What the adapters that keep their mesh in a tetcut::TetMesh share (tetcut's own, and the
// remeshing peers', which use it for adjacency and rings between cuts): building it from
// engine.h's arrays, giving it back as arrays with its tombstones, and the geometry of the tool.
// Header-only: each adapter is a module of its own.
#pragma once

#include <tetcut/harness/engine.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <optional>
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

}  // namespace tetcut::adapters
