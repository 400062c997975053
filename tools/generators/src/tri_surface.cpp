#include "tetcut/generators/tri_surface.hpp"

#include <algorithm>
#include <utility>

namespace tetcut::generators {

std::optional<std::string> closed_surface_problem(const TriSurface& surface) {
  if (surface.triangles.size() < 4) return "a closed surface needs at least 4 triangles";
  for (std::size_t i = 0; i < surface.positions.size(); ++i)
    if (!is_finite(surface.positions[i]))
      return "vertex " + std::to_string(i) + " has a non-finite coordinate";
  const auto nv = surface.positions.size();
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
  edges.reserve(3 * surface.triangles.size());
  for (std::size_t t = 0; t < surface.triangles.size(); ++t) {
    const auto& tri = surface.triangles[t];
    for (int k = 0; k < 3; ++k) {
      if (tri[k] >= nv)
        return "triangle " + std::to_string(t) + " references vertex " + std::to_string(tri[k]) +
               " of " + std::to_string(nv);
    }
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2])
      return "triangle " + std::to_string(t) + " repeats a vertex";
    for (int k = 0; k < 3; ++k) {
      const auto a = tri[k], b = tri[(k + 1) % 3];
      edges.emplace_back(std::min(a, b), std::max(a, b));
    }
  }
  std::sort(edges.begin(), edges.end());
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    while (j < edges.size() && edges[j] == edges[i]) ++j;
    if (j - i != 2) {
      return "edge (" + std::to_string(edges[i].first) + ", " + std::to_string(edges[i].second) +
             ") belongs to " + std::to_string(j - i) +
             " triangles, not 2: the surface is not closed and manifold";
    }
    i = j;
  }
  return std::nullopt;
}

}  // namespace tetcut::generators
