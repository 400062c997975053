#include "refine/split_templates.hpp"

#include <algorithm>
#include <cassert>
#include <utility>
#include <vector>

#include "tetcut/detail/local_tables.hpp"
#include "tetcut/predicates.hpp"

namespace tetcut {
namespace {

using Label = std::uint8_t;
using Triangle = std::array<Label, 3>;

constexpr Label midpoint_label(int a, int b) { return static_cast<Label>(4 + kEdgeIndex[a][b]); }

bool has(const Triangle& t, Label x) { return t[0] == x || t[1] == x || t[2] == x; }

// A planar piece of the boundary of the polytope being coned: the triangles it is made of.
struct Facet {
  std::vector<Triangle> triangles;
  bool contains(Label x) const {
    return std::any_of(triangles.begin(), triangles.end(), [&](const Triangle& t) { return has(t, x); });
  }
  bool is_fan_around(Label x) const {
    return std::all_of(triangles.begin(), triangles.end(), [&](const Triangle& t) { return has(t, x); });
  }
};

// The triangulation of face f decided by the face alone (see the header).
std::vector<Triangle> face_triangles(int f, std::uint8_t mask, const std::array<std::uint8_t, 4>& rank) {
  const int a = kFaceVerts[f][0], b = kFaceVerts[f][1], c = kFaceVerts[f][2];
  const std::array<std::pair<int, int>, 3> edges = {{{a, b}, {b, c}, {c, a}}};
  auto split = [&](std::pair<int, int> e) { return (mask >> kEdgeIndex[e.first][e.second]) & 1; };
  const int splits = split(edges[0]) + split(edges[1]) + split(edges[2]);
  if (splits == 0) return {{static_cast<Label>(a), static_cast<Label>(b), static_cast<Label>(c)}};
  if (splits == 3) {
    const Label mab = midpoint_label(a, b), mbc = midpoint_label(b, c), mca = midpoint_label(c, a);
    return {{static_cast<Label>(a), mab, mca}, {static_cast<Label>(b), mbc, mab}, {static_cast<Label>(c), mca, mbc}, {mab, mbc, mca}};
  }
  // One or two split edges: the fan from the midpoint of the first split edge in global order.
  auto key = [&](std::pair<int, int> e) {
    return std::minmax(rank[e.first], rank[e.second]);
  };
  std::pair<int, int> first{-1, -1};
  for (const auto& e : edges)
    if (split(e) && (first.first < 0 || key(e) < key(first))) first = e;
  const Label m = midpoint_label(first.first, first.second);
  std::vector<std::pair<Label, Label>> segments;  // the face's boundary, split edges in halves
  for (const auto& e : edges) {
    const Label x = static_cast<Label>(e.first), y = static_cast<Label>(e.second);
    if (split(e)) {
      segments.push_back({x, midpoint_label(x, y)});
      segments.push_back({midpoint_label(x, y), y});
    } else {
      segments.push_back({x, y});
    }
  }
  std::vector<Triangle> out;
  for (const auto& [x, y] : segments)
    if (x != m && y != m) out.push_back({m, x, y});
  return out;
}

Vec3 reference_point(Label l) {
  static constexpr Vec3 kCorner[4] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  if (l < 4) return kCorner[l];
  const int e = l - 4;
  return 0.5 * (kCorner[kEdgeVerts[e][0]] + kCorner[kEdgeVerts[e][1]]);
}

// Orders a child so that it is positive on the reference tet, hence on every positive tet (an
// orientation-preserving affine map carries the reference tet and its midpoints onto any tet).
std::array<Label, 4> oriented(std::array<Label, 4> t) {
  const int s = orientation(reference_point(t[0]), reference_point(t[1]), reference_point(t[2]), reference_point(t[3]));
  assert(s != 0 && "a template child is flat");
  if (s < 0) std::swap(t[2], t[3]);
  return t;
}

SplitTemplate build_template(std::uint8_t mask, const std::array<std::uint8_t, 4>& rank, int preferred_cone_point) {
  SplitTemplate tpl;
  auto emit = [&](std::array<Label, 4> t) {
    assert(tpl.count < kMaxSplitChildren);
    tpl.children[tpl.count++] = oriented(t);
  };
  std::vector<Facet> facets;
  bool cut[4] = {false, false, false, false};
  for (int v = 0; v < 4; ++v) {
    Label m[3];
    int k = 0;
    bool all_split = true;
    for (int u = 0; u < 4; ++u) {
      if (u == v) continue;
      all_split = all_split && ((mask >> kEdgeIndex[v][u]) & 1);
      m[k++] = midpoint_label(v, u);
    }
    if (!all_split) continue;
    cut[v] = true;
    emit({static_cast<Label>(v), m[0], m[1], m[2]});
    facets.push_back({{{m[0], m[1], m[2]}}});
  }
  for (int f = 0; f < 4; ++f) {
    Facet facet;
    for (const Triangle& t : face_triangles(f, mask, rank)) {
      const bool at_cut_corner = (t[0] < 4 && cut[t[0]]) || (t[1] < 4 && cut[t[1]]) || (t[2] < 4 && cut[t[2]]);
      if (!at_cut_corner) facet.triangles.push_back(t);
    }
    if (!facet.triangles.empty()) facets.push_back(std::move(facet));
  }
  auto can_cone_from = [&](Label w) {
    bool present = false;
    for (const Facet& f : facets) {
      if (!f.contains(w)) continue;
      present = true;
      if (!f.is_fan_around(w)) return false;
    }
    return present;
  };
  int cone = -1;
  if (preferred_cone_point >= 0 && can_cone_from(static_cast<Label>(preferred_cone_point))) cone = preferred_cone_point;
  for (Label w = 0; w < 10 && cone < 0; ++w)
    if (can_cone_from(w)) cone = w;
  assert(cone >= 0 && "no cone point: the face rules admit no Steiner-free subdivision");
  for (const Facet& f : facets) {
    if (f.contains(static_cast<Label>(cone))) continue;
    for (const Triangle& t : f.triangles) emit({static_cast<Label>(cone), t[0], t[1], t[2]});
  }
  return tpl;
}

struct TemplateTable {
  SplitTemplate by_mask_and_order[64][24];
  SplitTemplate one_to_eight[3];

