// The walk of one cut (cut.hpp): each stage entered once, in order, from cut().
#include "cut/cut_pipeline.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "cut/tissue_rule_veto.hpp"
#include "tetcut/detail/reserve_touched.hpp"

namespace tetcut {

// Microseconds since the last lap (the first: since construction).
class Cutter::Pipeline::Laps {
  using Clock = std::chrono::steady_clock;

 public:
  Laps() : start_(Clock::now()), last_(start_) {}
  double lap() {
    const Clock::time_point now = Clock::now();
    const double us = std::chrono::duration<double, std::micro>(now - last_).count();
    last_ = now;
    return us;
  }
  [[nodiscard]] double total() const { return std::chrono::duration<double, std::micro>(Clock::now() - start_).count(); }

 private:
  Clock::time_point start_, last_;
};

namespace {

RemovalOptions removal_options(const CutParams& p) {
  RemovalOptions o;
  o.strategy = p.strategy;
  o.max_path_depth = static_cast<int>(p.search_depth);
  o.neighbour_set = p.neighbour_set;
  return o;
}

}  // namespace

const char* to_string(CutRefusal refusal) {
  switch (refusal) {
    case CutRefusal::kNone: return "none";
    case CutRefusal::kStaleIndex: return "stale index";
    case CutRefusal::kParameters: return "parameters";
    case CutRefusal::kRequest: return "request";
    case CutRefusal::kDegenerateSplit: return "degenerate split";
    case CutRefusal::kTetBudget: return "tet budget";
    case CutRefusal::kQualityFloor: return "quality floor";
    case CutRefusal::kTissueRule: return "tissue rule";
  }
  return "?";
}

Cutter::Pipeline::Pipeline(TetMesh& mesh, const CutParams& params)
    : mesh_(mesh),
      params_(params),
      remover_(removal_options(params)),
      selection_(params_) {
  // The boundary grid's cell is the mean edge length, so that a tet spans a few cells at most.
  locator_.build(mesh_, mesh_.mean_edge_length());
  labels_.build(mesh_);
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
  const std::uint32_t tets = room_for_tets();
  const std::uint32_t vertices = mesh_.vertex_capacity() + mesh_.vertex_capacity() / 2 + 1024;
  mesh_.reserve(tets, vertices);
  refiner_.reserve(tets);
  remover_.reserve(tets, vertices);
  improver_.reserve(tets);
  uncuttable_.reserve(tets);
  selection_.reserve(tets);
  removal_loop_.reserve(tets);
  if (params_.order == RemovalOrder::kRevisit) reserve_revisit();
  audit_.reserve(tets);
  labels_.reserve(tets);
  locator_.reserve(tets);
  reserve_touched(rewired_, 16384);
  search_.reserve(tets, params_.fragment_search_bound);
  reserve_touched(fragments_, 1024);
  transaction_.reserve();
  reserve_history();
  // The working size of a cut's lists; a larger cut grows them once (allocations per cut are
  // gated by ci/bench).
  constexpr std::size_t kCutScratch = 16384;
  for (auto* list : {&hit_, &region_, &removed_, &created_}) reserve_touched(*list, kCutScratch);
}

void Cutter::Pipeline::reserve_history() {
  if (history_.size() != params_.undo_history) {
    history_.clear();  // a ring of another size: its order means nothing in the new one
    history_.resize(params_.undo_history);
    history_top_ = 0;
    if (kept_cuts_ > 0) empty_history("a change of CutParams::undo_history");
  }
  if (!history_.empty()) undo_log_.reserve(4096);
  for (KeptCut& k : history_) {
    k.mesh.reserve();
    constexpr std::size_t kCutScratch = 16384;
    detail::reserve_touched(k.removed, kCutScratch);
    detail::reserve_touched(k.created, kCutScratch);
    detail::reserve_touched(k.labels.relabelled, 4096);
  }
}

std::optional<std::string> Cutter::Pipeline::undo(ChangeLog* log) {
  if (auto invalid = stale()) return invalid;
  if (kept_cuts_ == 0) {
    if (params_.undo_history == 0) return "no cut is kept for undo: CutParams::undo_history is 0";
    if (history_emptied_by_) return std::string("no cut to undo: ") + history_emptied_by_ + " emptied the undo history";
    return "no cut to undo: every cut kept (CutParams::undo_history = " + std::to_string(params_.undo_history) +
           ") was taken back, or none changed the mesh";
  }
  KeptCut& k = history_[history_top_];
  if (!mesh_.is_last_change(k.mesh)) {
    empty_history("a change to the mesh made outside this Cutter");
    return "no cut to undo: the mesh was changed outside this Cutter since its last cut";
  }
  // The labels first: they read the made tets' labels while those are still the live ones.
  labels_.take_back(k.labels, k.removed, k.created);
  // The net change always: its moves are last_moved(), for the checker.
  undo_log_.clear();
  ChangeLog& net = log ? *log : undo_log_;
  const std::size_t first_moved = net.moved.size();
  rewired_.clear();
  TetMesh::rewired_tets(k.mesh, rewired_);  // what the cut rewired, the undo rewires back
  mesh_.undo(k.mesh, &net);
  locator_.update(mesh_, k.created, k.removed, rewired_);
  remover_.restore_report(k.removal_before);
  last_min_dihedral_held_ = k.min_dihedral_held_before;
  transaction_.undone(k.created, k.removed, std::span<const MovedVertex>(net.moved).subspan(first_moved));
  last_undone_reach_ = k.reach;
  audit_.clear();
  fragments_.clear();
  history_top_ = (history_top_ + params_.undo_history - 1) % params_.undo_history;
  if (--kept_cuts_ == 0) history_emptied_by_ = nullptr;
  return std::nullopt;
}

void Cutter::Pipeline::reset() {
  empty_history("reset()");
  locator_.build(mesh_, mesh_.mean_edge_length());
  labels_.build(mesh_);
  epoch_ = mesh_.id_epoch();
  scale_ = measure_scale(mesh_);
  judge_scale();
  remover_.reset();
  uncuttable_.clear();  // the ids it named are another mesh's
  transaction_.forget();
  audit_.clear();
  prepare();
}

Renumbering Cutter::Pipeline::compact(IdOrder order) {
  Renumbering map = mesh_.compact(order);
  detail::UncuttableTets uncuttable = std::move(uncuttable_);
  reset();
  empty_history("compact()");
  uncuttable.renumber(map);
  uncuttable_ = std::move(uncuttable);
  return map;
}

std::optional<std::string> Cutter::Pipeline::set_params(const CutParams& params) {
  if (auto invalid = validate(params)) return invalid;
  const bool removal_changed = params.strategy != params_.strategy || params.search_depth != params_.search_depth ||
                               params.neighbour_set != params_.neighbour_set;
  const bool revisit_now = params.order == RemovalOrder::kRevisit && params_.order != RemovalOrder::kRevisit;
  params_ = params;
  invalid_.reset();
  judge_scale();
  if (removal_changed) remover_.set_options(removal_options(params_));
  if (revisit_now) reserve_revisit();  // between cuts, so that the cuts in that order do not allocate
  search_.reserve(room_for_tets(), params_.fragment_search_bound);  // likewise for a larger bound
  reserve_history();
  return std::nullopt;
}

void Cutter::Pipeline::reserve_revisit() {
  removal_loop_.reserve_revisit(room_for_tets());
  remover_.reserve_search_only(room_for_tets());
}

std::optional<std::string> Cutter::Pipeline::set_uncuttable(std::span<const TetId> tets) {
  if (!indexes_current_mesh()) return "the mesh was compacted or replaced since this Cutter indexed it";
  for (TetId t : tets)
    if (t.value >= mesh_.tet_capacity() || !mesh_.is_live(t)) return "tet " + std::to_string(t.value) + " is not live";
  uncuttable_.assign(mesh_, tets);
  // A cut taken back would restore tets whose marks were written before this set.
  empty_history("set_uncuttable()");
  return std::nullopt;
}

bool Cutter::Pipeline::uncuttable(TetId t) const { return mesh_.is_live(t) && uncuttable_.contains(mesh_, t); }

void Cutter::Pipeline::judge_scale() {
  rule_ = params_.refinement != RefinementRule::kAuto   ? params_.refinement
          : params_.d_ref() < 0.75 * scale_.mean_edge ? RefinementRule::kGraded
                                                        : RefinementRule::kPaper;
  refusal_ = invalid_ ? invalid_ : check_scale(scale_, params_.tool_diameter, params_.d_ref_factor, params_.max_tets_created);
}

std::optional<std::string> Cutter::Pipeline::stale() const {
  if (indexes_current_mesh()) return std::nullopt;
  return "the mesh was compacted or replaced since this Cutter indexed it: compact with Cutter::compact(), "
         "or call Cutter::reset() after replacing the mesh";
}

TetId Cutter::Pipeline::tet_containing(const Vec3& p) {
  if (!indexes_current_mesh()) return kNoTet;
  locate(Tool::ball(p, 0.0));
  return hit_.empty() ? kNoTet : hit_.front();
}

bool Cutter::Pipeline::refuse(CutReport& report, CutRefusal refusal, std::string why) {
  report.ok = false;
  report.refusal = refusal;
  report.failure = std::move(why);
  return false;
}

void Cutter::Pipeline::begin(const Tool* tool) {
  transaction_.begin(mesh_, remover_);
  version_at_begin_ = mesh_.version();
  selection_.begin(tool);
  reach_at_begin_.reset();
  if (tool) reach_at_begin_ = CutReach{tool->a, tool->b, tool->radius, params_.d_ref()};
  // The cut's reach: the tool grown by D_ref, the longest edge its refinement leaves at the
  // tool (refine.hpp); what the cut removes beyond the tool lies within it, and the improvement
  // pass works within it (tissue_.reach()).
  tissue_.begin(tool, tool ? tool->radius + params_.d_ref() : 0.0);
}

void Cutter::Pipeline::roll_back(CutReport& report) {
  transaction_.roll_back(mesh_, remover_);
  // What the stages did before the refusal stays in the report, for people; nothing is left in
  // the tool by a cut that changed nothing it can be held to.
  report.left_in_tool = 0;
  report.volume_left_in_tool = 0.0;
  audit_.clear();
}

CutReport Cutter::Pipeline::cut(const Vec3& a, const Vec3& b, ChangeLog* log) {
  CutReport report;
  report.d_ref = params_.d_ref();
  transaction_.forget();
  audit_.clear();
  fragments_.clear();
  min_dihedral_held_at_begin_ = last_min_dihedral_held_;  // before any attempt's improvement pass
  if (auto invalid = stale()) {
    refuse(report, CutRefusal::kStaleIndex, *invalid);
    return report;
  }
  if (refusal_) {
    refuse(report, CutRefusal::kParameters, *refusal_);
    return report;
  }
  auto finite = [](const Vec3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); };
  if (!finite(a) || !finite(b)) {
    refuse(report, CutRefusal::kParameters, "the tool's position must be finite");
    return report;
  }
  Laps clock;
  const Tool tool{a, b, params_.tool_diameter / 2};
  locate(tool);
  report.tets_hit = static_cast<std::uint32_t>(hit_.size());
  report.time.locate_us = clock.lap();
  if (!hit_.empty()) {
    attempt_under_mesh_rule(tool, rule_, clock, report, log);
    // Auto's one retry: the paper's loop made tets the pass cannot lift; the graded rule, at the
    // same D_ref (the tissue rule is judged at it either way), makes tets the pass keeps above the
    // floor. The rolled-back attempt's time stays in the stages' and the cut's.
    if (!report.ok && report.refusal == CutRefusal::kQualityFloor && params_.refinement == RefinementRule::kAuto &&
        rule_ == RefinementRule::kPaper) {
      const CutTimings spent = report.time;
      const std::uint32_t mesh_rule_retries = report.mesh_rule_retries;
      report = CutReport{};
      report.d_ref = params_.d_ref();
      report.tets_hit = static_cast<std::uint32_t>(hit_.size());
      report.retries = 1;
      report.mesh_rule_retries = mesh_rule_retries;
      report.time = spent;
      attempt_under_mesh_rule(tool, RefinementRule::kGraded, clock, report, log);
    }
  }
  report.time.total_us = clock.total();
  return report;
}

