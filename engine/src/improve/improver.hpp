// The improvement pass that ends every Cutter transaction (a cut, a removal request): local mesh
// improvement of the tets the transaction made, until each reaches its own floor (I7,
// invariants/check.hpp, QualityRule::kNoDegradation): a radius ratio of at least min(F, its
// host's) and a smallest dihedral angle of at least min(theta, its host's).
//
// The floors are the checker's, computed the engine's way: a made tet's host is the tet that was
// there before the transaction and holds it (its one ancestor in the journal after splits, the
// ancestor containing its centroid after flips: core/host_location.hpp). Each made tet has its
// own: one poor host lowers the bar for the tets inside it, not for every tet the cut makes. A
// made tet at or above F and theta needs no host. Then, worst made tet first (quality(), which
// weighs both terms), the operations Klingner and Shewchuk's Stellar combines, every
// one a Plan (operation.hpp) made on the const mesh and offered to the pass, which applies the
// one whose worst new tet ends best, and only when it beats the worst tet it replaces:
//   edge removal and the 2-3 flip (flips.hpp), on the tet's edges and faces;
//   collapse of one of the tet's vertices that the transaction made into any neighbour
//   (collapse.hpp);
//   smoothing of the tet's vertices (smoothing.hpp): those the transaction made, and those there
//   before it within the cut's reach when their whole star ends at or above F and theta
//   (old_vertex_rule, old_vertex_move; ChangeLog::moved tells the consumers);
//   and when none of those lifts it, insertion (insertion.hpp): the tet's longest edge split at
//   its midpoint, the new vertex smoothed, kept only when the worst tet of what was split ends
//   better (else rolled back to a savepoint).
// A made tet still below its floor after all that, on the surface, within the cut's reach and
// removable on its own, goes with the tissue (sliver_removal.hpp), reported apart
// (ImproveOutcome::removed).
// And the mesh rule the checker's I7 holds a transaction to: the volume of tets below theta
// outside the tool does not grow. Per-tet floors allow the growth (a made tet is held to the
// angle of the host holding its centroid, so a flip can lift the worst tet by spreading a bad
// host's angle over good volume), so at the end of the pass the transaction is weighed as the
// checker weighs it (grows_bad_volume); when it grew, the caller makes the transaction again
// with every plan held to the rule (bad_volume_rule), which most cuts never need.
// Every plan passes, after its operator's own tests, the run's rules (uncuttable tissue keeps
// its region) and then the caller's hook (plan_veto.hpp), which may veto it; a plan refused for
// any reason is not applied, and the outcome counts why.
// The ops run inside the transaction: the journal records them (a flip's tets get every replaced
// tet as parents, a moved vertex its barycentric origin), so a consumer still sees one net
// change, and a rollback undoes them with the rest.
//
// Cost: local. The tets it starts from are the transaction's (the journal's births), each
// operation is O(its star), and a bound on the operations keeps a pathological cut from looping.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "core/quality.hpp"
#include "core/tool.hpp"
#include "core/uncuttable_tets.hpp"
#include "improve/collapse.hpp"
#include "improve/direct_mapped_memo.hpp"
#include "improve/flips.hpp"
#include "improve/insertion.hpp"
#include "improve/operation.hpp"
#include "improve/plan_veto.hpp"
#include "improve/smoothing.hpp"
#include "remove/tissue_removal.hpp"
#include "tetcut/detail/stamped_property.hpp"
#include "tetcut/mesh.hpp"

