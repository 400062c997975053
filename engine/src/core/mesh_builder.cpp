#include "tetcut/mesh_builder.hpp"

#include <algorithm>
#include <numeric>
#include <string>

#include "core/mesh_internals.hpp"
#include "tetcut/detail/local_tables.hpp"
#include "tetcut/predicates.hpp"

namespace tetcut {

const char* to_string(BuildProblemKind kind) {
  switch (kind) {
    case BuildProblemKind::kNonFinitePosition: return "non-finite position";
    case BuildProblemKind::kDanglingReference: return "dangling vertex reference";
    case BuildProblemKind::kRepeatedVertex: return "repeated vertex in a tet";
    case BuildProblemKind::kDuplicateTet: return "duplicate tet";
    case BuildProblemKind::kOverSharedFace: return "face shared by more than two tets";
    case BuildProblemKind::kInvertedTet: return "inverted tet";
    case BuildProblemKind::kFlatTet: return "flat tet";
    case BuildProblemKind::kSingularVertex: return "singular vertex";
    case BuildProblemKind::kSingularEdge: return "singular edge";
    case BuildProblemKind::kTooLarge: return "mesh too large";
  }
  return "unknown problem";
}

// Validates the input, then fills a TetMesh's arrays in one pass (through detail::MeshInternals).
class MeshAssembler {
 public:
  MeshAssembler(const RawMesh& raw, const BuildOptions& options, BuildResult& result)
      : raw_(raw), options_(options), result_(result), tets_(raw.tets) {}

  void run();

 private:
  using Tet = std::array<std::uint32_t, 4>;

  void report(BuildProblemKind kind, std::vector<std::uint32_t> tets, std::vector<std::uint32_t> vertices,
              std::string message) {
    result_.problems.push_back({kind, std::move(tets), std::move(vertices), std::move(message)});
  }
  bool check_elements();
  void build_incidence();
  void find_duplicates();
  void match_faces();
  void check_vertex_shells();
  void check_edge_shells();
  std::uint32_t walk_edge_shell(std::uint32_t t, std::uint32_t a, std::uint32_t b);
  bool contains(std::uint32_t t, std::uint32_t v) const {
    const Tet& x = tets_[t];
    return x[0] == v || x[1] == v || x[2] == v || x[3] == v;
  }
  int local(std::uint32_t t, std::uint32_t v) const {
    for (int i = 0; i < 4; ++i)
      if (tets_[t][i] == v) return i;
    return -1;
  }
  std::span<const std::uint32_t> incident(std::uint32_t v) const {
    return {incidence_.data() + offsets_[v], incidence_.data() + offsets_[v + 1]};
  }
  TetMesh assemble();

