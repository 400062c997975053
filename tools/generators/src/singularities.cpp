#include "tetcut/generators/singularities.hpp"

#include <algorithm>
#include <numeric>
#include <utility>

namespace tetcut::generators {
namespace {

// Union-find over the positions of a shell's tets.
class DisjointSets {
 public:
  explicit DisjointSets(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0u); }
  std::uint32_t find(std::uint32_t x) {
    while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
    return x;
  }
  void unite(std::uint32_t a, std::uint32_t b) {
    a = find(a);
    b = find(b);
    if (a != b) parent_[std::max(a, b)] = std::min(a, b);  // the smallest position is the root
  }

 private:
  std::vector<std::uint32_t> parent_;
};

// Groups `shell` (increasing tet ids) by the union-find roots, components ordered by first tet.
std::vector<std::vector<std::uint32_t>> components_of(const std::vector<std::uint32_t>& shell,
                                                      DisjointSets& sets) {
  std::vector<std::vector<std::uint32_t>> comps;
  std::vector<std::uint32_t> comp_of_root(shell.size(), 0xFFFFFFFFu);
  for (std::uint32_t i = 0; i < shell.size(); ++i) {
    const auto r = sets.find(i);
    if (comp_of_root[r] == 0xFFFFFFFFu) {
      comp_of_root[r] = static_cast<std::uint32_t>(comps.size());
      comps.emplace_back();
    }
    comps[comp_of_root[r]].push_back(shell[i]);
  }
  return comps;
}

}  // namespace

Singularities find_singularities(const RawMesh& mesh) {
  Singularities out;
  const auto nv = mesh.positions.size();
  const auto nt = mesh.tets.size();

  // Vertex -> tets by counting sort: each list in increasing tet order.
  std::vector<std::uint32_t> first(nv + 1, 0);
  for (const auto& t : mesh.tets)
    for (auto v : t) ++first[v + 1];
  std::partial_sum(first.begin(), first.end(), first.begin());
  std::vector<std::uint32_t> incident(first[nv]);
  {
    std::vector<std::uint32_t> fill(first.begin(), first.end() - 1);
    for (std::uint32_t t = 0; t < nt; ++t)
      for (auto v : mesh.tets[t]) incident[fill[v]++] = t;
  }

  // Vertex shells: components through the faces containing v; link Euler characteristic.
  struct FaceEntry {
    std::uint32_t a, b, pos;
    bool operator<(const FaceEntry& o) const {
      return a != o.a ? a < o.a : b != o.b ? b < o.b : pos < o.pos;
    }
  };
  std::vector<FaceEntry> faces;
  std::vector<std::uint32_t> neighbours;
  std::vector<std::uint32_t> shell;
  for (std::uint32_t v = 0; v < nv; ++v) {
    if (first[v] == first[v + 1]) continue;
    shell.assign(incident.begin() + first[v], incident.begin() + first[v + 1]);
    faces.clear();
    neighbours.clear();
    for (std::uint32_t pos = 0; pos < shell.size(); ++pos) {
      std::uint32_t others[3];
      int n = 0;
      for (auto w : mesh.tets[shell[pos]])
        if (w != v) others[n++] = w;
      for (int k = 0; k < 3; ++k) {
        neighbours.push_back(others[k]);
        const auto a = others[k], b = others[(k + 1) % 3];
        faces.push_back({std::min(a, b), std::max(a, b), pos});
      }
    }
    std::sort(faces.begin(), faces.end());
    std::sort(neighbours.begin(), neighbours.end());
    const auto link_vertices = std::unique(neighbours.begin(), neighbours.end()) - neighbours.begin();
    DisjointSets sets(shell.size());
    std::int64_t link_edges = 0;
    bool boundary = false;
    for (std::size_t i = 0; i < faces.size();) {
      std::size_t j = i + 1;
      while (j < faces.size() && faces[j].a == faces[i].a && faces[j].b == faces[i].b) {
        sets.unite(faces[i].pos, faces[j].pos);
        ++j;
      }
      if (j - i == 1) boundary = true;
      ++link_edges;
      i = j;
    }
    const std::int64_t euler =
        static_cast<std::int64_t>(link_vertices) - link_edges + static_cast<std::int64_t>(shell.size());
    auto comps = components_of(shell, sets);
    if (comps.size() > 1 || euler != (boundary ? 1 : 2)) {
      out.vertices.push_back({v, std::move(comps), boundary, euler});
    }
  }

  // Edge shells: components through the faces containing the edge (same third vertex).
  struct EdgeEntry {
    std::uint32_t a, b, tet;
    bool operator<(const EdgeEntry& o) const {
      return a != o.a ? a < o.a : b != o.b ? b < o.b : tet < o.tet;
    }
  };
  std::vector<EdgeEntry> edges;
  edges.reserve(6 * nt);
  for (std::uint32_t t = 0; t < nt; ++t) {
    const auto& q = mesh.tets[t];
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) edges.push_back({std::min(q[i], q[j]), std::max(q[i], q[j]), t});
  }
  std::sort(edges.begin(), edges.end());
  std::vector<std::pair<std::uint32_t, std::uint32_t>> thirds;  // (third vertex, position)
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    while (j < edges.size() && edges[j].a == edges[i].a && edges[j].b == edges[i].b) ++j;
    if (j - i > 1) {
      shell.clear();
      thirds.clear();
      for (std::size_t k = i; k < j; ++k) {
        const auto pos = static_cast<std::uint32_t>(shell.size());
        shell.push_back(edges[k].tet);
        for (auto w : mesh.tets[edges[k].tet])
          if (w != edges[i].a && w != edges[i].b) thirds.emplace_back(w, pos);
      }
      std::sort(thirds.begin(), thirds.end());
      DisjointSets sets(shell.size());
      for (std::size_t k = 1; k < thirds.size(); ++k)
        if (thirds[k].first == thirds[k - 1].first) sets.unite(thirds[k].second, thirds[k - 1].second);
      auto comps = components_of(shell, sets);
      if (comps.size() > 1) out.edges.push_back({edges[i].a, edges[i].b, std::move(comps)});
    }
    i = j;
  }
  return out;
}

}  // namespace tetcut::generators
