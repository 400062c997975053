#include "tetcut/generators/repair.hpp"

#include <algorithm>
#include <utility>

#include "tetcut/generators/singularities.hpp"
#include "tetcut/predicates.hpp"

namespace tetcut::generators {
namespace {

using Tet = std::array<std::uint32_t, 4>;

// Seeds tried when growing a disk in a pinched link: all of them for ordinary shells, an evenly
// spread subset for huge ones so that a pathological input stays polynomial.
constexpr std::size_t kMaxDiskSeeds = 64;

// The link of a vertex restricted to some of its tets: one triangle per tet, over local ids of
// the link's vertices (the vertex's neighbours) and edges (the faces through the vertex).
struct Link {
  std::vector<std::array<std::uint32_t, 3>> tri_verts;
  std::vector<std::array<std::uint32_t, 3>> tri_edges;
  std::uint32_t vertex_count = 0;
  std::uint32_t edge_count = 0;
  std::vector<std::uint32_t> edge_uses;  // tets of the set sharing each face through the vertex

  [[nodiscard]] bool is_disk_or_sphere() const {
    bool boundary = false;
    for (auto u : edge_uses) boundary = boundary || u == 1;
    const auto euler = static_cast<std::int64_t>(vertex_count) - edge_count +
                       static_cast<std::int64_t>(tri_verts.size());
    return euler == (boundary ? 1 : 2);
  }
};

Link make_link(const std::vector<Tet>& tets, std::uint32_t v, const std::vector<std::uint32_t>& set) {
  Link link;
  std::vector<std::uint32_t> verts;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
  std::vector<std::array<std::uint32_t, 3>> others(set.size());
  for (std::size_t i = 0; i < set.size(); ++i) {
    int n = 0;
    for (auto w : tets[set[i]])
      if (w != v) others[i][n++] = w;
    for (int k = 0; k < 3; ++k) {
      verts.push_back(others[i][k]);
      const auto a = others[i][k], b = others[i][(k + 1) % 3];
      edges.emplace_back(std::min(a, b), std::max(a, b));
    }
  }
  std::sort(verts.begin(), verts.end());
  verts.erase(std::unique(verts.begin(), verts.end()), verts.end());
  std::sort(edges.begin(), edges.end());
  std::vector<std::uint32_t> uses;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> unique_edges;
  for (const auto& e : edges) {
    if (unique_edges.empty() || unique_edges.back() != e) {
      unique_edges.push_back(e);
      uses.push_back(0);
    }
    ++uses.back();
  }
  link.vertex_count = static_cast<std::uint32_t>(verts.size());
  link.edge_count = static_cast<std::uint32_t>(unique_edges.size());
  link.edge_uses = std::move(uses);
  const auto vid = [&](std::uint32_t w) {
    return static_cast<std::uint32_t>(std::lower_bound(verts.begin(), verts.end(), w) - verts.begin());
  };
  const auto eid = [&](std::uint32_t a, std::uint32_t b) {
    const std::pair<std::uint32_t, std::uint32_t> e{std::min(a, b), std::max(a, b)};
    return static_cast<std::uint32_t>(
        std::lower_bound(unique_edges.begin(), unique_edges.end(), e) - unique_edges.begin());
  };
  for (const auto& o : others) {
    link.tri_verts.push_back({vid(o[0]), vid(o[1]), vid(o[2])});
    // tri_edges[k] is the edge opposite tri_verts[k].
    link.tri_edges.push_back({eid(o[1], o[2]), eid(o[2], o[0]), eid(o[0], o[1])});
  }
  return link;
}

// Grows a topological disk (or a sphere, when it closes) of link triangles from `seed`: a
// triangle joins when it shares one boundary edge and brings a new vertex, or shares two or three
// boundary edges. Such a union never pinches, so the tets kept have a manifold vertex.
std::vector<char> grow_disk(const Link& link, std::size_t seed) {
  const auto n = link.tri_verts.size();
  std::vector<char> in(n, 0);
  std::vector<std::uint32_t> vertex_uses(link.vertex_count, 0), edge_uses(link.edge_count, 0);
  const auto add = [&](std::size_t t) {
    in[t] = 1;
    for (int k = 0; k < 3; ++k) {
      ++vertex_uses[link.tri_verts[t][k]];
      ++edge_uses[link.tri_edges[t][k]];
    }
  };
  add(seed);
  for (bool grew = true; grew;) {
    grew = false;
    for (std::size_t t = 0; t < n; ++t) {
      if (in[t]) continue;
      int shared = 0, corner = -1;
      for (int k = 0; k < 3; ++k)
        if (edge_uses[link.tri_edges[t][k]] == 1) {
          ++shared;
          corner = k;  // tri_edges[k] is opposite tri_verts[k]
        }
      if (shared == 0) continue;
      // One shared edge: the corner across it must be new, or the disk would pinch there.
      if (shared == 1 && vertex_uses[link.tri_verts[t][corner]] != 0) continue;
      add(t);
      grew = true;
    }
  }
  return in;
}

// The tets of `shell` (a singular vertex's tets) to keep: the largest component, or, if its link
// is still no disk or sphere, the largest disk grown in it.
std::vector<std::uint32_t> kept_at_vertex(const std::vector<Tet>& tets, const SingularVertex& sv) {
  std::size_t best = 0;
  for (std::size_t c = 1; c < sv.components.size(); ++c)
    if (sv.components[c].size() > sv.components[best].size()) best = c;
  const auto& comp = sv.components[best];
  const Link link = make_link(tets, sv.vertex, comp);
  if (link.is_disk_or_sphere()) return comp;

  const std::size_t n = comp.size();
  const std::size_t stride = std::max<std::size_t>(1, (n + kMaxDiskSeeds - 1) / kMaxDiskSeeds);
  std::vector<char> best_disk;
  std::size_t best_size = 0;
  for (std::size_t seed = 0; seed < n; seed += stride) {
    auto disk = grow_disk(link, seed);
    const auto size = static_cast<std::size_t>(std::count(disk.begin(), disk.end(), 1));
    if (size > best_size) {
      best_size = size;
      best_disk = std::move(disk);
    }
  }
  std::vector<std::uint32_t> kept;
  for (std::size_t i = 0; i < n; ++i)
    if (best_disk[i]) kept.push_back(comp[i]);
  return kept;
}

}  // namespace

const char* to_string(RepairAction action) {
  switch (action) {
    case RepairAction::kReoriented: return "reoriented";
    case RepairAction::kRemovedInvalid: return "removed-invalid";
    case RepairAction::kRemovedFlat: return "removed-flat";
    case RepairAction::kRemovedDuplicate: return "removed-duplicate";
    case RepairAction::kRemovedOverSharedFace: return "removed-over-shared-face";
    case RepairAction::kRemovedSingularEdge: return "removed-at-singular-edge";
    case RepairAction::kRemovedSingularVertex: return "removed-at-singular-vertex";
  }
  return "unknown";
}

std::uint64_t RepairReport::count(RepairAction action) const {
  return static_cast<std::uint64_t>(std::count_if(
      changes.begin(), changes.end(), [&](const RepairChange& c) { return c.action == action; }));
}

std::uint64_t RepairReport::removed_tets() const {
  return changes.size() - count(RepairAction::kReoriented);
}

namespace {

// One repair, its steps in the order repair_mesh() takes them. `tets` are the input's (oriented
// in place), `alive` says which are kept; every removal is reported with its reason.
class Repair {
 public:
  Repair(const RawMesh& input, RepairReport& report)
      : input_(input), report_(report), nv_(input.positions.size()), nt_(input.tets.size()), tets_(input.tets),
        alive_(nt_, 1) {}