void Cutter::Pipeline::attempt_under_mesh_rule(const Tool& tool, RefinementRule rule, Laps& clock, CutReport& report,
                                               ChangeLog* log) {
  under_mesh_rule(report, [&] { attempt(tool, rule, clock, report, log); });
}

template <class Attempt>
void Cutter::Pipeline::under_mesh_rule(CutReport& report, Attempt&& make) {
  grew_bad_volume_ = false;
  make();
  if (!grew_bad_volume_) return;
  // Rolled back: the same attempt with every plan of the pass held to the mesh rule. What the
  // first attempt was given and the time it took stay in the report.
  CutReport again;
  again.d_ref = report.d_ref;
  again.tets_hit = report.tets_hit;
  again.retries = report.retries;
  again.mesh_rule_retries = report.mesh_rule_retries + 1;
  again.time = report.time;
  report = again;
  grew_bad_volume_ = false;
  hold_plans_to_mesh_rule_ = true;
  make();
  hold_plans_to_mesh_rule_ = false;
}

void Cutter::Pipeline::attempt(const Tool& tool, RefinementRule rule, Laps& clock, CutReport& report, ChangeLog* log) {
  begin(&tool);
  bool ok = refine(tool, rule, report);
  report.time.refine_us += clock.lap();
  if (ok) {
    select(report);
    report.time.select_us += clock.lap();
    ok = remove_selected(report);
    report.time.remove_us += clock.lap();
  }
  conclude(ok, clock, report, log);
}

