// The statistics of the paper's Tables 1 and 2 (3.3, 3.6), as a Cutter's removals accumulate
// them (Cutter::removal_report()).
//
// Counted per distinct tet: a tet requested again after being left unresolved is not counted
// again (its final fate replaces the first one). Two denominators for the cardinality of the
// removed sets: per request (the sets' mean size) and per selected tet (tets removed over the
// selected tets they took, since a neighbour set often swallows selected tets that are then
// never requested). The paper's "average number of tetrahedra removed when a single
// tetrahedron should be removed" (3.6) is the second.
#pragma once

#include <array>
#include <cstdint>

namespace tetcut {

// Paper 3.5 at an edge singularity (case 3: T's edge e on the surface, T inside the open ring of
// tets around e): T with the tets on one side of it around e ("left", the first run in the
// ring's rotation order), with those on the other side ("right"), then, when neither is
// removable, with all of them ("whole"). What the set test said about each candidate, and where
// it failed (to show why 3.5 leaves so many edge singularities to 3.7). "At an end":
// the offending vertex is an end of e, or the offending edge has one; T's vertices off e are
// its two ring neighbours.
enum class EdgeCandidateVerdict : std::uint8_t {
  kRemovable,        // the set test passed
  kSkipped,          // not tested: a removable candidate no larger was found first
  kTooLarge,         // not tested: more tets than RemovalOptions::max_set_size
  kVertexAtEnd,      // failed: an end of e would be singular
  kVertexOfT,        // failed: one of T's two vertices off e would be singular
  kVertexOfSide,     // failed: another vertex of the side's tets would be singular
  kEdgeAtEnd,        // failed: an edge through an end of e would keep two runs of tets
  kEdgeElsewhere,    // failed: an edge away from e's ends would keep two runs of tets
};
inline constexpr int kEdgeCandidateVerdicts = 8;

const char* to_string(EdgeCandidateVerdict verdict);

// One count per configuration (left, right, whole verdicts) over the distinct edge
// singularities the paper's search (3.5, in the neighbours and combined strategies) met: a
// fixed array, so counting costs an increment and the report stays a flat value.
struct EdgeSearchTally {
  static constexpr int kConfigurations = kEdgeCandidateVerdicts * kEdgeCandidateVerdicts * kEdgeCandidateVerdicts;
  std::array<std::uint64_t, kConfigurations> counts{};

  static constexpr std::uint16_t configuration(EdgeCandidateVerdict left, EdgeCandidateVerdict right,
                                               EdgeCandidateVerdict whole) {
    return static_cast<std::uint16_t>((static_cast<int>(left) * kEdgeCandidateVerdicts + static_cast<int>(right)) *
                                          kEdgeCandidateVerdicts +
                                      static_cast<int>(whole));
  }
  // The candidate's verdict in a configuration: 0 left, 1 right, 2 whole.
  static constexpr EdgeCandidateVerdict verdict(std::uint16_t configuration, int candidate) {
    int v = configuration;
    for (int k = candidate; k < 2; ++k) v /= kEdgeCandidateVerdicts;
    return static_cast<EdgeCandidateVerdict>(v % kEdgeCandidateVerdicts);
  }
  [[nodiscard]] std::uint64_t total() const;
  bool operator==(const EdgeSearchTally&) const = default;
};

// What a transaction's removal requests did, request by request: a tet requested again after an
// earlier request left it counts again (RemovalReport counts distinct tets, as the paper's tables
// do). The Remover adds each request here and to its RemovalReport in one tally; a CutReport is
// one of these.
struct RequestCounts {
  std::uint32_t requests = 0;        // removal requests made (a tet a set swallowed is not requested)
  std::uint32_t tets_removed = 0;    // tets the requests removed, neighbour sets and refined pieces included
  // How the requested tets stood when first requested (a repeated request is not counted again):
  // removable on their own, or a vertex or an edge singularity.
  std::uint32_t direct = 0, vertex_singularities = 0, edge_singularities = 0;
  // How each request that was not direct ended; unresolved: left in place, a tet left twice
  // counting twice.
  std::uint32_t resolved_by_neighbours = 0, resolved_by_refinement = 0, resolved_by_fallback = 0, unresolved = 0;
  // Requests left in place because the cut's tet budget (CutParams::max_tets_created) had run
  // out, not in `unresolved`: the strategy did not fail, the cut stopped it. In a cut that ends
  // ok only a kept piece's request ends so (its tets are in left_in_tool); any other refuses the
  // cut.
  std::uint32_t stopped_by_budget = 0;
  bool operator==(const RequestCounts&) const = default;
};

struct RemovalReport {
  std::uint64_t requested = 0;             // distinct tets requested
  std::uint64_t repeated_requests = 0;     // requests for a tet already left unresolved
  std::uint64_t removed = 0;               // requested tets that went (by any way)
  std::uint64_t unresolved = 0;
  std::uint64_t stopped_by_budget = 0;     // distinct tets left only because the budget ran out
  std::uint64_t direct = 0;
  std::uint64_t vertex_singularities = 0;
  std::uint64_t edge_singularities = 0;
  std::uint64_t resolved_by_neighbours = 0;
  std::uint64_t vertex_resolved_by_neighbours = 0;
  std::uint64_t edge_resolved_by_neighbours = 0;
  std::uint64_t resolved_by_refinement = 0;            // 3.4 or 3.7
  std::uint64_t resolved_by_optimized_refinement = 0;  // ... of which 3.7
  std::uint64_t resolved_by_fallback = 0;              // the normal-surface construction
  std::uint64_t neighbour_set_tets = 0;         // sum of the sets removed by neighbours
  std::uint64_t vertex_neighbour_set_tets = 0;
  std::uint64_t edge_neighbour_set_tets = 0;
  std::uint64_t selected_in_sets = 0;           // selected tets among the direct and neighbour sets
  std::uint64_t tets_removed = 0;               // all tets removed, refined children included
  std::uint64_t tets_created = 0;               // by refinement
  std::uint64_t edges_split = 0;
  std::uint64_t attempts_undone = 0;            // 3.4 / 3.7 attempts rolled back to the fallback
  // Fallbacks the splitter refused (a child the exact predicate finds flat: a sliver's split at
  // its midpoint), the request then left unresolved; the budget's refusals are not counted here.
  std::uint64_t fallback_refused = 0;
  // Table 1's population as the paper titles it ("removing a tetrahedron on the mesh surface"):
  // the distinct requested tets that had a face on the surface when requested, and their fates.
  std::uint64_t surface_requested = 0;
  std::uint64_t surface_direct = 0;
  std::uint64_t surface_vertex_singularities = 0;
  std::uint64_t surface_edge_singularities = 0;
  // Each distinct edge singularity 3.5 searched (neighbours, combined; not basic or wide), by
  // what its left, right and whole candidates' set tests said.
  EdgeSearchTally edge_search;

  // Tets removed per request over the requests removed without refinement (1 for a direct
  // removal). 0 when there are none.
  [[nodiscard]] double mean_cardinality() const;
  // Tets removed per selected tet they took, over the same sets: the paper's 1.3 (3.6).
  [[nodiscard]] double cardinality_per_selected() const;
  bool operator==(const RemovalReport&) const = default;
  // Adds another run's counts (a scenario that reloads or compacts its mesh has several).
  RemovalReport& operator+=(const RemovalReport& other);
};

}  // namespace tetcut