namespace tetcut::detail {

// What one run works with.
struct ImproveParams {
  double floor = 0.1;  // F: a made tet's radius ratio must reach min(F, its host's)
  double min_dihedral_deg = 15.0;  // theta: its smallest dihedral angle, min(theta, its host's)
  bool improve = true;  // false: the made tets are only measured against the floor
  // The cut's ball grown by D_ref (none for a removal request), where a sliver may go with the
  // tissue and the cut's surface may move within its tolerance.
  const Tool* reach = nullptr;
  // The cut's tool itself (none for a removal request): the mesh rule counts no tet whose
  // centroid lies in it.
  const Tool* tool = nullptr;
  // Tets the pass must leave as a region (uncuttable_tets.hpp): it flips only among tets all or
  // none of which are uncuttable, moves and collapses no vertex of one, and removes none.
  const UncuttableTets* uncuttable = nullptr;
  // The transaction's removal path (remove/tissue_removal.hpp), through which the slivers go and
  // are tallied with the rest of what it took (none: one of the Improver's own, untallied).
  TissueRemoval* tissue = nullptr;
  // The caller's say over every plan the pass would apply (empty: none).
  PlanVeto veto{};
  // Every plan held to the mesh rule (bad_volume_rule): for a transaction made again because it
  // grew the volume below theta when the rule was only weighed at the end.
  bool hold_plans_to_mesh_rule = false;
};

// The first theta a pass falls back to (ImproveOutcome::min_dihedral_held_deg).
inline constexpr double kFallbackDihedralDeg = 10.0;

struct ImproveOutcome {
  // The lowest floors of the made tets, each min(F or theta, its host's): F and theta themselves
  // when every made tet is above them (the hosts are not looked at).
  double floor = 1.0;
  double dihedral_floor_deg = 180.0;
  double worst_before = 1.0;  // the worst made tet's radius ratio before the pass (1 when none)
  double worst_after = 1.0;   // and after: the worst tet the transaction made
  double min_dihedral_before_deg = 180.0;  // the smallest dihedral angle of a made tet, before
  double min_dihedral_after_deg = 180.0;   // and after (180 when none)
  // The first made tet (worst quality() first) still below its floor after the pass, with its
  // floors: what a refusal names.
  struct Shortfall {
    double radius_ratio = 1.0, ratio_floor = 0.0, min_dihedral_deg = 180.0, dihedral_floor_deg = 0.0;
  };
  Shortfall shortfall;
  // The theta the made tets were held to: ImproveParams::min_dihedral_deg, or lower when the pass
  // could not lift them to it and went on at kFallbackDihedralDeg, then at none; angle_retries
  // counts those runs. A refused cut is worse for a simulation than an angle
  // below theta, and the report says which cut lowered it.
  double min_dihedral_held_deg = 180.0;
  std::uint32_t angle_retries = 0;
  // The transaction grew the volume of tets below theta outside the tool (the mesh rule, weighed
  // when the pass ends unless its plans were held to it): the caller rolls it back and makes it
  // again with ImproveParams::hold_plans_to_mesh_rule.
  bool grew_bad_volume = false;
  std::uint32_t flips = 0, collapses = 0, moves = 0, insertions = 0;
  std::uint32_t removed = 0;  // slivers removed with the tissue
  std::uint32_t vetoed = 0;   // plans the caller's hook vetoed
  // Plans refused, by Refusal (the hook's included): a plan that was made but lifted the tet less
  // than another is not refused, only not chosen.
  std::array<std::uint32_t, kRefusalCount> refused{};
  bool met = true;            // every made tet at or above its floors
};

class Improver {
 public:
  // Working sizes for meshes up to `tets` tet ids, allocated and touched now.
  void reserve(std::uint32_t tets);
  // The tets the open transaction made since `start` (and still has) against min(F, worst host);
  // improved when params.improve, only measured otherwise.
  ImproveOutcome run(TetMesh& mesh, const TetMesh::Savepoint& start, const ImproveParams& params);

