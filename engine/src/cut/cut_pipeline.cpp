// The cut pipeline behind Cutter (cut.hpp): locate, refine, select, remove.
#include "cut/cut_pipeline.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "core/quality.hpp"
#include "cut/planted_slowdown.hpp"
#include "tetcut/detail/local_tables.hpp"
#include "tetcut/detail/reserve_touched.hpp"

namespace tetcut {
namespace {

using Clock = std::chrono::steady_clock;

double micros(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double, std::micro>(b - a).count();
}

// One request in the cut's counts. Per request, except what the Remover's statistics count per
// distinct tet: a tet an earlier cut left unresolved was counted as a direct removal or a
// singularity then, not again.
void count_request(CutReport& report, const RemovalResult& r) {
  if (!r.repeat) {
    report.vertex_singularities += r.first.kind == SingularityKind::kVertex ? 1 : 0;
    report.edge_singularities += r.first.kind == SingularityKind::kEdge ? 1 : 0;
  }
  if (r.outcome != RemovalOutcome::kUnresolved) report.tets_removed += r.tets_removed;
  switch (r.outcome) {
    case RemovalOutcome::kDirect: report.direct += r.repeat ? 0 : 1; break;
    case RemovalOutcome::kNeighbours: ++report.resolved_by_neighbours; break;
    case RemovalOutcome::kRefinement: ++report.resolved_by_refinement; break;
    case RemovalOutcome::kFallback: ++report.resolved_by_fallback; break;
    case RemovalOutcome::kUnresolved: ++report.unresolved; break;
  }
}

RemovalOptions removal_options(const CutParams& p) {
  RemovalOptions o;
  o.strategy = p.strategy;
  o.max_path_depth = static_cast<int>(p.search_depth);
  return o;
}
}  // namespace

Cutter::Pipeline::Pipeline(TetMesh& mesh, const CutParams& params)
    // The grid's cell is the mean edge length, so that a tet spans a few cells at most.
    : mesh_(mesh), params_(params), remover_(removal_options(params)), index_(mesh.mean_edge_length()) {
  index_.build(mesh_);
  epoch_ = mesh_.id_epoch();
  scale_ = measure_scale(mesh_);
  invalid_ = validate(params_);
  judge_scale();
  prepare();
}

void Cutter::Pipeline::prepare() {
  using detail::reserve_touched;
  // Headroom of half the mesh again: cuts grow it (refinement creates more than removal takes)
  // and a reallocation of a million-tet array in the middle of a cut is a latency spike.
  const std::uint32_t tets = mesh_.tet_capacity() + mesh_.tet_capacity() / 2 + 4096;
  const std::uint32_t vertices = mesh_.vertex_capacity() + mesh_.vertex_capacity() / 2 + 1024;
  mesh_.reserve(tets, vertices);
  refiner_.reserve(tets);
  remover_.reserve(tets, vertices);
  improver_.reserve(tets);
  uncuttable_.reserve(tets);
  for (auto* marks : {&selected_, &tissue_, &tried_, &queued_}) marks->reserve(tets);
  // The working size of a cut's lists; a larger cut grows them once (allocations per cut are
  // gated by ci/bench).
  constexpr std::size_t kCutScratch = 16384;
  for (auto* list : {&work_, &removal_, &hit_, &region_, &net_removed_, &net_created_, &changes_.removed, &changes_.parents})
    reserve_touched(*list, kCutScratch);
  reserve_touched(changes_.created, kCutScratch);
  reserve_touched(changes_.vertices, kCutScratch);
  reserve_touched(changes_.removed_vertices, kCutScratch);
}

void Cutter::Pipeline::reset() {
  index_.build(mesh_, mesh_.mean_edge_length());
  epoch_ = mesh_.id_epoch();
  scale_ = measure_scale(mesh_);
  judge_scale();
  remover_.reset();
  uncuttable_.clear();  // the ids it named are another mesh's
  clear_marks();
  prepare();
}

std::optional<std::string> Cutter::Pipeline::set_params(const CutParams& params) {
  if (auto invalid = validate(params)) return invalid;
  const bool removal_changed = params.strategy != params_.strategy || params.search_depth != params_.search_depth;
  params_ = params;
  invalid_.reset();
  judge_scale();
  if (removal_changed) remover_.set_options(removal_options(params_));
  return std::nullopt;
}

void Cutter::Pipeline::judge_scale() {
  refusal_ = invalid_ ? invalid_ : check_scale(scale_, params_.tool_diameter, params_.d_ref_factor, params_.max_tets_created);
}

std::optional<std::string> Cutter::Pipeline::stale() const {
  if (indexes_current_mesh()) return std::nullopt;
  return "the mesh was compacted or replaced since this Cutter indexed it: compact with Cutter::compact(), "
         "or call Cutter::reset() after replacing the mesh";
}

TetId Cutter::Pipeline::tet_containing(const Vec3& p) {
  if (!indexes_current_mesh()) return kNoTet;
  index_.query(mesh_, Ball{p, 0.0}, hit_);
  return hit_.empty() ? kNoTet : hit_.front();
}

void Cutter::Pipeline::clear_marks() {
  for (auto* marks : {&selected_, &tissue_, &tried_, &queued_}) marks->clear();
}

// Paper 3.3: inside the tool (centroid in the closed ball) and no edge longer than D_ref.
bool Cutter::Pipeline::selectable(TetId t) const {
  if (!tool_) return false;
  const auto v = mesh_.tet(t);
  Vec3 centroid{};
  for (VertId x : v) centroid = centroid + 0.25 * mesh_.position(x);
  if (norm(centroid - tool_->centre) > tool_->radius) return false;
  for (int e = 0; e < 6; ++e)
    if (norm(mesh_.position(v[kEdgeVerts[e][1]]) - mesh_.position(v[kEdgeVerts[e][0]])) > d_ref_) return false;
  return true;
}

bool Cutter::Pipeline::pending(TetId t) const { return mesh_.is_live(t) && selected_.contains(t) && !tried_.contains(t); }

void Cutter::Pipeline::follow(const TetMesh::Savepoint& point) {
  for (const TetMesh::TetBirth& birth : mesh_.tets_made_since(point)) {
    // Selection is decided once, on the refined region (paper 3.3): a piece of a selected tet is
    // selected tissue, a piece of a kept tet stays kept wherever its centroid falls (else every
    // split at the ball's edge would select finer and finer pieces of kept tissue, and 3.4,
    // which splits around every singularity, would run away). A piece of selected tissue inside
    // the tool joins T_removal. The journal lists parents before children, so a parent's marks
    // are set when its children are seen.
    const auto parents = mesh_.parents(birth);
    if (!std::any_of(parents.begin(), parents.end(), [&](TetId p) { return tissue_.contains(p); })) continue;
    tissue_.insert(birth.tet);
    if (mesh_.is_live(birth.tet) && selectable(birth.tet)) {
      selected_.insert(birth.tet);
      removal_.push_back(birth.tet);
    }
  }
}

CutReport Cutter::Pipeline::cut(const Vec3& centre, ChangeLog* log) {
  CutReport report;
  net_removed_.clear();
  net_created_.clear();
  auto invalid = stale();
  if (!invalid) invalid = refusal_;
  if (invalid) {
    report.ok = false;
    report.failure = *invalid;
    return report;
  }
  const Clock::time_point start = Clock::now();
  detail::planted_slowdown();
  const Ball tool{centre, params_.tool_diameter / 2};
  double d_ref = params_.d_ref_factor * params_.tool_diameter;
  for (std::uint32_t retry = 0;; ++retry) {
    report = attempt(tool, d_ref, log);
    report.coarser_retries = retry;
    report.time.total_us = micros(start, Clock::now());
    // Only the floor is worth another try: a coarser D_ref makes fewer, larger tets, which the
    // pass lifts where the fine ones defeated it. A refusal for the budget or a degeneracy is final.
    const bool floor_unmet = !report.ok && params_.improve && !report.quality_met;
    if (!floor_unmet || retry == params_.coarser_retries) return report;
    d_ref *= 2;
  }
}

CutReport Cutter::Pipeline::attempt(const Ball& tool, double d_ref, ChangeLog* log) {
  CutReport report;
  report.d_ref = d_ref;
  net_removed_.clear();
  net_created_.clear();
  const Clock::time_point t0 = Clock::now();

  // Locate (paper 3.1).
  index_.query(mesh_, tool, hit_);
  report.tets_hit = static_cast<std::uint32_t>(hit_.size());
  const Clock::time_point t1 = Clock::now();
  report.time.locate_us = micros(t0, t1);
  if (hit_.empty()) {
    report.time.total_us = report.time.locate_us;
    return report;
  }

  begin();
  tool_ = tool;
  d_ref_ = d_ref;
  removal_.clear();
  auto fail = [&](std::string why) {
    roll_back();
    report.ok = false;
    report.failure = std::move(why);
    net_removed_.clear();
    net_created_.clear();
    report.time.total_us = micros(t0, Clock::now());
    return report;
  };

  // Refine (paper 3.2), following the new tets that meet the tool.
  RefineParams refine;
  refine.d_ref = d_ref;
  refine.p = params_.p;
  refine.max_iterations = params_.max_refine_iterations;
  refine.method = params_.split_method;
  refine.focus = tool;
  refine.max_tets_created = params_.max_tets_created;  // checked before each round (net)
  refine.measure_quality = false;  // finish() reports the worst net new tet
  const RefineReport refined = refiner_.refine(mesh_, hit_, refine, region_);
  if (refined.refusal != SplitRefusal::kNone)
    return fail(std::string("refinement refused: ") + to_string(refined.refusal));
  report.refine_iterations = refined.iterations;
  report.edges_split = refined.edges_split;
  report.tets_refined = refined.tets_removed;
  const Clock::time_point t2 = Clock::now();
  report.time.refine_us = micros(t1, t2);

  // Select T_removal (paper 3.3).
  for (TetId t : region_) {
    // region_ is live and distinct, the refinement's children included (Refiner::refine): each
    // is tested once. Nothing is tissue before this, so there is nothing to follow() yet.
    if (!selectable(t)) continue;
    if (uncuttable_.contains(mesh_, t)) {
      ++report.uncuttable_in_tool;
      continue;
    }
    selected_.insert(t);
    tissue_.insert(t);
    removal_.push_back(t);
  }
  const Clock::time_point t3 = Clock::now();
  report.time.select_us = micros(t2, t3);

  // Remove (paper 3.3-3.7).
  remove_selected(report);
  if (!report.ok) return fail(report.failure);
  const Clock::time_point t4 = Clock::now();
  report.time.remove_us = micros(t3, t4);
  improve(report);
  report.time.improve_us = micros(t4, Clock::now());
  if (!report.quality_met && params_.improve) return fail(floor_failure(report));
  count_left_in_tool(report);
  finish(report, log);
  report.time.total_us = micros(t0, Clock::now());
  return report;
}

CutReport Cutter::Pipeline::remove(TetId t, ChangeLog* log) {
  CutReport report;
  net_removed_.clear();
  net_created_.clear();
  if (auto invalid = stale()) {
    report.ok = false;
    report.failure = *invalid;
    return report;
  }
  if (!mesh_.is_live(t)) {
    report.ok = false;
    report.failure = "tet " + std::to_string(t.value) + " is not live";
    return report;
  }
  if (uncuttable_.contains(mesh_, t)) {
    report.ok = false;
    report.failure = "tet " + std::to_string(t.value) + " is uncuttable";
    return report;
  }
  const Clock::time_point t0 = Clock::now();
  begin();
  tool_.reset();  // no tool: the request alone, no children join it
  removal_.assign(1, t);
  selected_.insert(t);
  tissue_.insert(t);
  remove_selected(report);
  if (!report.ok) {
    roll_back();
    return report;
  }
  const Clock::time_point t1 = Clock::now();
  report.time.remove_us = micros(t0, t1);
  improve(report);
  report.time.improve_us = micros(t1, Clock::now());
  if (!report.quality_met && params_.improve) {
    roll_back();
    report.ok = false;
    report.failure = floor_failure(report);
    return report;
  }
  finish(report, log);
  report.time.total_us = micros(t0, Clock::now());
  return report;
}

void Cutter::Pipeline::begin() {
  mesh_.begin_transaction();
  cut_start_ = mesh_.savepoint();
  clear_marks();
  removal_at_start_ = remover_.report();
}

void Cutter::Pipeline::roll_back() {
  mesh_.rollback();
  remover_.restore_report(removal_at_start_);
}

void Cutter::Pipeline::remove_selected(CutReport& report) {
  if (tool_ && removal_.size() == mesh_.num_tets()) {
    // The tool holds every tet (each selected one is live and counted once): removing the whole
    // mesh leaves nothing that could pinch, so it goes at once, in O(#T), instead of tet by tet.
    mesh_.remove_tets(removal_);
    report.requested = report.tets_removed = static_cast<std::uint32_t>(removal_.size());
    return;
  }
  // A cut the budget refuses is rolled back and reports none of its requests.
  const CutReport before = report;
  // The tets to test for a direct removal: every selected tet once, then what each request
  // exposes or selects. Removal only turns faces, edges and vertices into boundary ones, so a tet
  // that is not removable becomes removable only when it gains a boundary face, i.e. when a face
  // neighbour goes, which exposes it: one pass over a worklist instead of passes over T_removal.
  work_.clear();
  std::size_t head = 0;
  auto enqueue = [&](TetId t) {
    if (!pending(t) || !queued_.insert(t)) return;
    work_.push_back(t);
  };
  for (TetId t : removal_) enqueue(t);
  // `first`: removability(mesh_, t), just computed.
  // `pieces`: follow what the request made (the selection's loop); off for the leftovers below.
  auto request = [&](TetId t, const Removability& first, bool pieces = true) {
    tried_.insert(t);
    ++report.requests;
    RequestLimits limits;
    limits.max_tets_created = params_.max_tets_created > net_made() ? params_.max_tets_created - net_made() : 0;
    limits.selection = &selected_;
    limits.uncuttable = &uncuttable_;
    const std::size_t selected_before = removal_.size();
    const TetMesh::Savepoint before_request = mesh_.savepoint();
    const RemovalResult r = remover_.remove(mesh_, t, first, limits);
    if (pieces) {
      follow(before_request);
      for (std::size_t i = selected_before; i < removal_.size(); ++i) enqueue(removal_[i]);
      for (TetId e : remover_.last_exposed()) enqueue(e);
    }
    if (r.over_budget || net_made() > params_.max_tets_created) {
      report = before;
      report.ok = false;
      report.failure = "the removal would exceed the per-cut tet budget";
      return false;
    }
    count_request(report, r);
    return true;
  };
  // The paper's order (cut_strategies.hpp): the first pending tet on the surface, else the
  // first pending, each requested as it comes. T_removal grows at its end (followed pieces).
  auto next_pending = [&] {
    for (TetId t : removal_)
      if (pending(t) && mesh_.boundary_face_count(t) > 0) return t;
    for (TetId t : removal_)
      if (pending(t)) return t;
    return kNoTet;
  };
  if (params_.order == RemovalOrder::kPaper) {
    for (TetId t = next_pending(); t.valid(); t = next_pending())
      if (!request(t, removability(mesh_, t))) return;
    work_.clear();
  }
  for (;;) {
    // Every directly removable selected tet first, until none is left (paper 3.3): a strategy's
    // larger set then meets fewer singularities.
    while (head < work_.size()) {
      const TetId t = work_[head++];
      queued_.erase(t);
      if (!pending(t)) continue;
      const Removability first = removability(mesh_, t);
      if (!first.removable()) continue;
      if (!request(t, first)) return;
    }
    // Then one stuck tet, outside in: on the surface first (the paper's statistics are about
    // "removing a tetrahedron on the mesh surface", 3.3), else any (a tool inside the mesh).
    const TetId stuck = next_pending();
    if (!stuck.valid()) break;
    if (!request(stuck, removability(mesh_, stuck))) return;
  }
  report.requested = static_cast<std::uint32_t>(removal_.size());
  if (!tool_) return;

  // Pieces of kept tets inside the tool: a removal-time split (3.4, 3.7, the fallback) cuts
  // unselected neighbours too, and a piece whose centroid falls in the ball is tissue in the tool
  // that follow() does not select (selecting it would cascade, each request splitting further
  // kept tets). Each such piece is requested once, what its own request makes is not followed,
  // and what stays is counted: a report with nothing unresolved and nothing left in the tool
  // means the tool is empty.
  work_.clear();
  for (const TetMesh::TetBirth& birth : mesh_.tets_made_since(cut_start_))
    if (piece_in_tool(birth.tet)) work_.push_back(birth.tet);
  for (TetId t : work_) {
    if (!mesh_.is_live(t) || tried_.contains(t)) continue;
    ++report.kept_pieces_requested;
    if (!request(t, removability(mesh_, t), false)) return;
  }
}

bool Cutter::Pipeline::piece_in_tool(TetId t) const {
  // A piece of an uncuttable tet is not tissue to take, however it lies.
  return mesh_.is_live(t) && !tissue_.contains(t) && selectable(t) && !uncuttable_.contains(mesh_, t);
}

void Cutter::Pipeline::count_left_in_tool(CutReport& report) {
  // After the improvement pass, whose flips and collapses make tets too. The tets that were there
  // before the cut and meet the tool were all selected (and went, or count as unresolved).
  for (const TetMesh::TetBirth& birth : mesh_.tets_made_since(cut_start_))
    if (piece_in_tool(birth.tet)) ++report.left_in_tool;
}

std::string Cutter::Pipeline::floor_failure(const CutReport& report) {
  char text[320];
  std::snprintf(text, sizeof text,
                "the quality floor could not be met: a created tet has radius ratio %.3g, below %.3g = min(quality_floor, "
                "the worst tet replaced); a lower quality_floor, or improve off, lets such a cut through",
                report.min_radius_ratio, report.quality_floor);
  return text;
}

void Cutter::Pipeline::improve(CutReport& report) {
  // The cut's reach: the tool's ball grown by D_ref, the longest edge its refinement leaves at
  // the ball (refine.hpp); the cut's own surface and its made tets lie within it.
  const std::optional<Ball> reach =
      tool_ ? std::optional<Ball>(Ball{tool_->centre, tool_->radius + d_ref_}) : std::nullopt;
  const detail::ImproveOutcome outcome =
      improver_.run(mesh_, cut_start_, params_.quality_floor, params_.improve, reach ? &*reach : nullptr, &uncuttable_);
  report.tets_removed += outcome.removed;
  report.min_radius_ratio_before_improvement = outcome.worst_before;
  report.min_radius_ratio = outcome.worst_after;  // the worst net new tet: the made tets still live
  report.quality_floor = outcome.floor;
  report.quality_met = outcome.met;
  report.improvement_flips = outcome.flips;
  report.improvement_collapses = outcome.collapses;
  report.improvement_moves = outcome.moves;
}

// Commits the transaction, brings the index up to date with the net changes, hands the caller
// the net change (the journal derives it), and reports the worst new tet.
void Cutter::Pipeline::finish(CutReport& report, ChangeLog* log) {
  uncuttable_.before_commit(mesh_, cut_start_);
  if (log) {
    changes_.clear();
    mesh_.commit(&changes_);
    net_removed_.assign(changes_.removed.begin(), changes_.removed.end());
    net_created_.clear();
    for (const CreatedTet& c : changes_.created) net_created_.push_back(c.tet);
    append(*log, changes_);
  } else {
    // Nobody reads the parents and origins: the ids alone, for the index.
    mesh_.transaction_changes(net_removed_, net_created_);
    mesh_.commit();
  }
  uncuttable_.after_commit(mesh_);
  for (TetId t : net_removed_) index_.erase(t);
  for (TetId t : net_created_) index_.insert(mesh_, t);
  report.tets_created = static_cast<std::uint32_t>(net_created_.size());
}

}  // namespace tetcut