void Cutter::Pipeline::conclude(bool ok, Laps& clock, CutReport& report, ChangeLog* log) {
  if (ok) {
    ok = improve(report);
    report.time.improve_us += clock.lap();
  }
  if (ok) ok = audit(report);
  if (ok) {
    report.time.finish_us += clock.lap();
    find_pieces(report);
    report.time.pieces_us += clock.lap();
    commit(report, log);
  } else {
    roll_back(report);
  }
  report.time.finish_us += clock.lap();
}

CutReport Cutter::Pipeline::remove(TetId t, ChangeLog* log) {
  CutReport report;
  transaction_.forget();
  audit_.clear();
  fragments_.clear();
  min_dihedral_held_at_begin_ = last_min_dihedral_held_;  // before any attempt's improvement pass
  if (auto invalid = stale()) {
    refuse(report, CutRefusal::kStaleIndex, *invalid);
    return report;
  }
  if (!mesh_.is_live(t)) {
    refuse(report, CutRefusal::kRequest, "tet " + std::to_string(t.value) + " is not live");
    return report;
  }
  if (uncuttable_.contains(mesh_, t)) {
    refuse(report, CutRefusal::kRequest, "tet " + std::to_string(t.value) + " is uncuttable");
    return report;
  }
  Laps clock;
  under_mesh_rule(report, [&] {
    begin(nullptr);  // no tool: the request alone, no children join it
    selection_.select_request(t);
    const bool ok = remove_selected(report);
    report.time.remove_us += clock.lap();
    conclude(ok, clock, report, log);
  });
  report.time.total_us = clock.total();
  return report;
}

