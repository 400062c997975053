#include "neighbourhood.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <span>

namespace tetcut::peers {
namespace {

void sort_unique(std::vector<TetId>& tets) {
  std::sort(tets.begin(), tets.end());
  tets.erase(std::unique(tets.begin(), tets.end()), tets.end());
}

// Adds the whole shell of each vertex to `part`.
void add_shells(const TetMesh& mesh, const std::vector<VertId>& vertices, std::vector<TetId>& part) {
  std::vector<TetId> shell;
  for (VertId v : vertices) {
    mesh.vertex_shell(v, shell);
    part.insert(part.end(), shell.begin(), shell.end());
  }
  sort_unique(part);
}

std::vector<VertId> vertices_of(const TetMesh& mesh, const std::vector<TetId>& tets) {
  std::vector<VertId> out;
  for (TetId t : tets)
    for (VertId v : mesh.tet(t)) out.push_back(v);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

// One edge of a boundary vertex's link: the boundary face (vertex, a, b) seen from the vertex.
struct LinkEdge {
  VertId vertex, a, b;
};

// True when the link edges (all of one vertex) form a single cycle: every link vertex in exactly
// two of them (each boundary edge in exactly two boundary faces) and all of them connected (one
// fan around the vertex, not two touching at it).
bool is_one_cycle(std::span<const LinkEdge> link) {
  std::vector<VertId> ends;
  for (const LinkEdge& e : link) {
    ends.push_back(e.a);
    ends.push_back(e.b);
  }
  std::sort(ends.begin(), ends.end());
  for (std::size_t i = 0; i < ends.size(); i += 2) {
    if (ends[i] != ends[i + 1]) return false;                         // an end once
    if (i + 2 < ends.size() && ends[i + 2] == ends[i]) return false;  // an end three times or more
  }
  // Every end twice: the edges form disjoint cycles. Walk the one through link[0], count its edges.
  std::size_t walked = 1, came_by = 0;
  VertId at = link[0].b;
  while (at != link[0].a) {
    std::size_t next = 0;
    while (next == came_by || (link[next].a != at && link[next].b != at)) ++next;  // exists: `at` is an end twice
    at = link[next].a == at ? link[next].b : link[next].a;
    came_by = next;
    ++walked;
  }
  return walked == link.size();
}

// The vertices around which the boundary of `part` (marked in `in_part`) is not a 2-manifold.
std::vector<VertId> offending_vertices(const TetMesh& mesh, const std::vector<TetId>& part,
                                       const std::vector<std::uint8_t>& in_part) {
  std::vector<LinkEdge> link;
  for (TetId t : part)
    for (int f = 0; f < 4; ++f) {
      const FaceRef across = mesh.neighbour(t, f);
      if (across.valid() && in_part[across.tet.value]) continue;
      std::array<VertId, 3> face;
      for (int i = 0, k = 0; i < 4; ++i)
        if (i != f) face[static_cast<std::size_t>(k++)] = mesh.vertex(t, i);  // face f: the vertices but f
      link.push_back({face[0], face[1], face[2]});
      link.push_back({face[1], face[0], face[2]});
      link.push_back({face[2], face[0], face[1]});
    }
  std::sort(link.begin(), link.end(), [](const LinkEdge& x, const LinkEdge& y) { return x.vertex < y.vertex; });
  std::vector<VertId> out;
  for (std::size_t i = 0; i < link.size();) {
    std::size_t j = i;
    while (j < link.size() && link[j].vertex == link[i].vertex) ++j;
    if (!is_one_cycle(std::span<const LinkEdge>(link).subspan(i, j - i))) out.push_back(link[i].vertex);
    i = j;
  }
  return out;
}

}  // namespace

std::optional<std::vector<TetId>> manifold_neighbourhood(const TetMesh& mesh, const std::vector<TetId>& selection,
                                                         int rings, int max_repairs) {
  std::vector<TetId> part;
  if (rings < 0) {
    for (std::uint32_t t = 0; t < mesh.tet_capacity(); ++t)
      if (mesh.is_live(TetId{t})) part.push_back(TetId{t});
    return part;
  }
  part = selection;
  sort_unique(part);
  for (int ring = 0; ring < rings; ++ring) add_shells(mesh, vertices_of(mesh, part), part);

  std::vector<std::uint8_t> in_part(mesh.tet_capacity(), 0);
  for (int round = 0; round <= max_repairs; ++round) {
    for (TetId t : part) in_part[t.value] = 1;
    const std::vector<VertId> offending = offending_vertices(mesh, part, in_part);
    for (TetId t : part) in_part[t.value] = 0;
    if (offending.empty()) return part;
    add_shells(mesh, offending, part);
  }
  return std::nullopt;
}

}  // namespace tetcut::peers
