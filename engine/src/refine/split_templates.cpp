#include "refine/split_templates.hpp"

#include <algorithm>
#include <cassert>
#include <tuple>
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

// Per mask, its two-split faces and each one's two split edges (local edge indices, ascending):
// what the fans choose between.
struct TwoSplitFaces {
  std::uint8_t faces = 0;  // bit f: face f has exactly two split edges
  std::array<std::array<std::uint8_t, 2>, 4> edges{};
};

constexpr std::array<TwoSplitFaces, 64> make_two_split_faces() {
  std::array<TwoSplitFaces, 64> out{};
  for (int mask = 0; mask < 64; ++mask)
    for (int f = 0; f < 4; ++f) {
      std::uint8_t split[3] = {0, 0, 0};
      int n = 0;
      for (int e = 0; e < 6; ++e)  // ascending
        if (((mask >> e) & 1) && kEdgeVerts[e][0] != f && kEdgeVerts[e][1] != f) split[n++] = static_cast<std::uint8_t>(e);
      if (n != 2) continue;
      out[static_cast<std::size_t>(mask)].faces = static_cast<std::uint8_t>(out[static_cast<std::size_t>(mask)].faces | (1u << f));
      out[static_cast<std::size_t>(mask)].edges[static_cast<std::size_t>(f)] = {split[0], split[1]};
    }
  return out;
}

constexpr std::array<TwoSplitFaces, 64> kTwoSplitFaces = make_two_split_faces();
static_assert(kTwoSplitFaces[0b011110].faces == 0b1111, "a 4-cycle of split edges makes every face a two-split face");
static_assert(kTwoSplitFaces[0b000111].faces == 0b1110, "three split edges around corner 0: the faces at that corner");

// The triangulation of face f decided by the face alone (see the header).
std::vector<Triangle> face_triangles(int f, std::uint8_t mask, FaceFans fans) {
  const int a = kFaceVerts[f][0], b = kFaceVerts[f][1], c = kFaceVerts[f][2];
  const std::array<std::pair<int, int>, 3> edges = {{{a, b}, {b, c}, {c, a}}};
  auto split = [&](std::pair<int, int> e) { return (mask >> kEdgeIndex[e.first][e.second]) & 1; };
  const int splits = split(edges[0]) + split(edges[1]) + split(edges[2]);
  if (splits == 0) return {{static_cast<Label>(a), static_cast<Label>(b), static_cast<Label>(c)}};
  if (splits == 3) {
    const Label mab = midpoint_label(a, b), mbc = midpoint_label(b, c), mca = midpoint_label(c, a);
    return {{static_cast<Label>(a), mab, mca}, {static_cast<Label>(b), mbc, mab}, {static_cast<Label>(c), mca, mbc}, {mab, mbc, mca}};
  }
  // One or two split edges: the fan from the only midpoint, or from the one the fans bit names.
  Label m = 0;
  if (splits == 2) {
    m = static_cast<Label>(4 + kTwoSplitFaces[mask].edges[static_cast<std::size_t>(f)][(fans >> f) & 1]);
  } else {
    for (const auto& e : edges)
      if (split(e)) m = midpoint_label(e.first, e.second);
  }
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

// What is left of the tet once its corner tets are cut off, as the facets its faces and the cuts
// make under `mask` and `fans`, and the subdivisions coning it from one of its points.
class Polytope {
 public:
  Polytope(std::uint8_t mask, FaceFans fans) {
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
      cut_[v] = true;
      corner_tets_.push_back({static_cast<Label>(v), m[0], m[1], m[2]});
      facets_.push_back({{{m[0], m[1], m[2]}}});
    }
    for (int f = 0; f < 4; ++f) {
      Facet facet;
      for (const Triangle& t : face_triangles(f, mask, fans)) {
        const bool at_cut_corner = (t[0] < 4 && cut_[t[0]]) || (t[1] < 4 && cut_[t[1]]) || (t[2] < 4 && cut_[t[2]]);
        if (!at_cut_corner) facet.triangles.push_back(t);
      }
      if (!facet.triangles.empty()) facets_.push_back(std::move(facet));
    }
  }

  // w is a point of the polytope and every facet through it is a fan around it.
  [[nodiscard]] bool can_cone_from(Label w) const {
    bool present = false;
    for (const Facet& f : facets_) {
      if (!f.contains(w)) continue;
      present = true;
      if (!f.is_fan_around(w)) return false;
    }
    return present;
  }

  // The corner tets and the cone from w over every facet not through w.
  [[nodiscard]] SplitTemplate cone_from(Label w) const {
    SplitTemplate tpl;
    auto emit = [&](std::array<Label, 4> t) {
      assert(tpl.count < kMaxSplitChildren);
      tpl.children[tpl.count++] = oriented(t);
    };
    for (const auto& t : corner_tets_) emit(t);
    for (const Facet& f : facets_) {
      if (f.contains(w)) continue;
      for (const Triangle& t : f.triangles) emit({w, t[0], t[1], t[2]});
    }
    return tpl;
  }

 private:
  std::vector<Facet> facets_;
  std::vector<std::array<Label, 4>> corner_tets_;
  bool cut_[4] = {false, false, false, false};
};