// Locate (paper 3.1): T_hit, the live tets meeting the tool.
void Cutter::Pipeline::locate(const Tool& tool) {
  locator_.query(mesh_, tool, hit_);
#ifdef TETCUT_CHECK_LOCATE
  // The sanitizer and fuzzing builds (CMakePresets.json) check every answer against a scan of
  // the mesh: the walk's equality with the index it replaced, on every test and fuzz input, up to
  // the size at which the scan would dominate the suites' time.
  constexpr std::uint32_t kLargestScanned = 200000;
  if (mesh_.tet_capacity() > kLargestScanned) return;
  scan_tets_meeting(mesh_, tool, scanned_);
  if (scanned_ != hit_) {
    std::fprintf(stderr, "tetcut: the walking locator found %zu tets where a scan finds %zu\n", hit_.size(), scanned_.size());
    std::abort();
  }
#endif
}

// Refine (paper 3.2), following the new tets that meet the tool.
bool Cutter::Pipeline::refine(const Tool& tool, RefinementRule rule, CutReport& report) {
  RefineParams refine;
  refine.rule = rule;
  report.refinement = rule;
  refine.d_ref = params_.d_ref();
  refine.p = params_.p;
  refine.max_iterations = params_.max_refine_iterations;
  refine.method = params_.split_method;
  refine.focus = tool;
  refine.max_tets_created = params_.max_tets_created;  // checked before each round (net)
  refine.measure_quality = false;  // the improvement pass reports the worst net new tet
  const RefineReport refined = refiner_.refine(mesh_, hit_, refine, region_);
  report.refine_iterations = refined.iterations;
  report.edges_split = refined.edges_split;
  report.tets_refined = refined.tets_removed;
  if (refined.refusal == SplitRefusal::kOverBudget)
    return refuse(report, CutRefusal::kTetBudget, "refinement refused: " + std::string(to_string(refined.refusal)));
  if (refined.refusal != SplitRefusal::kNone)
    return refuse(report, CutRefusal::kDegenerateSplit, "refinement refused: " + std::string(to_string(refined.refusal)));
  return true;
}