 private:
  // A tet's floors: its radius ratio at least `ratio`, its dihedral angles' cosines at most
  // `cosine` (its smallest angle at least acos(cosine)).
  struct Floors {
    double ratio = 0.0, cosine = 1.0;
  };
  // The made tets against F and theta, into `out`'s before and after figures: true when every
  // one is at or above both (nothing to do).
  bool measure(TetMesh& mesh, const TetMesh::Savepoint& start, const ImproveParams& params, ImproveOutcome& out);
  // The pass proper: judge, then lift at theta, kFallbackDihedralDeg and none in turn.
  void lift_to_floors(TetMesh& mesh, const TetMesh::Savepoint& start, const ImproveParams& params, ImproveOutcome& out);
  // The mesh rule over the transaction, as the checker's I7 weighs it: whether the made tets
  // below theta outside the tool cover more volume than the tets below theta that were there
  // before covered of the same region (their shared volumes: core/tet_intersection.hpp).
  bool grows_bad_volume(TetMesh& mesh);
  // Adds to `before` the volume made tet t shares with the tets below theta it descends from, as
  // they were; whether it shares any.
  bool shares_bad_volume(TetMesh& mesh, TetId t, double& before);
  // The made tets still live into made_; their worst radius ratio and largest dihedral cosine.
  std::pair<double, double> collect_made(TetMesh& mesh, const TetMesh::Savepoint& start);
  // Made tet t's floors: F and theta when it reaches them, else min(F or theta, its host's).
  Floors floors_of(TetMesh& mesh, TetId t);
  // Tet `old`'s shape when the transaction began (live then), as Floors: its radius ratio and
  // largest dihedral cosine. Memoized: it never changes within a transaction.
  Floors shape_at_start(TetMesh& mesh, TetId old);
  // Whether made tet t is below its floors (`floors`, when given, receives them). `measured`:
  // its shape as the mesh has it now, when the caller has it (else it is looked up or measured).
  bool below_floor(TetMesh& mesh, TetId t, Floors* floors = nullptr, const TetShape* measured = nullptr);
  // The run's F and theta, and what follows from them.
  void set_theta(double theta_deg, double floor_f);
  // Every made tet against its floors: `out`'s lowest floors, met and shortfall.
  void judge(TetMesh& mesh, ImproveOutcome& out);
  // Operations on the made tets below their floors, worst first, until none helps (counted in
  // `out`, at most kMaxOperations in all), then the slivers that go with the tissue.
  void lift(TetMesh& mesh, ImproveOutcome& out, std::uint32_t& operations);
  // The operation that lifts tet t most, applied: which one, or none when nothing lifts it.
  std::optional<Operator> improve_tet(TetMesh& mesh, TetId t, ImproveOutcome& out);
  // candidate_, just planned (`planned`: kNone, or why not), becomes best_ when it lifts the tet
  // more than best_ does and admit() lets it through.
  void offer(TetMesh& mesh, Refusal planned, ImproveOutcome& out);
  // The run's rules, then the caller's hook, on a plan its operator made; a refusal is counted.
  Refusal admit(TetMesh& mesh, const Plan& plan, ImproveOutcome& out);
  // Uncuttable tissue keeps its region: a flip retriangulates the polytope it replaces, so it only
  // needs tets of one kind; a split child lies in its parent; the other plans touch none.
  Refusal region_rule(TetMesh& mesh, const Plan& plan) const;
  // The checker's mesh rule (I7), plan by plan: the volume of the tets below theta a plan makes
  // is at most that of the tets below theta it removes, both outside the cut's tool (a tet whose
  // centroid is in the tool's open ball counts on neither side, as the checker counts it). Every plan but a sliver removal keeps the
  // polytope it replaces, so the two compare directly; without it the pass lifted a tet by a
  // flip that spread a tet below theta (held to its bad host's angle) over good volume.
  Refusal bad_volume_rule(const TetMesh& mesh, const Plan& plan);
  // The volume of the tets below theta among `tets` (live ids); within rounding of theta does
  // not count (what a plan removes: the rule stays on the strict side of the
  // checker's).
  double bad_volume(const TetMesh& mesh, std::span<const TetId> tets);
  // Whether a tet with these corners has its centroid in the cut's tool (its open ball).
  [[nodiscard]] bool in_tool(const std::array<Vec3, 4>& corners) const;
  // Whether the operations may reshape v's star (move v, collapse v): kNone when v was made by
  // the transaction and none of its tets is uncuttable, else why not. Asked before planning.
  Refusal star_rule(TetMesh& mesh, VertId v);
  // Whether the pass may smooth v, a vertex there before the transaction: kNone when the run has
  // a reach (a cut), v was within it (its start position inside the tool's ball grown by D_ref)
  // and none of its tets is uncuttable. Such a vertex is never collapsed (the organ keeps its
  // input vertices), and moves only as old_vertex_move() allows.
  Refusal old_vertex_rule(TetMesh& mesh, VertId v);
  // A move of such a vertex: kNone when it stays within the reach and its whole star ends at or
  // above F and theta, so that the move makes no tet below the floors anywhere, whatever its
  // hosts were (the tets around an old vertex are mostly tets no cut made, and good).
  Refusal old_vertex_move(const Plan& plan) const;
  // Insertion on t's longest edge, with its new vertex smoothed: kept when it lifts the worst
  // tet around the edge and the hook lets it through, else rolled back.
  bool insert(TetMesh& mesh, TetId t, ImproveOutcome& out);
  // The made tets still below the floor that go with the tissue.
  void remove_slivers(TetMesh& mesh, ImproveOutcome& out);
  // Applies an admitted plan; what it made joins made_.
  void apply(TetMesh& mesh, const Plan& plan);