  // 1. Tets that are not tets at all.
  void remove_invalid() {
    const auto& P = input_.positions;
    for (std::uint32_t t = 0; t < nt_; ++t) {
      const auto& q = tets_[t];
      bool bad = false;
      for (int i = 0; i < 4 && !bad; ++i) {
        bad = q[i] >= nv_ || !is_finite(P[q[i]]);
        for (int j = i + 1; j < 4 && !bad; ++j) bad = q[i] == q[j];
      }
      if (bad) remove(t, RepairAction::kRemovedInvalid);
    }
  }

  // 2. Orientation, by the exact predicate: reorient rather than remove.
  void orient() {
    const auto& P = input_.positions;
    for (std::uint32_t t = 0; t < nt_; ++t) {
      if (!alive_[t]) continue;
      auto& q = tets_[t];
      const int o = orientation(P[q[0]], P[q[1]], P[q[2]], P[q[3]]);
      if (o == 0) {
        remove(t, RepairAction::kRemovedFlat);
      } else if (o < 0) {
        std::swap(q[2], q[3]);
        report_.changes.push_back({RepairAction::kReoriented, t, kNoIndex, kNoIndex});
      }
    }
  }

  // 3. Duplicates: the first of equal vertex sets stays.
  void remove_duplicates() {
    std::vector<std::pair<Tet, std::uint32_t>> keys;
    for (std::uint32_t t = 0; t < nt_; ++t) {
      if (!alive_[t]) continue;
      Tet k = tets_[t];
      std::sort(k.begin(), k.end());
      keys.emplace_back(k, t);
    }
    std::sort(keys.begin(), keys.end());
    for (std::size_t i = 1; i < keys.size(); ++i)
      if (keys[i].first == keys[i - 1].first) remove(keys[i].second, RepairAction::kRemovedDuplicate);
  }