// Select T_removal (paper 3.3).
void Cutter::Pipeline::select(CutReport& report) { selection_.select(mesh_, region_, uncuttable_, report.uncuttable_in_tool); }

// Remove (paper 3.3-3.7).
bool Cutter::Pipeline::remove_selected(CutReport& report) {
  const detail::RemovalLoop::Context ctx{mesh_, selection_, remover_, tissue_, uncuttable_, params_, transaction_.start()};
  removal_start_ = mesh_.savepoint();
  const bool ok = removal_loop_.run(ctx, report);
  removal_end_ = mesh_.savepoint();
  if (ok) return true;
  return refuse(report, CutRefusal::kTetBudget, "the removal would exceed the per-cut tet budget");
}

// The improvement pass (improve/improver.hpp) over what the transaction made.
bool Cutter::Pipeline::improve(CutReport& report) {
  const Tool* tool = selection_.tool();
  const Tool* reach = tissue_.reach();  // begin()'s: the tool grown by D_ref
  // No operation of the pass may break the tissue rule the audit then holds the cut to.
  const detail::TissueRuleVeto veto(mesh_, selection_, uncuttable_, params_.d_ref());
  const detail::ImproveOutcome outcome =
      improver_.run(mesh_, transaction_.start(),
                    {.floor = params_.quality_floor, .min_dihedral_deg = params_.min_dihedral_deg, .improve = params_.improve, .reach = reach, .tool = tool,
                     .uncuttable = &uncuttable_, .tissue = &tissue_, .veto = veto,
                     .hold_plans_to_mesh_rule = hold_plans_to_mesh_rule_});
  report.tets_removed_by_improvement = outcome.removed;
  report.min_radius_ratio_before_improvement = outcome.worst_before;
  report.min_radius_ratio = outcome.worst_after;  // the worst net new tet: the made tets still live
  report.min_dihedral_deg_before_improvement = outcome.min_dihedral_before_deg;
  report.min_dihedral_deg = outcome.min_dihedral_after_deg;
  report.quality_floor = outcome.floor;
  report.dihedral_floor_deg = outcome.dihedral_floor_deg;
  report.min_dihedral_held_deg = last_min_dihedral_held_ = outcome.min_dihedral_held_deg;
  report.angle_retries += outcome.angle_retries;
  report.quality_met = outcome.met;
  report.improvement_flips = outcome.flips;
  report.improvement_collapses = outcome.collapses;
  report.improvement_moves = outcome.moves;
  report.improvement_insertions = outcome.insertions;
  if (outcome.grew_bad_volume) {
    // The mesh rule: rolled back, and made again with every plan held to it (cut(), remove()).
    grew_bad_volume_ = true;
    return refuse(report, CutRefusal::kQualityFloor, "the volume of tets below theta outside the tool grew");
  }
  if (report.quality_met || !params_.improve) return true;
  const detail::ImproveOutcome::Shortfall& s = outcome.shortfall;
  char text[400];
  std::snprintf(text, sizeof text,
                "the quality floor could not be met: a created tet has radius ratio %.3g (its floor %.3g = min(quality_floor, "
                "its host's)) and smallest dihedral angle %.3g degrees (its floor %.3g = min(min_dihedral_deg, its host's)); "
                "a lower quality_floor or min_dihedral_deg, or improve off, lets such a cut through",
                s.radius_ratio, s.ratio_floor, s.min_dihedral_deg, s.dihedral_floor_deg);
  return refuse(report, CutRefusal::kQualityFloor, text);
}

