// Paper 3.5, as written: remove T with the smallest set of its neighbours that suppresses the
// singularity without creating another one.
//
// Vertex singularity at v (cases 1 and 2). In the shell of v, search breadth-first from T to
// the border of the shell (depth <= 10: figure 4); every border tet reached gives a path, the
// shortest first. Test T plus each path. Where one fails, "the path often divides the adjacency
// of one of the tetrahedron vertices into two connected components": test T plus the path
// extended by each component of the offending vertex's remaining shell; a removable one is kept
// "if no smaller removable set is determined" by the paths that follow. The search stops when
// the next path is no smaller than the set kept; "no paths nor extended paths" removable gives
// the empty set. An offence at an edge the path pinches is not extended here (the wide search
// does that: ours, not the paper's).
//
// Edge singularity at e (case 3). T lies inside the open ring of tets around the boundary edge
// e: test T with the tets on its left, with those on its right (the smaller wins), then with
// all of them. None gives the empty set.
//
// Cost: O(shell of v or e) plus one set test per candidate (per path at most 1 + components;
// paths bounded by the border tets within depth 10). Never mutates the mesh.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "remove/removability.hpp"
#include "remove/set_removal.hpp"
#include "tetcut/mesh.hpp"
#include "tetcut/removal_report.hpp"

namespace tetcut::detail {

class NeighbourSearch {
 public:
  // A removable set containing t into `out`; false (out unspecified) when the paper's
  // candidates all fail. `first` is the O(1) test's verdict on t (not removable).
  // `first_found`: the first removable candidate in the search's order, not the smallest
  // (NeighbourSetChoice, cut_strategies.hpp).
  bool find(const TetMesh& mesh, SetRemovalWorkspace& ws, TetId t, const Removability& first, int max_depth,
            std::uint32_t max_set_size, std::vector<TetId>& out, bool first_found = false);
  // After find() on a vertex singularity: T followed by the shortest path it tested, which
  // 3.7 refines along ("we also store the shortest path ... eventually used for the optimized
  // local refinement"); empty when find() found none or met an edge singularity.
  [[nodiscard]] std::span<const TetId> path() const {
    return path_found_ ? std::span<const TetId>(shortest_) : std::span<const TetId>();
  }
  // After find() on an edge singularity: what each of its candidates' set tests said (left,
  // right, whole), as an EdgeSearchTally configuration; kNoConfiguration otherwise.
  static constexpr std::uint16_t kNoConfiguration = 0xFFFF;
  [[nodiscard]] std::uint16_t edge_configuration() const { return edge_configuration_; }
  // Working sizes, allocated and touched now (a larger search grows them once).
  void reserve();

 private:
  // Tests base + extra; keeps it in `out` when removable and smaller than what `out` holds.
  // `tested`: what a test of base alone found, if there was one. The verdict is an edge
  // candidate's (kVertexOfSide for any vertex off `edge`, which the vertex case ignores).
  EdgeCandidateVerdict consider(const TetMesh& mesh, SetRemovalWorkspace& ws, std::span<const TetId> base,
                std::span<const TetId> extra, std::uint32_t max_set_size, std::vector<TetId>& out,
                TestedPrefix tested = {}, Edge edge = {});
  std::vector<TetId> base_, candidate_, parts_;
  std::vector<TetId> ends_;      // the border tets the breadth-first search reached
  std::vector<TetId> shortest_;  // T and the first (shortest) path
  bool path_found_ = false;      // shortest_ holds it
  std::uint16_t edge_configuration_ = kNoConfiguration;
  std::vector<std::uint32_t> sizes_;
};

// The shortest path of paper 3.5 (figure 4) from t to the border of v's shell, t excluded,
// nearest to t first: what 3.7 refines along. False when none is within max_depth.
bool shortest_path_to_border(const TetMesh& mesh, SetRemovalWorkspace& ws, TetId t, VertId v, int max_depth,
                             std::vector<TetId>& path);

// The tets around edge (a, b) other than t, split by t into the two runs of the open ring:
// appended to `tets`, run after run, with the runs' sizes in `sizes` (paper 3.5: the leftmost
// and rightmost tets).
void sides_of_edge(const TetMesh& mesh, SetRemovalWorkspace& ws, TetId t, VertId a, VertId b, std::vector<TetId>& tets,
                   std::vector<std::uint32_t>& sizes);

}  // namespace tetcut::detail