  // 4. Faces with more than two tets: overlapping tets; on each side of the face the first stays.
  void remove_over_shared_faces() {
    const auto& P = input_.positions;
    struct FaceKey {
      std::array<std::uint32_t, 3> f;
      std::uint32_t tet;
      std::uint32_t apex;
      bool operator<(const FaceKey& o) const { return f != o.f ? f < o.f : tet < o.tet; }
    };
    std::vector<FaceKey> faces;
    for (std::uint32_t t = 0; t < nt_; ++t) {
      if (!alive_[t]) continue;
      for (int i = 0; i < 4; ++i) {
        std::array<std::uint32_t, 3> f{};
        int n = 0;
        for (int j = 0; j < 4; ++j)
          if (j != i) f[n++] = tets_[t][j];
        std::sort(f.begin(), f.end());
        faces.push_back({f, t, tets_[t][i]});
      }
    }
    std::sort(faces.begin(), faces.end());
    for (std::size_t i = 0; i < faces.size();) {
      std::size_t j = i;
      while (j < faces.size() && faces[j].f == faces[i].f) ++j;
      if (j - i > 2) {
        bool side_taken[2] = {false, false};
        for (std::size_t k = i; k < j; ++k) {
          if (!alive_[faces[k].tet]) continue;
          const auto& f = faces[k].f;
          const int side = orientation(P[f[0]], P[f[1]], P[f[2]], P[faces[k].apex]) > 0 ? 1 : 0;
          if (side_taken[side])
            remove(faces[k].tet, RepairAction::kRemovedOverSharedFace);
          else
            side_taken[side] = true;
        }
      }
      i = j;
    }
  }

  // 5. Singularities, until none is left. Each sweep fixes every singularity whose shell no
  //    earlier fix of the sweep touched (the others are re-examined on fresh data next sweep);
  //    edges first, because a singular edge makes both its ends singular too.
  void remove_singularities() {
    while (singularity_sweep()) {
    }
  }

