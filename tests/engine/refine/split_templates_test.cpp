// The split templates as a table (split_templates.hpp), checked entry by entry on the reference
// tet: every mask under every choice of fans is either a subdivision of the tet that keeps each
// face's triangulation, or marked as having no cone point, and marked exactly when the fans are
// cyclic; every order on edges, hence both face rules, gives fans with a cone point.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <map>
#include <set>
#include <vector>

#include "core/random.hpp"
#include "refine/split_templates.hpp"
#include "tetcut/detail/local_tables.hpp"
#include "tetcut/predicates.hpp"

namespace tetcut {
namespace {

using Label = std::uint8_t;
using Tri = std::array<Label, 3>;

// The reference tet and its edge midpoints, as labels (0..3 corners, 4 + e midpoints): all
// coordinates are multiples of 1/2, so volumes and areas below are exact in doubles.
Vec3 point(Label l) {
  static constexpr Vec3 kCorner[4] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  if (l < 4) return kCorner[l];
  return 0.5 * (kCorner[kEdgeVerts[l - 4][0]] + kCorner[kEdgeVerts[l - 4][1]]);
}

// Six times the signed volume.
double volume6(const std::array<Label, 4>& t) {
  const Vec3 a = point(t[0]), b = point(t[1]), c = point(t[2]), d = point(t[3]);
  return dot(cross(b - a, c - a), d - a);
}

// Twice the area.
double area2(const Tri& t) { return norm(cross(point(t[1]) - point(t[0]), point(t[2]) - point(t[0]))); }

Tri sorted(Tri t) {
  std::sort(t.begin(), t.end());
  return t;
}

// A label lies on the face opposite corner f: the corner f is not one of its ends.
bool on_face(Label l, int f) { return l < 4 ? l != f : kEdgeVerts[l - 4][0] != f && kEdgeVerts[l - 4][1] != f; }

// The split edges of face f under `mask`, ascending local indices.
std::vector<int> split_edges_of_face(std::uint8_t mask, int f) {
  std::vector<int> out;
  for (int e = 0; e < 6; ++e)
    if (((mask >> e) & 1) && kEdgeVerts[e][0] != f && kEdgeVerts[e][1] != f) out.push_back(e);
  return out;
}

// The two-split faces' "fans from e, before the other split edge o" as pairs (e, o).
std::vector<std::pair<int, int>> comes_before(std::uint8_t mask, FaceFans fans) {
  std::vector<std::pair<int, int>> out;
  for (int f = 0; f < 4; ++f) {
    const std::vector<int> split = split_edges_of_face(mask, f);
    if (split.size() != 2) continue;
    const int from = (fans >> f) & 1;
    out.push_back({split[static_cast<std::size_t>(from)], split[static_cast<std::size_t>(1 - from)]});
  }
  return out;
}

// Whether the relation has a cycle (at most six edges: try every order).
bool cyclic(const std::vector<std::pair<int, int>>& before) {
  std::array<int, 6> order = {0, 1, 2, 3, 4, 5};
  do {
    std::array<int, 6> pos{};
    for (int i = 0; i < 6; ++i) pos[static_cast<std::size_t>(order[static_cast<std::size_t>(i)])] = i;
    if (std::all_of(before.begin(), before.end(), [&](auto p) { return pos[static_cast<std::size_t>(p.first)] < pos[static_cast<std::size_t>(p.second)]; }))
      return false;
  } while (std::next_permutation(order.begin(), order.end()));
  return true;
}

// The children are a subdivision of the reference tet that triangulates each face as the face
// alone decides: every child positive; the volumes sum to the tet's; every interior triangle
// shared by exactly two children; on each face, triangles that tile it and, when the face has one
// or two split edges, all contain the fan's centre (the midpoint the fans name), with three the
// central triangle of the red split.
::testing::AssertionResult is_conforming_subdivision(const SplitTemplate& tpl, std::uint8_t mask, FaceFans fans) {
  double volume = 0;
  std::map<Tri, int> interior;
  std::array<std::vector<Tri>, 4> on;
  for (int c = 0; c < tpl.count; ++c) {
    const std::array<Label, 4>& t = tpl.children[static_cast<std::size_t>(c)];
    if (orientation(point(t[0]), point(t[1]), point(t[2]), point(t[3])) <= 0)
      return ::testing::AssertionFailure() << "child " << c << " not positive";
    volume += volume6(t);
    for (int k = 0; k < 4; ++k) {
      const Tri tri = sorted({t[kFaceVerts[k][0]], t[kFaceVerts[k][1]], t[kFaceVerts[k][2]]});
      int face = -1;
      for (int f = 0; f < 4; ++f)
        if (on_face(tri[0], f) && on_face(tri[1], f) && on_face(tri[2], f)) face = f;
      if (face >= 0) on[static_cast<std::size_t>(face)].push_back(tri);
      else ++interior[tri];
    }
  }
  if (volume != 1.0) return ::testing::AssertionFailure() << "volumes sum to " << volume / 6 << ", not 1/6";
  for (const auto& [tri, n] : interior)
    if (n != 2) return ::testing::AssertionFailure() << "an interior triangle is shared by " << n << " children";
  for (int f = 0; f < 4; ++f) {
    const auto& tris = on[static_cast<std::size_t>(f)];
    double area = 0;
    for (const Tri& t : tris) area += area2(t);
    const Tri whole = sorted({kFaceVerts[f][0], kFaceVerts[f][1], kFaceVerts[f][2]});
    if (area != area2(whole)) return ::testing::AssertionFailure() << "face " << f << " is not tiled";
    if (std::set<Tri>(tris.begin(), tris.end()).size() != tris.size())
      return ::testing::AssertionFailure() << "face " << f << " has a triangle twice";
    const std::vector<int> split = split_edges_of_face(mask, f);
    if (split.size() == 1 || split.size() == 2) {
      const int centre = split.size() == 1 ? split[0] : split[static_cast<std::size_t>((fans >> f) & 1)];
      for (const Tri& t : tris)
        if (std::find(t.begin(), t.end(), 4 + centre) == t.end())
          return ::testing::AssertionFailure() << "face " << f << " is not the fan from the midpoint of edge " << centre;
    } else if (split.size() == 3) {
      const Tri centre = sorted({static_cast<Label>(4 + split[0]), static_cast<Label>(4 + split[1]), static_cast<Label>(4 + split[2])});
      if (std::find(tris.begin(), tris.end(), centre) == tris.end())
        return ::testing::AssertionFailure() << "face " << f << " lacks the red split's central triangle";
    }
  }
  return ::testing::AssertionSuccess();
}

// The fans that an order on the six edges gives (`rank[e]`: e's position): each two-split face
// fans from its split edge that comes first.
FaceFans fans_of_order(std::uint8_t mask, const std::array<int, 6>& rank) {
  FaceFans fans = 0;
  for (int f = 0; f < 4; ++f) {
    const std::vector<int> split = split_edges_of_face(mask, f);
    if (split.size() == 2 && rank[static_cast<std::size_t>(split[1])] < rank[static_cast<std::size_t>(split[0])])
      fans = static_cast<FaceFans>(fans | (1u << f));
  }
  return fans;
}

TEST(SplitTemplates, OrderIndexIsAPermutationRank) {
  std::array<std::uint32_t, 4> ids = {10, 20, 30, 40};
  std::vector<int> seen(24, 0);
  do ++seen[vertex_order_index(ids)];
  while (std::next_permutation(ids.begin(), ids.end()));
  for (int count : seen) EXPECT_EQ(count, 1);
}

TEST(SplitTemplates, TwoSplitFacesAreTheFacesWithExactlyTwoSplitEdges) {
  for (int mask = 0; mask < 64; ++mask)
    for (int f = 0; f < 4; ++f)
      EXPECT_EQ((two_split_faces(static_cast<std::uint8_t>(mask)) >> f) & 1,
                split_edges_of_face(static_cast<std::uint8_t>(mask), f).size() == 2 ? 1 : 0)
          << "mask " << mask << " face " << f;
}

// The exhaustive check of the table: 238 distinct entries, of which exactly the 14 with cyclic
// fans (three faces around a cut corner, or four around a 4-cycle, each fanning "forward") have
// no cone point, and every other one is a conforming subdivision.
TEST(SplitTemplates, EveryMaskAndFansIsAConformingSubdivisionOrMarkedCyclic) {
  int entries = 0, marked = 0;
  for (int m = 1; m < 64; ++m) {
    const auto mask = static_cast<std::uint8_t>(m);
    const int two = two_split_faces(mask);
    for (int fans = 0; fans < 16; ++fans) {
      if ((fans & ~two) != 0) {  // bits of other faces are ignored
        const SplitTemplate& a = split_template_with_fans(mask, static_cast<FaceFans>(fans));
        const SplitTemplate& b = split_template_with_fans(mask, static_cast<FaceFans>(fans & two));
        EXPECT_EQ(a.count, b.count);
        EXPECT_EQ(a.children, b.children);
        continue;
      }
      ++entries;
      const SplitTemplate& tpl = split_template_with_fans(mask, static_cast<FaceFans>(fans));
      const bool is_cyclic = cyclic(comes_before(mask, static_cast<FaceFans>(fans)));
      EXPECT_EQ(!tpl.has_cone_point(), is_cyclic) << "mask " << m << " fans " << fans;
      if (!tpl.has_cone_point()) {
        ++marked;
        continue;
      }
      EXPECT_TRUE(is_conforming_subdivision(tpl, mask, static_cast<FaceFans>(fans))) << "mask " << m << " fans " << fans;
    }
  }
  EXPECT_EQ(entries, 238);
  EXPECT_EQ(marked, 14);
  EXPECT_FALSE(split_template_with_fans(0b011110, 0b0110).has_cone_point()) << "Schoenhardt's prism: the 4-cycle 02, 21, 13, 30";
}

// The soundness of both face rules: each is an order on edges, and every one of the 720 orders
// of a tet's six edges gives fans with a cone point under every mask.
TEST(SplitTemplates, EveryOrderOnEdgesGivesFansWithAConePoint) {
  std::array<int, 6> order = {0, 1, 2, 3, 4, 5};
  int orders = 0;
  do {
    ++orders;
    std::array<int, 6> rank{};
    for (int i = 0; i < 6; ++i) rank[static_cast<std::size_t>(order[static_cast<std::size_t>(i)])] = i;
    for (int mask = 1; mask < 64; ++mask) {
      const FaceFans fans = fans_of_order(static_cast<std::uint8_t>(mask), rank);
      ASSERT_TRUE(split_template_with_fans(static_cast<std::uint8_t>(mask), fans).has_cone_point()) << "mask " << mask;
    }
  } while (std::next_permutation(order.begin(), order.end()));
  EXPECT_EQ(orders, 720);
}

// The paper's rule, as the splitter computes it from ids, is the vertex-order table's entry: the
// same children as split_template(mask, order), which always has a cone point.
TEST(SplitTemplates, VertexOrderFansAreThePapersTemplates) {
  std::array<std::uint32_t, 4> ids = {3, 17, 42, 1000};
  const std::array<double, 6> unused{};
  do {
    for (int m = 1; m < 64; ++m) {
      const auto mask = static_cast<std::uint8_t>(m);
      const SplitTemplate& paper = split_template(mask, vertex_order_index(ids));
      ASSERT_TRUE(paper.has_cone_point());
      const SplitTemplate& by_fans = split_template_with_fans(mask, face_fans(FaceRule::kVertexOrder, mask, ids, unused));
      EXPECT_EQ(paper.count, by_fans.count);
      EXPECT_EQ(paper.children, by_fans.children);
      EXPECT_TRUE(is_conforming_subdivision(paper, mask, face_fans(FaceRule::kVertexOrder, mask, ids, unused)));
    }
  } while (std::next_permutation(ids.begin(), ids.end()));
}

// kLongerEdge: a two-split face fans from the midpoint of its longer split edge (its trapezoid's
// shorter diagonal), equal lengths by the paper's rule. Checked through a random relabelling of
// the same tet, as a neighbour would see the face: the same midpoint, as a pair of global ids.
TEST(SplitTemplates, LongerEdgeFansFromTheLongerSplitEdgeHoweverTheTetIsLabelled) {
  SplitMix64 rng(29);
  for (int trial = 0; trial < 2000; ++trial) {
    std::array<std::uint32_t, 4> ids{};
    std::array<Vec3, 4> p{};
    for (int i = 0; i < 4; ++i) {
      ids[static_cast<std::size_t>(i)] = static_cast<std::uint32_t>(rng.below(1000)) * 4 + static_cast<std::uint32_t>(i);
      // Every fourth trial on a coarse grid: equal lengths, so that ties are met too.
      p[static_cast<std::size_t>(i)] = trial % 4 == 0 ? Vec3{double(rng.below(3)), double(rng.below(3)), double(rng.below(3))}
                                                      : Vec3{rng.unit(), rng.unit(), rng.unit()};
    }
    auto length2 = [&](const std::array<Vec3, 4>& q) {
      std::array<double, 6> out{};
      for (int e = 0; e < 6; ++e) {
        const Vec3 d = q[kEdgeVerts[e][0]] - q[kEdgeVerts[e][1]];
        out[static_cast<std::size_t>(e)] = dot(d, d);
      }
      return out;
    };
    const auto mask = static_cast<std::uint8_t>(1 + rng.below(63));
    const FaceFans fans = face_fans(FaceRule::kLongerEdge, mask, ids, length2(p));
    // The same tet with its local labels permuted.
    std::array<int, 4> perm = {0, 1, 2, 3};
    for (int i = 3; i > 0; --i) std::swap(perm[static_cast<std::size_t>(i)], perm[rng.below(static_cast<std::uint64_t>(i) + 1)]);
    std::array<std::uint32_t, 4> ids2{};
    std::array<Vec3, 4> p2{};
    for (int i = 0; i < 4; ++i) {
      ids2[static_cast<std::size_t>(i)] = ids[static_cast<std::size_t>(perm[static_cast<std::size_t>(i)])];
      p2[static_cast<std::size_t>(i)] = p[static_cast<std::size_t>(perm[static_cast<std::size_t>(i)])];
    }
    std::uint8_t mask2 = 0;
    for (int e = 0; e < 6; ++e)
      if ((mask >> e) & 1) {
        const int a = std::find(perm.begin(), perm.end(), kEdgeVerts[e][0]) - perm.begin();
        const int b = std::find(perm.begin(), perm.end(), kEdgeVerts[e][1]) - perm.begin();
        mask2 = static_cast<std::uint8_t>(mask2 | (1u << kEdgeIndex[a][b]));
      }
    const FaceFans fans2 = face_fans(FaceRule::kLongerEdge, mask2, ids2, length2(p2));
    for (int f = 0; f < 4; ++f) {
      const std::vector<int> split = split_edges_of_face(mask, f);
      if (split.size() != 2) continue;
      const int centre = split[static_cast<std::size_t>((fans >> f) & 1)], other = split[static_cast<std::size_t>(1 - ((fans >> f) & 1))];
      auto len2 = [&](int e) {
        const Vec3 d = p[kEdgeVerts[e][1]] - p[kEdgeVerts[e][0]];
        return dot(d, d);
      };
      auto key = [&](int e) { return std::minmax(ids[kEdgeVerts[e][0]], ids[kEdgeVerts[e][1]]); };
      EXPECT_TRUE(len2(centre) > len2(other) || (len2(centre) == len2(other) && key(centre) < key(other))) << "trial " << trial;
      // The same face in the relabelled tet: it is opposite the corner that was f.
      const int f2 = static_cast<int>(std::find(perm.begin(), perm.end(), f) - perm.begin());
      const std::vector<int> split2 = split_edges_of_face(mask2, f2);
      ASSERT_EQ(split2.size(), 2u);
      const int centre2 = split2[static_cast<std::size_t>((fans2 >> f2) & 1)];
      EXPECT_EQ(std::minmax(ids2[kEdgeVerts[centre2][0]], ids2[kEdgeVerts[centre2][1]]), key(centre)) << "trial " << trial;
    }
  }
}

// Where a mask and fans leave the polytope's interior free (two cone points with different
// children), the alternative is a conforming subdivision too, with the same face triangulations:
// only the four- and five-edge configurations, never mask 63 (its three diagonals are
// `diagonal`'s).
TEST(SplitTemplates, AlternativesAreConformingSubdivisionsOfTheSameFaces) {
  int alternatives = 0;
  for (int m = 1; m < 64; ++m) {
    const auto mask = static_cast<std::uint8_t>(m);
    for (int fans = 0; fans < 16; ++fans) {
      if ((fans & ~two_split_faces(mask)) != 0) continue;
      const SplitTemplate& other = split_template_alternative(mask, static_cast<FaceFans>(fans));
      if (other.count == 0) continue;
      ++alternatives;
      const int edges = std::popcount(static_cast<unsigned>(m));
      EXPECT_TRUE(edges == 4 || edges == 5) << "mask " << m;
      const SplitTemplate& tpl = split_template_with_fans(mask, static_cast<FaceFans>(fans));
      EXPECT_TRUE(is_conforming_subdivision(other, mask, static_cast<FaceFans>(fans))) << "mask " << m << " fans " << fans;
      EXPECT_TRUE(other.count != tpl.count || other.children != tpl.children);
    }
  }
  EXPECT_EQ(alternatives, 24);
  for (std::uint8_t d = 0; d < 3; ++d)
    EXPECT_TRUE(is_conforming_subdivision(split_template_with_fans(63, 0, d), 63, 0)) << "1:8 along diagonal " << int(d);
}

}  // namespace
}  // namespace tetcut
