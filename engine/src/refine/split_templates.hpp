// The subdivision of one tetrahedron whose edges are split at their midpoints (paper 3.2,
// Figure 2), as a table indexed by which edges are split and by how each face with two split
// edges is triangulated.
//
// Local point labels: 0..3 are the tet's corners, 4 + e is the midpoint of local edge e
// (kEdgeVerts). A face's triangulation is decided by the face alone, so the two tets sharing a
// face always triangulate it alike:
//   - a face with one split edge: two triangles from the midpoint (the only choice);
//   - a face with two split edges (a "two-split face": split edges (v, a) and (v, b) around the
//     apex v, edge (a, b) whole): the corner triangle (v, m_va, m_vb) and the trapezoid
//     (m_va, a, b, m_vb), cut by one of its diagonals. Which one is the face's *fan*: the fan
//     from m_va has the diagonal (m_va, b), the fan from m_vb has (m_vb, a). A FaceRule decides;
//   - a face with three split edges: the red 1:4 split (one central triangle).
// The tet is then subdivided without Steiner points: the corners whose three edges are all
// split are cut off (the corner tets), and the remaining convex polytope is coned from a point
// whose incident facets are all fans around it. With all six edges split the polytope is the
// central octahedron and the cone point is chosen to cut it along its shortest diagonal (1:8).
// In 24 four- and five-edge entries two cone points give different children: the table keeps
// both (split_template_alternative) and the splitter keeps the one with the better children.
//
// Not every choice of fans has a cone point: fans chosen face by face can be cyclic inside one
// tet. With the three edges around a corner split, the polytope left by the corner tet is a
// triangular prism, and with four split edges forming a 4-cycle (e.g. 01, 12, 23, 30) every face
// is a two-split face; if each face fans "forward" around the cycle, the polytope is Schoenhardt's
// twisted prism, which has no triangulation without a Steiner point. split_template_with_fans()
// marks such entries (count 0: 14 of the 238 distinct mask x fans combinations); the table is
// built by the cone-point search for every mask and every choice of fans, and the tests check
// every entry exhaustively.
//
// Which fans are safe: those induced by a strict total order on edges, each two-split face
// fanning from the midpoint of whichever of its two split edges comes first. Such fans are never
// cyclic, and every one of the 720 orders of a tet's six edges gives fans with a cone point under
// every mask (exhaustive test). A rule that is the restriction of one global order on the mesh's
// edges therefore (a) triangulates each face from the face alone, identically in both tets, and
// (b) always has a cone point: no revert, no search across neighbours. Both rules below are such
// orders:
//   - FaceRule::kVertexOrder, the paper's "lexicographic order": edges by their sorted global
//     vertex ids. It ignores geometry;
//   - FaceRule::kLongerEdge: edges by decreasing length, ties by kVertexOrder. A
//     two-split face fans from the midpoint of its longer split edge. In the trapezoid,
//     |m_va - b|^2 - |m_vb - a|^2 = 3/4 (|v - b|^2 - |v - a|^2), so this is its shorter
//     diagonal, which is also its Delaunay diagonal and the one that maximises the triangles'
//     smallest angle (both come down to comparing the angles at a and b); it is Rivara's
//     longest-edge bisection of the face. The order reads each edge's squared length, computed
//     from its two end positions, which gives the same bits in every tet around the edge.
//
// The resulting tet counts are those of the paper's ten configurations: 1 edge: 2; two edges on
// a face: 3; two opposite: 4; three on a face or around a vertex: 4; three along a path: 4 or 5;
// four edges: 5 or 6; five: 7; six: 8.
#pragma once

#include <array>
#include <cstdint>

namespace tetcut {

inline constexpr int kMaxSplitChildren = 8;

struct SplitTemplate {
  std::uint8_t count = 0;  // 0: no cone point for this choice of fans (never for mask 63)
  // Children as local point labels, positively oriented whenever the parent is.
  std::array<std::array<std::uint8_t, 4>, kMaxSplitChildren> children{};

  [[nodiscard]] bool has_cone_point() const { return count > 0; }
};

// A tet's fan choices: bit f is set when face f is a two-split face that fans from the midpoint
// of its split edge with the larger local edge index (kEdgeIndex), clear when it fans from the
// other one. Bits of the other faces are ignored.
using FaceFans = std::uint8_t;

// The two-split faces of `mask` (bit f for face f): the faces whose triangulation is a choice.
std::uint8_t two_split_faces(std::uint8_t mask);

// The global order on edges that decides every two-split face (see above).
enum class FaceRule : std::uint8_t {
  kLongerEdge,   // decreasing length, ties by vertex order: the face's shorter diagonal
  kVertexOrder,  // sorted global vertex ids: the paper's rule
};

// The fans `rule` chooses for the two-split faces of `mask`: always a combination with a cone
// point. `ids`: the tet's global vertex ids; `edge_length2`: squared length of each local edge,
// dot(d, d) with d the difference of its end positions in either direction (kLongerEdge only).
FaceFans face_fans(FaceRule rule, std::uint8_t mask, const std::array<std::uint32_t, 4>& ids,
                   const std::array<double, 6>& edge_length2);

// Index 0..23 of the order of four distinct global ids: rank[i] is the position of local vertex
// i when the four ids are sorted.
std::uint8_t vertex_order_index(const std::array<std::uint32_t, 4>& global_ids);

// The template for `mask` (bit e set when local edge e is split; 1..63) and the fans; count 0
// when that choice of fans has no cone point. For mask 63 (no two-split face), `diagonal` (0..2)
// selects which interior diagonal of the central octahedron is used: the one joining the
// midpoints of local edges d and 5 - d.
const SplitTemplate& split_template_with_fans(std::uint8_t mask, FaceFans fans, std::uint8_t diagonal = 0);

// Another subdivision for the same mask and fans, from another cone point, whose children differ
// from split_template_with_fans()'s (the same face triangulations, another interior); count 0
// when the cone point is unique up to the children, and for mask 63, whose choice is `diagonal`.
const SplitTemplate& split_template_alternative(std::uint8_t mask, FaceFans fans);

// The template of the paper's rule for the vertex order `order_index` (vertex_order_index()):
// split_template_with_fans() with the kVertexOrder fans. Always has a cone point.
const SplitTemplate& split_template(std::uint8_t mask, std::uint8_t order_index, std::uint8_t diagonal = 0);

}  // namespace tetcut
