// The only CGAL translation unit of the checker.
//
// CGAL_ALWAYS_ROUND_TO_NEAREST: CGAL's interval filters normally switch the FPU rounding mode,
// which valgrind does not emulate; with this they work in round-to-nearest (slightly slower,
// equally exact), so the checker also runs under valgrind.
#ifndef CGAL_ALWAYS_ROUND_TO_NEAREST
#define CGAL_ALWAYS_ROUND_TO_NEAREST
#endif

#include "boundary_self_intersection.hpp"

#include <algorithm>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>
#include <boost/iterator/function_output_iterator.hpp>

namespace tetcut::invariants::detail {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using SurfaceMesh = CGAL::Surface_mesh<Kernel::Point_3>;
using VertexIndex = SurfaceMesh::Vertex_index;
using FaceIndex = SurfaceMesh::Face_index;

}  // namespace

SelfIntersections find_boundary_self_intersections(std::span<const Vec3> positions,
                                                   std::span<const std::array<std::uint32_t, 3>> triangles,
                                                   std::size_t max_pairs) {
  SelfIntersections result;
  SurfaceMesh mesh;
  std::vector<VertexIndex> to_mesh(positions.size(), SurfaceMesh::null_vertex());
  for (const auto& tri : triangles) {
    std::array<VertexIndex, 3> corners;
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t v = tri[k];
      if (v >= positions.size()) {
        result.message = "a boundary triangle references vertex " + std::to_string(v) + " out of range";
        return result;
      }
      if (to_mesh[v] == SurfaceMesh::null_vertex()) {
        const Vec3& p = positions[v];
        to_mesh[v] = mesh.add_vertex(Kernel::Point_3(p.x, p.y, p.z));
      }
      corners[k] = to_mesh[v];
    }
    // Face i of the surface mesh is triangle i as long as every add_face succeeds.
    if (mesh.add_face(corners[0], corners[1], corners[2]) == SurfaceMesh::null_face()) {
      result.message = "the boundary triangles do not form an oriented 2-manifold surface";
      return result;
    }
  }
  result.tested = true;
  // All pairs, then sorted: the order in which CGAL's box intersection reports them is not
  // part of its contract, and reports must be deterministic.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  auto record = [&](const std::pair<FaceIndex, FaceIndex>& pair) {
    const auto a = static_cast<std::uint32_t>(pair.first.idx());
    const auto b = static_cast<std::uint32_t>(pair.second.idx());
    pairs.emplace_back(std::min(a, b), std::max(a, b));
  };
  CGAL::Polygon_mesh_processing::self_intersections(mesh, boost::make_function_output_iterator(record));
  std::sort(pairs.begin(), pairs.end());
  result.pair_count = pairs.size();
  pairs.resize(std::min(pairs.size(), max_pairs));
  result.first_pairs = std::move(pairs);
  return result;
}

}  // namespace tetcut::invariants::detail