  TemplateTable() {
    std::array<std::uint8_t, 4> rank = {0, 1, 2, 3};
    do {
      const std::array<std::uint32_t, 4> ids = {rank[0], rank[1], rank[2], rank[3]};
      const std::uint8_t order = vertex_order_index(ids);
      for (int mask = 1; mask < 64; ++mask)
        by_mask_and_order[mask][order] = build_template(static_cast<std::uint8_t>(mask), rank, -1);
    } while (std::next_permutation(rank.begin(), rank.end()));
    for (int d = 0; d < 3; ++d) one_to_eight[d] = build_template(63, {0, 1, 2, 3}, 4 + d);
  }
};

}  // namespace

std::uint8_t vertex_order_index(const std::array<std::uint32_t, 4>& ids) {
  // Lehmer code: for each position, how many later ids are smaller.
  int index = 0;
  for (int i = 0; i < 4; ++i) {
    int smaller_after = 0;
    for (int j = i + 1; j < 4; ++j) smaller_after += ids[j] < ids[i];
    index = index * (4 - i) + smaller_after;
  }
  return static_cast<std::uint8_t>(index);
}

const SplitTemplate& split_template(std::uint8_t mask, std::uint8_t order_index, std::uint8_t diagonal) {
  static const TemplateTable table;  // built once, read-only afterwards
  if (mask == 63) return table.one_to_eight[diagonal % 3];
  return table.by_mask_and_order[mask & 63][order_index % 24];
}

}  // namespace tetcut
