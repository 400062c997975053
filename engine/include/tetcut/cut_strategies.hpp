// The choices a cut offers besides its sizes (CutParams, cut.hpp): how a tet that cannot go
// alone is removed (paper 3.4-3.7), which tets the refinement splits and how it splits edges
// (paper 3.2).
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

namespace tetcut {

// When removing a tet alone would make a vertex or an edge singular:
//   kNeighbours  the paper's neighbour search (3.5): remove a small removable set around it;
//                may leave the tet in place (counted as unresolved, the mesh still valid).
//   kBasic       split every edge at the singularity, then remove the small tets there (3.4).
//   kCombined    neighbours, else the optimized local refinement (3.7). The default.
//   kWide        ours, not the paper's: a broader search in place of 3.5, then as combined.
// kBasic, kCombined and kWide end with a construction that always succeeds topologically
// (docs/removal-proof.md) unless a split is refused for degeneracy or the cut's tet budget, or
// its set holds an uncuttable tet (Cutter::set_uncuttable: the set is refused); the quality
// floor can still refuse the whole cut (CutRefusal::kQualityFloor).
enum class RemovalStrategy : std::uint8_t { kBasic, kNeighbours, kCombined, kWide };

const char* to_string(RemovalStrategy strategy);
// "basic", "neighbours" (or "neighbors"), "combined", "wide".
std::optional<RemovalStrategy> parse_removal_strategy(std::string_view text);

// In which order a cut requests its selected tets (T_removal, paper 3.3). The paper gives none
// ("removing one-by-one all tetrahedra in T_removal"); these are three readings of it:
//   kDirectFirst        every directly removable selected tet first, again until none is left,
//                       then one stuck tet (on the surface first), and again. The default: a
//                       strategy's larger set then meets fewer singularities.
//   kSurfaceFirstById   the next request is the first pending selected tet, in T_removal's order
//                       (by when it was selected, then by id), that has a face on the surface
//                       (the cautery works from the surface in, and Table 1 is about "removing a
//                       tetrahedron on the mesh surface"); a tool inside the mesh, with none on
//                       the surface, takes the first pending one. Removable or not, it is
//                       requested as it comes, once. Spelled "paper" before: an alias still.
//   kRevisit            as kSurfaceFirstById, but a tet that is not removable and that the
//                       neighbour search (3.5) cannot take is put off, not refined: it is met
//                       again after the next removal (which may have made it removable), and
//                       counted once, by its first verdict (the paper: "if a non-removable
//                       tetrahedra is encountered several times it is only counted once"). Only
//                       when every pending tet is put off does the first one go to the whole
//                       strategy (3.7's refinement, the fallback).
enum class RemovalOrder : std::uint8_t {
  kDirectFirst,
  kSurfaceFirstById,
  kRevisit,
  kPaper = kSurfaceFirstById,  // the old name
};

const char* to_string(RemovalOrder order);
// "direct-first", "surface-first-by-id" (or "paper", its old name), "revisit".
std::optional<RemovalOrder> parse_removal_order(std::string_view text);

// Which set the neighbour search (paper 3.5) removes when several of its candidates are
// removable. The paper's text fits both: "the smallest set of neighboring tetrahedra" and "when
// a path is found, its removability is tested and, when successful, the set is removed".
//   kSmallest  go on through the further paths (and their extensions) while they could give a
//              smaller set, and keep the smallest; for an edge, the smaller of the left and the
//              right side. The default (its tables and pinned hashes are this reading's).
//   kFirst     stop at the first removable candidate, in the search's order (shortest path
//              first, then its extensions; left side, right side, whole ring).
enum class NeighbourSetChoice : std::uint8_t { kSmallest, kFirst };

const char* to_string(NeighbourSetChoice choice);
// "smallest", "first".
std::optional<NeighbourSetChoice> parse_neighbour_set_choice(std::string_view text);

// kTemplates: every marked edge of a tet at once, by the tet's split template (paper 3.2).
// kBisection: one edge at a time across its whole shell (the baseline the templates beat).
enum class SplitMethod : std::uint8_t { kTemplates, kBisection };

const char* to_string(SplitMethod method);
// "templates", "bisection".
std::optional<SplitMethod> parse_split_method(std::string_view text);

// Which refinement makes the tets the tool meets short enough to select (edges <= D_ref):
//   kPaper   paper 3.2: the edges of the tets in reach longer than D_ref, plus the shell edges
//            longer than p x |e|, split by the templates, round after round. Its tables and
//            pinned hashes are this rule's. The default.
//   kGraded  Rivara's longest-edge bisection, restricted to the tets meeting the tool: each is
//            refined by bisecting the terminal edge of its longest-edge propagation path, so the
//            tets made grade outward from the tool instead of splitting coarse neighbours across
//            their long edges (refine/longest_edge_bisection.hpp).
//   kAuto    graded when the tool is fine for the mesh (D_ref below three quarters of its mean
//            edge: the tets it meets need halving more than once), the paper's loop otherwise.
//            Decided per Cutter from the mesh's scale (measured when it is indexed), not per cut;
//            and a cut the paper's loop left with tets the improvement pass cannot lift is made
//            again with the graded rule (CutReport::retries), at the same D_ref.
//            The default: the paper's loop where it serves (a tool about the mesh's edge or
//            coarser, where its tets are fewer and its tables and hashes are), the graded one
//            where the paper's makes slivers no improvement lifts (bench/quality_sweeps.cpp).
enum class RefinementRule : std::uint8_t { kPaper, kGraded, kAuto };

const char* to_string(RefinementRule rule);
// "paper", "graded", "auto".
std::optional<RefinementRule> parse_refinement_rule(std::string_view text);

}  // namespace tetcut