  const RawMesh& raw_;
  const BuildOptions& options_;
  BuildResult& result_;
  std::vector<Tet> tets_;                     // possibly reoriented copy
  std::vector<std::uint8_t> excluded_;         // tets left out of topology (bad or duplicate)
  std::vector<std::uint32_t> offsets_;         // vertex -> incidence range (CSR)
  std::vector<std::uint32_t> incidence_;       // tets by vertex, ascending
  std::vector<std::array<std::uint32_t, 4>> adj_;
  std::vector<std::uint32_t> boundary_faces_;  // per vertex
  bool structural_problem_ = false;
};

bool MeshAssembler::check_elements() {
  const std::uint32_t nv = static_cast<std::uint32_t>(raw_.positions.size());
  if (raw_.tets.size() > kMaxTets) {
    report(BuildProblemKind::kTooLarge, {}, {},
           std::to_string(raw_.tets.size()) + " tets, at most " + std::to_string(kMaxTets) + " are addressable");
    return false;
  }
  for (std::uint32_t v = 0; v < nv; ++v)
    if (!is_finite(raw_.positions[v]))
      report(BuildProblemKind::kNonFinitePosition, {}, {v}, "vertex " + std::to_string(v) + " has a NaN or infinite coordinate");

  excluded_.assign(tets_.size(), 0);
  for (std::uint32_t t = 0; t < tets_.size(); ++t) {
    Tet& x = tets_[t];
    bool dangling = false;
    for (std::uint32_t v : x)
      if (v >= nv) {
        dangling = true;
        report(BuildProblemKind::kDanglingReference, {t}, {v},
               "tet " + std::to_string(t) + " references vertex " + std::to_string(v) + " but there are only " +
                   std::to_string(nv));
      }
    if (dangling) {
      excluded_[t] = 1;
      continue;
    }
    bool repeated = false;
    for (int i = 0; i < 4 && !repeated; ++i)
      for (int j = i + 1; j < 4; ++j)
        if (x[i] == x[j]) {
          repeated = true;
          report(BuildProblemKind::kRepeatedVertex, {t}, {x[i]},
                 "tet " + std::to_string(t) + " lists vertex " + std::to_string(x[i]) + " twice");
          break;
        }
    if (repeated) {
      excluded_[t] = 1;
      continue;
    }
    const auto& p = raw_.positions;
    if (!is_finite(p[x[0]]) || !is_finite(p[x[1]]) || !is_finite(p[x[2]]) || !is_finite(p[x[3]])) continue;
    const int sign = orientation(p[x[0]], p[x[1]], p[x[2]], p[x[3]]);
    if (sign == 0) {
      report(BuildProblemKind::kFlatTet, {t}, {x[0], x[1], x[2], x[3]}, "tet " + std::to_string(t) + " has zero volume");
    } else if (sign < 0) {
      if (options_.reorient_inverted) {
        std::swap(x[2], x[3]);
        ++result_.reoriented;
      } else {
        report(BuildProblemKind::kInvertedTet, {t}, {x[0], x[1], x[2], x[3]},
               "tet " + std::to_string(t) + " is negatively oriented (reorientation not requested)");
      }
    }
  }
  return true;
}

// Vertex -> tets by counting sort: O(#V + #T), tets in ascending order within each vertex.
void MeshAssembler::build_incidence() {
  const std::size_t nv = raw_.positions.size();
  offsets_.assign(nv + 1, 0);
  for (std::uint32_t t = 0; t < tets_.size(); ++t)
    if (!excluded_[t])
      for (std::uint32_t v : tets_[t]) ++offsets_[v + 1];
  std::partial_sum(offsets_.begin(), offsets_.end(), offsets_.begin());
  incidence_.resize(offsets_[nv]);
  std::vector<std::uint32_t> fill(offsets_.begin(), offsets_.end() - 1);
  for (std::uint32_t t = 0; t < tets_.size(); ++t)
    if (!excluded_[t])
      for (std::uint32_t v : tets_[t]) incidence_[fill[v]++] = t;
}

void MeshAssembler::find_duplicates() {
  auto sorted = [&](std::uint32_t t) {
    Tet s = tets_[t];
    std::sort(s.begin(), s.end());
    return s;
  };
  for (std::uint32_t t = 0; t < tets_.size(); ++t) {
    if (excluded_[t]) continue;
    const Tet key = sorted(t);
    // Only earlier tets in the incidence of the smallest vertex can be duplicates of t.
    for (std::uint32_t u : incident(key[0])) {
      if (u >= t) break;
      if (!excluded_[u] && sorted(u) == key) {
        report(BuildProblemKind::kDuplicateTet, {u, t}, {key[0], key[1], key[2], key[3]},
               "tets " + std::to_string(u) + " and " + std::to_string(t) + " have the same four vertices");
        excluded_[t] = 1;
        structural_problem_ = true;
        break;
      }
    }
  }
  if (structural_problem_) build_incidence();  // drop the duplicates from the incidence
}

// A face's partners are found in the incidence list of its least-shared vertex: no global hash
// table, and each interior face is matched once, from its lower-numbered tet.
void MeshAssembler::match_faces() {
  constexpr std::uint32_t kUnset = 0xFFFFFFFEu;
  adj_.assign(tets_.size(), {kUnset, kUnset, kUnset, kUnset});
  boundary_faces_.assign(raw_.positions.size(), 0);
  for (std::uint32_t t = 0; t < tets_.size(); ++t) {
    if (excluded_[t]) continue;
    for (int f = 0; f < 4; ++f) {
      if (adj_[t][f] != kUnset) continue;
      const std::uint32_t a = tets_[t][kFaceVerts[f][0]], b = tets_[t][kFaceVerts[f][1]], c = tets_[t][kFaceVerts[f][2]];
      std::uint32_t pivot = a;
      for (std::uint32_t v : {b, c})
        if (offsets_[v + 1] - offsets_[v] < offsets_[pivot + 1] - offsets_[pivot]) pivot = v;
      std::uint32_t partner = TetMesh::kNoNeighbour, partner_face = 0, sharing = 1;
      for (std::uint32_t u : incident(pivot)) {
        if (u == t || !contains(u, a) || !contains(u, b) || !contains(u, c)) continue;
        ++sharing;
        partner = u;
        for (int g = 0; g < 4; ++g)
          if (tets_[u][g] != a && tets_[u][g] != b && tets_[u][g] != c) partner_face = static_cast<std::uint32_t>(g);
      }
      if (sharing > 2) {
        std::vector<std::uint32_t> owners;
        for (std::uint32_t u : incident(pivot))
          if (contains(u, a) && contains(u, b) && contains(u, c)) owners.push_back(u);
        if (owners.front() == t)  // report each face once
          report(BuildProblemKind::kOverSharedFace, owners, {a, b, c},
                 "face (" + std::to_string(a) + ", " + std::to_string(b) + ", " + std::to_string(c) + ") belongs to " +
                     std::to_string(sharing) + " tets");
        structural_problem_ = true;
        adj_[t][f] = TetMesh::kNoNeighbour;
      } else if (sharing == 2) {
        adj_[t][f] = (partner << 2) | partner_face;
        adj_[partner][partner_face] = (t << 2) | static_cast<std::uint32_t>(f);
      } else {
        adj_[t][f] = TetMesh::kNoNeighbour;
        ++boundary_faces_[a];
        ++boundary_faces_[b];
        ++boundary_faces_[c];
      }
    }
  }
}

// Paper 2.1: the shell of a vertex must be one connected component. We also require its link to
// be a disk (surface vertex) or a sphere (inner vertex), which a connected shell alone does not
// guarantee (a tunnel pinched to a point). Given manifold edges, the link is a connected surface
// and its Euler characteristic E - F + T (edges, faces, tets at the vertex) is 1 exactly for a
// disk and 2 exactly for a sphere.
void MeshAssembler::check_vertex_shells() {
  std::vector<std::uint32_t> stamp(tets_.size(), 0xFFFFFFFFu), queue, others;
  for (std::uint32_t v = 0; v < raw_.positions.size(); ++v) {
    const auto shell = incident(v);
    if (shell.empty()) continue;
    std::uint32_t components = 0;
    for (std::uint32_t seed : shell) {
      if (stamp[seed] == v) continue;
      ++components;
      stamp[seed] = v;
      queue.assign(1, seed);
      while (!queue.empty()) {
        const std::uint32_t t = queue.back();
        queue.pop_back();
        const int lv = local(t, v);
        for (int f = 0; f < 4; ++f) {
          const std::uint32_t a = adj_[t][f];
          if (f == lv || a == TetMesh::kNoNeighbour) continue;
          if (stamp[a >> 2] != v) {
            stamp[a >> 2] = v;
            queue.push_back(a >> 2);
          }
        }
      }
    }
    if (components > 1) {
      report(BuildProblemKind::kSingularVertex, {shell.begin(), shell.end()}, {v},
             "the shell of vertex " + std::to_string(v) + " has " + std::to_string(components) + " components");
      continue;
    }
    others.clear();
    for (std::uint32_t t : shell)
      for (std::uint32_t w : tets_[t])
        if (w != v) others.push_back(w);
    std::sort(others.begin(), others.end());
    const auto edges = static_cast<long>(std::unique(others.begin(), others.end()) - others.begin());
    const auto tets = static_cast<long>(shell.size());
    const auto faces = (3 * tets + static_cast<long>(boundary_faces_[v])) / 2;
    const long euler = edges - faces + tets;
    const long expected = boundary_faces_[v] > 0 ? 1 : 2;
    if (euler != expected)
      report(BuildProblemKind::kSingularVertex, {shell.begin(), shell.end()}, {v},
             "the link of vertex " + std::to_string(v) + " has Euler characteristic " + std::to_string(euler) +
                 ", not " + std::to_string(expected) + " (" + (expected == 1 ? "disk" : "sphere") + ")");
  }
}

// Number of tets reached by rotating about edge (a, b) in both directions from tet t.
std::uint32_t MeshAssembler::walk_edge_shell(std::uint32_t t, std::uint32_t a, std::uint32_t b) {
  const std::uint8_t e = kEdgeIndex[local(t, a)][local(t, b)];
  std::uint32_t reached = 1;
  for (int dir = 0; dir < 2; ++dir) {
    std::uint32_t cur = t;
    int face = kEdgeFaces[e][dir];
    for (std::size_t guard = 0; guard <= tets_.size(); ++guard) {
      const std::uint32_t adj = adj_[cur][face];
      if (adj == TetMesh::kNoNeighbour) break;
      cur = adj >> 2;
      if (cur == t) return reached;  // closed ring: counted once
      ++reached;
      const std::uint8_t ce = kEdgeIndex[local(cur, a)][local(cur, b)];
      face = kEdgeFaces[ce][0] == static_cast<int>(adj & 3u) ? kEdgeFaces[ce][1] : kEdgeFaces[ce][0];
    }
  }
  return reached;
}

void MeshAssembler::check_edge_shells() {
  std::vector<std::uint32_t> others;
  for (std::uint32_t a = 0; a < raw_.positions.size(); ++a) {
    const auto shell = incident(a);
    others.clear();
    for (std::uint32_t t : shell)
      for (std::uint32_t w : tets_[t])
        if (w > a) others.push_back(w);
    std::sort(others.begin(), others.end());
    others.erase(std::unique(others.begin(), others.end()), others.end());
    for (std::uint32_t b : others) {
      std::uint32_t around = 0, first = 0;
      for (std::uint32_t t : shell)
        if (contains(t, b)) {
          if (around++ == 0) first = t;
        }
      if (walk_edge_shell(first, a, b) != around) {
        std::vector<std::uint32_t> tets;
        for (std::uint32_t t : shell)
          if (contains(t, b)) tets.push_back(t);
        report(BuildProblemKind::kSingularEdge, std::move(tets), {a, b},
               "the shell of edge (" + std::to_string(a) + ", " + std::to_string(b) + ") is not one connected component");
      }
    }
  }
}

TetMesh MeshAssembler::assemble() {
  using M = detail::MeshInternals;
  TetMesh mesh;
  const std::uint32_t nv = static_cast<std::uint32_t>(raw_.positions.size());
  const auto tets = static_cast<std::uint32_t>(tets_.size());
  // Moved, not copied: the build's peak is the session's (bench/session_memory.cpp).
  M::tet_verts(mesh) = std::move(tets_);
  M::adjacency(mesh) = std::move(adj_);
  M::positions(mesh) = raw_.positions;
  auto& vert_tet = M::vertex_tet(mesh);
  vert_tet.assign(nv, kNoTet);
  M::boundary_faces(mesh) = std::move(boundary_faces_);
  auto& free_next = M::free_vert_next(mesh);
  free_next.assign(nv, kNoVert);
  M::live_tets(mesh) = tets;
  for (std::uint32_t v = 0; v < nv; ++v) {
    if (offsets_[v] != offsets_[v + 1]) {
      vert_tet[v] = TetId{incidence_[offsets_[v]]};
      ++M::live_vertices(mesh);
    }
  }
  // Unreferenced input vertices keep their ids as tombstones, reusable by later splits;
  // pushed in descending order so that the lowest id is reused first.
  for (std::uint32_t v = nv; v-- > 0;)
    if (!vert_tet[v].valid()) {
      free_next[v] = M::free_vert_head(mesh);
      M::free_vert_head(mesh) = VertId{v};
    }
  M::attributes(mesh).resize(nv);
  return mesh;
}

void MeshAssembler::run() {
  if (!check_elements()) return;
  build_incidence();
  find_duplicates();
  match_faces();
  // Shell analysis is meaningless over broken references or faces shared by three tets.
  const bool can_analyse = !structural_problem_ &&
                           std::none_of(result_.problems.begin(), result_.problems.end(), [](const BuildProblem& p) {
                             return p.kind == BuildProblemKind::kDanglingReference ||
                                    p.kind == BuildProblemKind::kRepeatedVertex;
                           });
  if (options_.require_manifold && can_analyse) {
    check_vertex_shells();
    check_edge_shells();
  }
  if (result_.problems.empty()) result_.mesh = assemble();
}

BuildResult build_mesh(const RawMesh& raw, const BuildOptions& options) {
  BuildResult result;
  MeshAssembler(raw, options, result).run();
  return result;
}

}  // namespace tetcut