  Flipper flipper_;
  Collapser collapser_;
  Smoother smoother_;
  Inserter inserter_;
  // The best plan so far for the tet being improved, the plan being offered, and an insertion's.
  Plan best_, candidate_, insertion_;
  double best_after_ = 0.0;  // best_.worst_after, 0 while there is no best_
  bool has_best_ = false;
  std::vector<TetId> star_;
  std::vector<VertId> neighbours_;
  double goal_ = 0.0;                  // quality() at the run's F and theta: a plan lifting a tet
                                       // twice past it is taken without the dearer ones
  double floor_f_ = 0.0;               // the run's F
  double theta_ = 0.0;                 // the run's theta, degrees
  double cos_theta_ = 1.0;             // cos(theta)
  std::vector<std::pair<double, TetId>> made_quality_;  // judge()'s, worst first
  const Tool* tool_ = nullptr;         // the run's reach, if a cut
  const Tool* cut_tool_ = nullptr;     // the cut's tool itself, if a cut
  const UncuttableTets* uncuttable_ = nullptr;  // the run's, if any
  TissueRemoval* tissue_ = nullptr;             // the run's removal path
  TissueRemoval own_tissue_;
  PlanVeto veto_;                               // the run's, if any
  std::vector<TetId> made_, ancestors_, created_;
  std::vector<TetShape> made_shapes_;  // made_'s shapes as collect_made() measured them
  std::vector<std::pair<double, TetId>> bad_;  // (quality, tet), worst first
  // The hosts' shapes (radius ratio, largest dihedral cosine), by host id: a host's shape at the
  // start never changes within a transaction.
  DirectMappedMemo<Floors, 1024> host_shapes_;
  // Each made tet's shape and host, by its birth (TetMesh::birth_index: unique in the
  // transaction, and so are the tet's shape and host, since a move makes its star anew). Every
  // round asks for both again: the shape for each made tet several times a round, the host by a
  // walk of the tet's lines of ancestors, which the smoothing's moves and the flips make long.
  // The births a rollback undoes are forgotten: their indices may come back as other tets.
  struct MadeTet {
    TetShape shape{-1.0, 2.0};  // a ratio below 0: not measured yet
    TetId host;                 // invalid: not located yet
  };
  DirectMappedMemo<MadeTet, 4096> made_tets_;
  // An insertion's removed tets' bad volume, taken before it is applied (admit() sees it after).
  double insertion_bad_before_ = 0.0;
  // Whether plans are held to the mesh rule one by one (bad_volume_rule): only in a pass made
  // again because the first grew the volume below theta (the common pass pays nothing for it).
  bool spread_rule_ = false;
  std::uint32_t old_vertex_plans_ = 0;  // smoothing plans of old vertices left in this pass
  // grows_bad_volume()'s scratch: the made tets outside the tool it weighs last.
  std::vector<TetId> outside_;
  // Made tet t's shape: the memo's, else `measured` (the caller's, as the mesh has it now), else
  // measured here; remembered.
  TetShape shape_of(const TetMesh& mesh, TetId t, const TetShape* measured = nullptr);
  TetId host_of(TetMesh& mesh, TetId t);
};

}  // namespace tetcut::detail
