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
// kBasic, kCombined and kWide end with a construction that always succeeds
// (docs/removal-proof.md) unless a split is refused for degeneracy or the cut's tet budget.
enum class RemovalStrategy : std::uint8_t { kBasic, kNeighbours, kCombined, kWide };

const char* to_string(RemovalStrategy strategy);
// "basic", "neighbours" (or "neighbors"), "combined", "wide".
std::optional<RemovalStrategy> parse_removal_strategy(std::string_view text);

// In which order a cut requests its selected tets (T_removal, paper 3.3):
//   kDirectFirst  every directly removable selected tet first, again until none is left, then
//                 one stuck tet (on the surface first), and again. The default: a strategy's
//                 larger set then meets fewer singularities.
//   kPaper        "removing one-by-one all tetrahedra in T_removal" (3.3): the next request is
//                 the first pending selected tet, in T_removal's order, that has a face on the
//                 surface (the cautery works from the surface in, and Table 1 is about
//                 "removing a tetrahedron on the mesh surface"); a tool inside the mesh, with
//                 none on the surface, takes the first pending one. Removable or not, it is
//                 requested as it comes.
enum class RemovalOrder : std::uint8_t { kDirectFirst, kPaper };

const char* to_string(RemovalOrder order);
// "direct-first", "paper".
std::optional<RemovalOrder> parse_removal_order(std::string_view text);

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
