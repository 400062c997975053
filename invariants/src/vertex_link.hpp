// The heart of the checker: everything combinatorial that can be decided from one vertex's shell.
//
// For a vertex v with shell S (the tets containing v), the *link* of v is the triangle complex
// made of the faces opposite v in S. Its triangles are the tets around v, its edges are the faces
// through v, its vertices are the edges through v. So one small sort per vertex decides:
//   I1  duplicate tets (at the tet's smallest vertex),
//   I3  a face through v shared by more than two tets (a link edge in 3+ triangles),
//   I6  an edge (v, w) whose shell is not one face-connected component: the link triangles
//       around link vertex w do not form a single fan,
//   I5  the shell is not face-connected (the link is not connected) or the link is not a disk
//       (boundary vertex) or a sphere (interior vertex),
//   I2  (engine given) the engine's neighbour across each face through v,
//   I8  (engine given) the engine's boundary face count and vertex->tet reference of v.
// Every face and edge is seen from each of its touched vertices but counted once, at its
// smallest touched vertex, so that the full level (every vertex touched) and the local level
// (the vertices of one operation) count the same way.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "engine_records.hpp"
#include "report_builder.hpp"

namespace tetcut::invariants::detail {

// A boundary face, vertices counter-clockwise seen from outside (kTetFaces order of its tet).
struct BoundaryTriangle {
  std::array<std::uint32_t, 3> v;
  std::uint32_t tet;
};

struct LinkContext {
  std::span<const RawTet> tets;        // the checker's view of every tet, by id
  std::span<std::uint8_t> excluded;    // per tet: 1 = left out (duplicate, bad references, dead)
  // Which vertices this check covers: null = all of them (full level), otherwise
  // touched_stamp[w] == stamp.
  const std::uint32_t* touched_stamp = nullptr;
  std::uint32_t stamp = 0;
  const EngineRecordsView* engine = nullptr;        // set: compare for I2 and I8
  std::vector<BoundaryTriangle>* boundary = nullptr;  // set: collect each boundary face once
  ReportBuilder* report = nullptr;
};

class VertexLinkChecker {
 public:
  // Checks vertex v whose shell (tet ids, any order, no repeats) is `shell`; excluded tets in it
  // are skipped. Returns the number of boundary faces through v.
  std::uint32_t check(const LinkContext& ctx, std::uint32_t v, std::span<const std::uint32_t> shell);

 private:
  struct LinkEdge {
    std::uint64_t key;     // (a << 32) | b, a < b: the face {v, a, b}
    std::uint32_t tet;     // index into shell_
    std::uint8_t slot_a;   // where a sits in the tet's link triangle
    std::uint8_t slot_b;
    std::uint8_t face;     // local face of the tet that is {v, a, b}
  };
  struct TetKey {
    std::array<std::uint32_t, 3> others;
    std::uint32_t tet;
  };

  struct FaceCounts {
    std::uint32_t faces = 0;     // faces through v: link edges
    std::uint32_t boundary = 0;  // those with one tet
  };

  std::uint32_t find(std::vector<std::uint32_t>& parent, std::uint32_t x);
  // The steps of check(), in order. I1: duplicate tets reported and excluded.
  void report_duplicates(const LinkContext& ctx, std::uint32_t v, std::span<const std::uint32_t> shell);
  // The link of v (triangles, edges, vertices) and the union-find state; the number of its tets.
  std::uint32_t build_link(const LinkContext& ctx, std::uint32_t v, std::span<const std::uint32_t> shell);
  // Every face through v once: I3 (at most two tets), I2 against the engine, the boundary faces;
  // the tets and wedges across each interior face united.
  FaceCounts check_faces(const LinkContext& ctx, std::uint32_t v);
  // I6 at every edge through v; whether the link is a surface (every link vertex one fan).
  bool check_edge_shells(const LinkContext& ctx, std::uint32_t v, std::uint32_t k);
  // I5: one face-connected shell, and a link that is a disk or a sphere.
  void check_vertex_shell(const LinkContext& ctx, std::uint32_t v, std::uint32_t k, const FaceCounts& faces,
                          bool link_is_surface);

  // Scratch, reused across vertices: no allocation once warmed up.
  std::vector<std::uint32_t> shell_;
  std::vector<std::array<std::uint32_t, 3>> triangle_;  // link triangle of shell_[i]
  std::vector<LinkEdge> edges_;
  std::vector<TetKey> keys_;
  std::vector<std::uint32_t> link_verts_;
  std::vector<std::uint32_t> shell_parent_;
  std::vector<std::uint32_t> wedge_parent_;   // 3 * i + slot: tet i seen around edge (v, slot)
  std::vector<std::uint32_t> wedge_vertex_;   // 3 * i + slot: index of its link vertex
  std::vector<std::uint32_t> first_root_;     // per link vertex
  std::vector<std::uint8_t> boundary_faces_;  // per link vertex, saturating
  std::vector<std::uint8_t> bad_;             // per link vertex: bit 0 split fan, bit 1 over-shared face
};

}  // namespace tetcut::invariants::detail