// The tissue rule (tissue_audit.hpp), and what the cut removed as tissue.
bool Cutter::Pipeline::audit(CutReport& report) {
  const detail::RemovedTissue& removed = tissue_.removed();
  report.volume_removed = removed.volume;
  report.tets_removed_beyond_tool = removed.tets_beyond_tool;
  report.volume_removed_beyond_tool = removed.volume_beyond_tool;
  report.tets_removed_beyond_reach = removed.tets_beyond_reach;
  if (!selection_.tool()) return true;  // a removal request: no tool to hold to the rule
  const auto removal_births = mesh_.tets_made_since(removal_start_);
  const detail::TissueAudit::Context ctx{
      mesh_, hit_, transaction_.start(), removal_births.first(removal_births.size() - mesh_.tets_made_since(removal_end_).size()),
      selection_, removal_loop_, uncuttable_, params_.d_ref()};
  if (auto why = audit_.run(ctx, report)) return refuse(report, CutRefusal::kTissueRule, *why);
  return true;
}

// The pieces the transaction detached (fragment_search.hpp), and the debris removed: whole
// pieces, so no singularity can follow (a manifold mesh's pieces share no vertex), through the
// mesh's one removal primitive, inside the transaction and so in its change log.
void Cutter::Pipeline::find_pieces(CutReport& report) {
  fragments_.clear();
  mesh_.changes_since(transaction_.start(), removed_, created_);
  search_.run(mesh_, labels_, removed_, created_, params_.fragment_search_bound);
  report.fragment_tets_visited = search_.visited();
  report.fragment_search_bounded = search_.bounded();
  for (const detail::FragmentSearch::Piece& piece : search_.pieces()) {
    const std::span<const TetId> tets = search_.tets_of(piece);
    const bool debris = params_.debris_volume > 0.0 && piece.volume < params_.debris_volume && !uncuttable_.any_of(mesh_, tets);
    if (debris) {
      mesh_.remove_tets(tets);
      ++report.debris_pieces_removed;
      report.debris_tets_removed += piece.count;
      report.debris_volume_removed += piece.volume;
    }
    fragments_.push_back({tets, piece.volume, piece.centroid, debris, piece.organ});
  }
  report.fragments = static_cast<std::uint32_t>(fragments_.size());
}

// Commits the transaction, brings the index and the piece labels up to date with the net changes
// and hands the caller the net change (the journal derives it).
void Cutter::Pipeline::commit(CutReport& report, ChangeLog* log) {
  // Kept for undo() in the ring's next record, unless no history is asked for.
  KeptCut* kept = history_.empty() ? nullptr : &history_[(history_top_ + 1) % history_.size()];
  if (kept) labels_.keep(kept->labels);
  labels_.before_commit(mesh_, transaction_.start(), removed_);
  // The search's net change is the transaction's unless debris went since.
  const detail::CutTransaction::NetChange known{removed_, created_};
  report.tets_created = transaction_.commit(mesh_, uncuttable_, locator_, log, report.debris_pieces_removed == 0 ? &known : nullptr,
                                            kept ? &kept->mesh : nullptr);
  report.vertices_moved = static_cast<std::uint32_t>(transaction_.net_moved().size());
  labels_.after_commit(transaction_.net_removed());
  for (const Fragment& f : fragments_)
    if (!f.removed) labels_.detach(f.tets, kept ? &kept->labels : nullptr);
  if (!kept) return;
  if (mesh_.version() == version_at_begin_) {  // nothing changed: nothing to take back
    kept->mesh.clear();
    // The record was the oldest kept when the ring is full: it is spent.
    if (kept_cuts_ == history_.size()) --kept_cuts_;
    return;
  }
  kept->removal_before = transaction_.removal_at_start();
  kept->min_dihedral_held_before = min_dihedral_held_at_begin_;
  kept->reach = reach_at_begin_;
  kept->removed.assign(transaction_.net_removed().begin(), transaction_.net_removed().end());
  kept->created.assign(transaction_.net_created().begin(), transaction_.net_created().end());
  history_top_ = static_cast<std::uint32_t>((history_top_ + 1) % history_.size());
  kept_cuts_ = std::min<std::uint32_t>(kept_cuts_ + 1, params_.undo_history);
  history_emptied_by_ = nullptr;
}

}  // namespace tetcut