// The same children, whatever their order and the order of their labels.
bool same_children(const SplitTemplate& x, const SplitTemplate& y) {
  auto sorted = [](const SplitTemplate& t) {
    std::vector<std::array<Label, 4>> out(t.children.begin(), t.children.begin() + t.count);
    for (auto& c : out)  // insertion sort: std::sort on 4 bytes makes GCC 12 warn (-Wstringop-overflow)
      for (std::size_t i = 1; i < c.size(); ++i)
        for (std::size_t j = i; j > 0 && c[j] < c[j - 1]; --j) std::swap(c[j], c[j - 1]);
    std::sort(out.begin(), out.end());
    return out;
  };
  return sorted(x) == sorted(y);
}

// The subdivisions of `mask` with `fans`: from the lowest cone point, and from the next cone
// point whose children differ (count 0 when there is none). Both count 0 when the fans are
// cyclic: no cone point, no Steiner-free subdivision of this kind.
std::pair<SplitTemplate, SplitTemplate> build_templates(std::uint8_t mask, FaceFans fans) {
  const Polytope polytope(mask, fans);
  std::pair<SplitTemplate, SplitTemplate> out;
  bool first = true;
  for (Label w = 0; w < 10; ++w) {
    if (!polytope.can_cone_from(w)) continue;
    SplitTemplate tpl = polytope.cone_from(w);
    if (first) {
      out.first = tpl;
      first = false;
    } else if (!same_children(tpl, out.first)) {
      out.second = tpl;
      break;
    }
  }
  return out;
}

// The fans of a strict order on the tet's edges (`precedes(e, f)`: e comes before f): each
// two-split face fans from the midpoint of its split edge that comes first.
template <class Precedes>
FaceFans fans_of_order(std::uint8_t mask, Precedes precedes) {
  const TwoSplitFaces& two = kTwoSplitFaces[mask & 63];
  FaceFans fans = 0;
  for (int f = 0; f < 4; ++f) {
    const auto& e = two.edges[static_cast<std::size_t>(f)];
    if (((two.faces >> f) & 1) && precedes(e[1], e[0])) fans = static_cast<FaceFans>(fans | (1u << f));
  }
  return fans;
}

// The paper's order on edges: by their sorted global ids (any ids with the same order, such as
// the ranks 0..3, give the same comparisons).
struct VertexOrder {
  const std::array<std::uint32_t, 4>& ids;
  [[nodiscard]] std::pair<std::uint32_t, std::uint32_t> key(int e) const {
    return std::minmax(ids[kEdgeVerts[e][0]], ids[kEdgeVerts[e][1]]);
  }
  bool operator()(int e, int f) const { return key(e) < key(f); }
};

struct TemplateTable {
  SplitTemplate by_mask_and_fans[64][16];
  SplitTemplate alternative[64][16];  // another cone point's subdivision, when it differs
  FaceFans vertex_order_fans[64][24];  // the kVertexOrder fans of each mask under each order
  SplitTemplate one_to_eight[3];

  TemplateTable() {
    // Only the fans of two-split faces matter; the other bits repeat the entry without them.
    for (int mask = 1; mask < 64; ++mask) {
      const int two = kTwoSplitFaces[static_cast<std::size_t>(mask)].faces;
      for (int fans = 0; fans < 16; ++fans)
        std::tie(by_mask_and_fans[mask][fans], alternative[mask][fans]) =
            (fans & ~two) != 0 ? std::pair(by_mask_and_fans[mask][fans & two], alternative[mask][fans & two])
                               : build_templates(static_cast<std::uint8_t>(mask), static_cast<FaceFans>(fans));
    }
    std::array<std::uint32_t, 4> rank = {0, 1, 2, 3};
    do {
      const std::uint8_t order = vertex_order_index(rank);
      for (int mask = 0; mask < 64; ++mask)
        vertex_order_fans[mask][order] = fans_of_order(static_cast<std::uint8_t>(mask), VertexOrder{rank});
    } while (std::next_permutation(rank.begin(), rank.end()));
    for (auto& a : alternative[63]) a = {};  // mask 63 chooses by `diagonal`
    const Polytope octahedron(63, 0);
    for (int d = 0; d < 3; ++d) one_to_eight[d] = octahedron.cone_from(static_cast<Label>(4 + d));
  }
};

const TemplateTable& table() {
  static const TemplateTable table;  // built once, read-only afterwards
  return table;
}

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

std::uint8_t two_split_faces(std::uint8_t mask) { return kTwoSplitFaces[mask & 63].faces; }

FaceFans face_fans(FaceRule rule, std::uint8_t mask, const std::array<std::uint32_t, 4>& ids,
                   const std::array<double, 6>& edge_length2) {
  const VertexOrder by_ids{ids};
  if (rule == FaceRule::kVertexOrder) return fans_of_order(mask, by_ids);
  return fans_of_order(mask, [&](int e, int f) {
    const double le = edge_length2[static_cast<std::size_t>(e)], lf = edge_length2[static_cast<std::size_t>(f)];
    return le > lf || (le == lf && by_ids(e, f));
  });
}

const SplitTemplate& split_template_with_fans(std::uint8_t mask, FaceFans fans, std::uint8_t diagonal) {
  if (mask == 63) return table().one_to_eight[diagonal % 3];
  return table().by_mask_and_fans[mask & 63][fans & 15];
}

const SplitTemplate& split_template_alternative(std::uint8_t mask, FaceFans fans) {
  return table().alternative[mask & 63][fans & 15];
}

const SplitTemplate& split_template(std::uint8_t mask, std::uint8_t order_index, std::uint8_t diagonal) {
  return split_template_with_fans(mask, table().vertex_order_fans[mask & 63][order_index % 24], diagonal);
}

}  // namespace tetcut