  // 6. Output: kept tets and the vertices they use, both in input order.
  void output(RepairResult& result) {
    std::vector<std::uint32_t> new_index(nv_, kNoIndex);
    for (std::uint32_t t = 0; t < nt_; ++t)
      if (alive_[t])
        for (auto v : tets_[t]) new_index[v] = 0;
    RawMesh out;
    for (std::uint32_t v = 0; v < nv_; ++v) {
      if (new_index[v] == kNoIndex) {
        report_.dropped_vertices.push_back(v);
      } else {
        new_index[v] = static_cast<std::uint32_t>(out.positions.size());
        out.positions.push_back(input_.positions[v]);
      }
    }
    for (std::uint32_t t = 0; t < nt_; ++t)
      if (alive_[t]) out.tets.push_back({new_index[tets_[t][0]], new_index[tets_[t][1]],
                                         new_index[tets_[t][2]], new_index[tets_[t][3]]});
    if (out.tets.empty()) {
      result.error = nt_ == 0 ? "the mesh has no tetrahedra"
                              : "cannot be repaired: all " + std::to_string(nt_) +
                                    " tetrahedra would have to be removed";
      return;
    }
    result.mesh = std::move(out);
  }

 private:
  void remove(std::uint32_t t, RepairAction why, std::uint32_t a = kNoIndex, std::uint32_t b = kNoIndex) {
    alive_[t] = 0;
    report_.changes.push_back({why, t, a, b});
  }

  // One sweep of step 5; false when no singularity is left (or no tet).
  bool singularity_sweep() {
    ++report_.rounds;
    RawMesh current;
    current.positions = input_.positions;
    std::vector<std::uint32_t> input_index;
    for (std::uint32_t t = 0; t < nt_; ++t)
      if (alive_[t]) {
        current.tets.push_back(tets_[t]);
        input_index.push_back(t);
      }
    if (current.tets.empty()) return false;
    const Singularities s = find_singularities(current);
    if (s.empty()) return false;

    std::vector<char> touched(current.tets.size(), 0);
    const auto untouched = [&](const std::vector<std::vector<std::uint32_t>>& comps) {
      for (const auto& c : comps)
        for (auto t : c)
          if (touched[t]) return false;
      return true;
    };
    const auto touch_all = [&](const std::vector<std::vector<std::uint32_t>>& comps) {
      for (const auto& c : comps)
        for (auto t : c) touched[t] = 1;
    };
    std::size_t removed_this_round = 0;
    if (!s.edges.empty()) {
      for (const auto& e : s.edges) {
        if (!untouched(e.components)) continue;
        touch_all(e.components);
        std::size_t best = 0;
        for (std::size_t c = 1; c < e.components.size(); ++c)
          if (e.components[c].size() > e.components[best].size()) best = c;
        for (std::size_t c = 0; c < e.components.size(); ++c) {
          if (c == best) continue;
          for (auto t : e.components[c]) {
            remove(input_index[t], RepairAction::kRemovedSingularEdge, e.a, e.b);
            ++removed_this_round;
          }
        }
        ++report_.singular_edges_fixed;
      }
    } else {
      for (const auto& v : s.vertices) {
        if (!untouched(v.components)) continue;
        touch_all(v.components);
        auto kept = kept_at_vertex(current.tets, v);
        std::sort(kept.begin(), kept.end());
        for (const auto& c : v.components)
          for (auto t : c)
            if (!std::binary_search(kept.begin(), kept.end(), t)) {
              remove(input_index[t], RepairAction::kRemovedSingularVertex, v.vertex);
              ++removed_this_round;
            }
        ++report_.singular_vertices_fixed;
      }
    }
    if (removed_this_round == 0) {
      // Cannot happen by construction (a kept disk is always smaller than a non-disk link), but a
      // repair that loops forever would be worse than one that removes a whole shell.
      const auto& comps = s.vertices.empty() ? s.edges.front().components : s.vertices.front().components;
      for (const auto& c : comps)
        for (auto t : c) remove(input_index[t], RepairAction::kRemovedSingularVertex);
    }
    return true;
  }

  const RawMesh& input_;
  RepairReport& report_;
  const std::size_t nv_, nt_;
  std::vector<Tet> tets_;
  std::vector<char> alive_;
};

}  // namespace

RepairResult repair_mesh(const RawMesh& input) {
  RepairResult result;
  Repair repair(input, result.report);
  repair.remove_invalid();
  repair.orient();
  repair.remove_duplicates();
  repair.remove_over_shared_faces();
  repair.remove_singularities();
  repair.output(result);
  return result;
}

}  // namespace tetcut::generators
