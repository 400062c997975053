#include "improve/improver.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/host_location.hpp"
#include "core/quality.hpp"
#include "core/tet_intersection.hpp"
#include "improve/sliver_removal.hpp"
#include "tetcut/detail/reserve_touched.hpp"

namespace tetcut::detail {
namespace {

// A flip or a move must lift the worst tet it touches by this much (relative): what makes the
// pass end, and keeps it from trading places between equal tets.
constexpr double kMargin = 1e-6;
// Operations per pass: far above what a cut needs (a few dozen), a bound for pathological ones.
constexpr std::uint32_t kMaxOperations = 512;
// Smoothing plans for vertices there before the transaction that may come to nothing, per pass:
// each evaluates a star of a few dozen tets over and over, and where they cannot help (the gated
// sweep's cuts move none) a cut with many tets nothing lifts planned them again and again: its
// slowest cut went from 2.3 to 3.4 million instructions unbounded, 2.8 at three. A plan that
// lifts a tet does not count: at two, one cut of the sphere's ratchet (tests/engine/cut/
// angle_ratchet_test.cpp) fell back below theta; at three none does.
constexpr std::uint32_t kOldVertexPlans = 3;
// Tets a plan may remove or add before its storage grows: a star of a vertex in a real mesh.
constexpr std::size_t kPlanTets = 128;

void count(ImproveOutcome& out, Refusal refusal) { ++out.refused[static_cast<std::size_t>(refusal)]; }

void count_applied(ImproveOutcome& out, Operator op) {
  switch (op) {
    case Operator::kEdgeRemoval:
    case Operator::kFaceRemoval: ++out.flips; break;
    case Operator::kCollapse: ++out.collapses; break;
    case Operator::kSmoothing: ++out.moves; break;
    case Operator::kInsertion: ++out.insertions; break;
    case Operator::kSliverRemoval: ++out.removed; break;
  }
}

// Live tet t's shape as the mesh has it now.
TetShape shape_now(const TetMesh& mesh, TetId t) {
  const TetMesh::TetVerts v = mesh.tet(t);
  return tet_shape(mesh.position(v[0]), mesh.position(v[1]), mesh.position(v[2]), mesh.position(v[3]));
}

}  // namespace

void Improver::reserve(std::uint32_t tets) {
  flipper_.reserve();
  collapser_.reserve();
  smoother_.reserve();
  inserter_.reserve(tets);
  for (Plan* p : {&best_, &candidate_, &insertion_}) p->reserve(kPlanTets);
  reserve_touched(star_, 128);
  reserve_touched(neighbours_, 128);
  for (auto* v : {&made_, &created_}) reserve_touched(*v, 4096);
  reserve_touched(made_shapes_, 4096);
  reserve_touched(bad_, 4096);
  reserve_touched(made_quality_, 4096);
  reserve_touched(ancestors_, 64);
  reserve_touched(outside_, 4096);
}

std::pair<double, double> Improver::collect_made(TetMesh& mesh, const TetMesh::Savepoint& start) {
  made_.clear();
  made_shapes_.clear();
  double worst = 1.0, cosine = -1.0;
  for (const TetMesh::TetBirth& b : mesh.tets_made_since(start))
    if (mesh.is_live(b.tet)) {
      made_.push_back(b.tet);
      // Measured directly: most cuts' made tets all meet F and theta here, and the pass never
      // asks again (the memo would only cost them its look-ups). Kept beside made_ for judge(),
      // which comes next when one is below, so that no made tet is measured twice.
      const TetShape s = shape_now(mesh, b.tet);
      made_shapes_.push_back(s);
      worst = std::min(worst, s.ratio);
      cosine = std::max(cosine, s.max_cosine);
    }
  return {worst, cosine};
}

TetShape Improver::shape_of(const TetMesh& mesh, TetId t, const TetShape* measured) {
  const std::uint32_t birth = mesh.birth_index(t);
  MadeTet entry;
  if (birth != TetMesh::kNoBirth)
    if (const MadeTet* known = made_tets_.find(birth)) {
      if (known->shape.ratio >= 0.0) return known->shape;
      entry = *known;
    }
  entry.shape = measured ? *measured : shape_now(mesh, t);
  if (birth != TetMesh::kNoBirth) made_tets_.set(birth, entry);
  return entry.shape;
}

TetId Improver::host_of(TetMesh& mesh, TetId t) {
  const std::uint32_t birth = mesh.birth_index(t);
  MadeTet entry;
  if (birth != TetMesh::kNoBirth)
    if (const MadeTet* known = made_tets_.find(birth)) {
      if (known->host.valid()) return known->host;
      entry = *known;
    }
  ancestors_.clear();
  mesh.ancestors_at_start(t, ancestors_);
  TetId host = ancestors_.front();
  if (ancestors_.size() > 1) {
    // After a flip: the ancestor that holds the tet's centroid.
    const TetMesh::TetVerts v = mesh.tet(t);
    const Vec3 centroid = 0.25 * (mesh.position(v[0]) + mesh.position(v[1]) + mesh.position(v[2]) + mesh.position(v[3]));
    if (const DeepestTet deepest = deepest_at_start(mesh, ancestors_, centroid); deepest.found()) host = deepest.tet();
  }
  entry.host = host;
  if (birth != TetMesh::kNoBirth) made_tets_.set(birth, entry);
  return host;
}

Improver::Floors Improver::floors_of(TetMesh& mesh, TetId t) {
  const Floors h = shape_at_start(mesh, host_of(mesh, t));
  return {std::min(floor_f_, h.ratio), std::max(cos_theta_, h.cosine)};
}

Improver::Floors Improver::shape_at_start(TetMesh& mesh, TetId old) {
  if (const Floors* known = host_shapes_.find(old.value)) return *known;
  // As it was: its vertices were there before the transaction, where they were then.
  const TetMesh::TetVerts v = mesh.tet_at_start(old);
  const TetShape s = tet_shape(mesh.position_at_start(v[0]), mesh.position_at_start(v[1]), mesh.position_at_start(v[2]),
                               mesh.position_at_start(v[3]));
  const Floors h{s.ratio, s.max_cosine};
  host_shapes_.set(old.value, h);
  return h;
}

bool Improver::below_floor(TetMesh& mesh, TetId t, Floors* floors, const TetShape* measured) {
  // The checker compares with its own formulas: aim a rounding above the ratio's floor. An angle
  // equal to its floor is not below it: a split child keeps its parent's dihedral angles at the
  // parent's edges exactly, to rounding, which the checker allows for (no_degradation.hpp).
  const TetShape shape = shape_of(mesh, t, measured);
  auto below = [&](const Floors& f) { return shape.ratio < f.ratio * (1.0 + 1e-9) || shape.max_cosine > f.cosine + 1e-12; };
  const Floors global{floor_f_, cos_theta_};
  if (!below(global)) {
    if (floors) *floors = global;
    return false;
  }
  const Floors own = floors_of(mesh, t);
  if (floors) *floors = own;
  return below(own);
}

void Improver::judge(TetMesh& mesh, ImproveOutcome& out) {
  out.met = true;
  out.floor = floor_f_;
  double lowest_cosine = cos_theta_;
  // The tets below their floors, worst quality() first: the first is the shortfall.
  made_quality_.clear();
  // Every call follows a collect_made() with no operation between: its shapes are the mesh's.
  for (std::size_t i = 0; i < made_.size(); ++i) {
    const TetId t = made_[i];
    Floors f;
    const bool below = below_floor(mesh, t, &f, &made_shapes_[i]);
    out.floor = std::min(out.floor, f.ratio);
    lowest_cosine = std::max(lowest_cosine, f.cosine);
    if (below) made_quality_.push_back({quality(mesh, t), t});
  }
  out.met = made_quality_.empty();
  if (!out.met) {
    const auto [q, t] = *std::min_element(made_quality_.begin(), made_quality_.end());
    const Floors f = floors_of(mesh, t);
    const TetMesh::TetVerts v = mesh.tet(t);
    const Vec3 &p0 = mesh.position(v[0]), &p1 = mesh.position(v[1]), &p2 = mesh.position(v[2]), &p3 = mesh.position(v[3]);
    out.shortfall = {radius_ratio(p0, p1, p2, p3), f.ratio, min_dihedral_angle_deg(p0, p1, p2, p3), degrees_of_cosine(f.cosine)};
  }
  out.dihedral_floor_deg = degrees_of_cosine(lowest_cosine);
}

void Improver::set_theta(double theta_deg, double floor_f) {
  theta_ = theta_deg;
  floor_f_ = floor_f;
  cos_theta_ = std::cos(theta_deg * std::numbers::pi / 180.0);
  const double sine = std::sin(theta_deg * std::numbers::pi / 180.0);
  t_dihedral_sine_weight = sine > 0.0 ? floor_f / sine : 0.0;
  goal_ = floor_f;  // quality() at F and theta
}

Refusal Improver::star_rule(TetMesh& mesh, VertId v) {
  if (!mesh.made_in_transaction(v)) return Refusal::kNotMadeByCut;
  if (!uncuttable_ || uncuttable_->empty()) return Refusal::kNone;
  mesh.vertex_shell(v, star_);
  return uncuttable_->any_of(mesh, star_) ? Refusal::kUncuttable : Refusal::kNone;
}

Refusal Improver::old_vertex_rule(TetMesh& mesh, VertId v) {
  if (!tool_) return Refusal::kNotMadeByCut;  // a removal request has no reach
  if (distance_to_axis(*tool_, mesh.position_at_start(v)) > tool_->radius) return Refusal::kOutOfReach;
  if (!uncuttable_ || uncuttable_->empty()) return Refusal::kNone;
  mesh.vertex_shell(v, star_);
  return uncuttable_->any_of(mesh, star_) ? Refusal::kUncuttable : Refusal::kNone;
}

Refusal Improver::old_vertex_move(const Plan& plan) const {
  if (distance_to_axis(*tool_, plan.placed_at) > tool_->radius) return Refusal::kOutOfReach;
  return plan.worst_after >= goal_ * (1.0 + kMargin) ? Refusal::kNone : Refusal::kNotBetter;
}

Refusal Improver::region_rule(TetMesh& mesh, const Plan& plan) const {
  if (!uncuttable_ || uncuttable_->empty()) return Refusal::kNone;
  switch (plan.op) {
    case Operator::kEdgeRemoval:
    case Operator::kFaceRemoval:
      return !uncuttable_->any_of(mesh, plan.removed_tets()) || uncuttable_->all_of(mesh, plan.removed_tets())
                 ? Refusal::kNone
                 : Refusal::kUncuttable;
    case Operator::kInsertion: return Refusal::kNone;
    case Operator::kCollapse:
    case Operator::kSmoothing:
    case Operator::kSliverRemoval:
      return uncuttable_->any_of(mesh, plan.removed_tets()) ? Refusal::kUncuttable : Refusal::kNone;
  }
  return Refusal::kNone;
}

bool Improver::in_tool(const std::array<Vec3, 4>& p) const {
  return cut_tool_ && distance_to_axis(*cut_tool_, 0.25 * (p[0] + p[1] + p[2] + p[3])) < cut_tool_->radius;
}

double Improver::bad_volume(const TetMesh& mesh, std::span<const TetId> tets) {
  double volume = 0.0;
  for (TetId t : tets) {
    const TetMesh::TetVerts v = mesh.tet(t);
    if (in_tool({mesh.position(v[0]), mesh.position(v[1]), mesh.position(v[2]), mesh.position(v[3])})) continue;
    if (shape_of(mesh, t).max_cosine > cos_theta_ + 1e-12) volume += mesh.volume(t);
  }
  return volume;
}

Refusal Improver::bad_volume_rule(const TetMesh& mesh, const Plan& plan) {
  if (!spread_rule_ || plan.op == Operator::kSliverRemoval || !(theta_ > 0.0)) return Refusal::kNone;
  double after = 0.0;
  for (const TetMesh::TetVerts& tet : plan.added_tets()) {
    const std::array<Vec3, 4> p = plan.corners(mesh, tet);
    if (in_tool(p)) continue;
    // Within rounding of theta counts as below: a made tet the checker could call bad.
    if (tet_shape(p[0], p[1], p[2], p[3]).max_cosine > cos_theta_ - 1e-12)
      after += dot(p[1] - p[0], cross(p[2] - p[0], p[3] - p[0])) / 6.0;
  }
  if (after == 0.0) return Refusal::kNone;
  const double before = plan.op == Operator::kInsertion ? insertion_bad_before_ : bad_volume(mesh, plan.removed_tets());
  return after <= before * (1.0 + 1e-9) ? Refusal::kNone : Refusal::kSpreadsBadVolume;
}

Refusal Improver::admit(TetMesh& mesh, const Plan& plan, ImproveOutcome& out) {
  Refusal verdict = region_rule(mesh, plan);
  if (verdict == Refusal::kNone) verdict = bad_volume_rule(mesh, plan);
  if (verdict == Refusal::kNone && veto_) {
    verdict = veto_(mesh, plan);
    out.vetoed += verdict != Refusal::kNone;
  }
  if (verdict != Refusal::kNone) count(out, verdict);
  return verdict;
}

void Improver::offer(TetMesh& mesh, Refusal planned, ImproveOutcome& out) {
  if (planned != Refusal::kNone) {
    count(out, planned);
    return;
  }
  if (!(candidate_.worst_after > best_after_)) return;  // made, but another lifts the tet more
  if (admit(mesh, candidate_, out) != Refusal::kNone) return;
  std::swap(best_, candidate_);
  best_after_ = best_.worst_after;
  has_best_ = true;
}

void Improver::apply(TetMesh& mesh, const Plan& plan) {
  const std::size_t before = created_.size();
  plan.apply(mesh, created_);
  made_.insert(made_.end(), created_.begin() + static_cast<std::ptrdiff_t>(before), created_.end());
}

std::optional<Operator> Improver::improve_tet(TetMesh& mesh, TetId t, ImproveOutcome& out) {
  // Every operation that would lift the tet, planned; the one whose worst tet ends best is
  // applied (ties: the first offered: a flip, then a collapse, then a move).
  best_after_ = 0.0;
  has_best_ = false;
  for (int e = 0; e < 6; ++e) offer(mesh, flipper_.plan_edge_removal(mesh, t, e, kMargin, candidate_), out);
  for (int f = 0; f < 4; ++f) offer(mesh, flipper_.plan_face_flip(mesh, t, f, kMargin, candidate_), out);
  // A flip that lifts the tet well past the goal is taken as it is (the dearer plans below would
  // rarely beat it by much).
  if (has_best_ && best_after_ >= 2.0 * goal_) {
    apply(mesh, best_);
    return best_.op;
  }
  const TetMesh::TetVerts corners = mesh.tet(t);
  std::array<VertId, 4> old_corners{};
  std::size_t old_count = 0;
  for (VertId v : corners) {
    if (const Refusal r = star_rule(mesh, v); r != Refusal::kNone) {
      if (r == Refusal::kNotMadeByCut) old_corners[old_count++] = v;
      else count(out, r);
      continue;
    }
    // Into any neighbour: v's going removes the tet whichever way it goes.
    mesh.vertex_neighbours(v, neighbours_, star_);
    for (VertId w : neighbours_) offer(mesh, collapser_.plan(mesh, v, w, kMargin, best_after_, candidate_), out);
    offer(mesh, smoother_.plan(mesh, v, kMargin, tool_, candidate_), out);
  }
  // Only when nothing above lifts it (most bad tets are lifted by what the cut made, and this
  // costs a star's worth of evaluations per vertex): a vertex there before, within the reach,
  // smoothed (never collapsed) to where its whole star meets F and theta (old_vertex_move).
  for (std::size_t i = 0; i < old_count && !has_best_ && old_vertex_plans_ > 0; ++i) {
    const VertId v = old_corners[i];
    if (const Refusal r = old_vertex_rule(mesh, v); r != Refusal::kNone) {
      count(out, r);
      continue;
    }
    Refusal planned = smoother_.plan(mesh, v, kMargin, tool_, candidate_);
    if (planned == Refusal::kNone) planned = old_vertex_move(candidate_);
    if (planned != Refusal::kNone) --old_vertex_plans_;  // only a plan that came to nothing counts
    offer(mesh, planned, out);
  }
  if (!has_best_) {
    if (!insert(mesh, t, out)) return std::nullopt;
    return Operator::kInsertion;
  }
  apply(mesh, best_);
  return best_.op;
}

bool Improver::insert(TetMesh& mesh, TetId t, ImproveOutcome& out) {
  const TetMesh::Savepoint point = mesh.savepoint();
  if (const Refusal r = inserter_.plan(mesh, t, insertion_); r != Refusal::kNone) {
    count(out, r);
    return false;
  }
  if (spread_rule_) insertion_bad_before_ = bad_volume(mesh, insertion_.removed_tets());  // bad_volume_rule's, when on
  const std::size_t before = created_.size();
  insertion_.apply(mesh, created_);
  const VertId midpoint = mesh.vertices_made_since(point).front().vertex;
  if (const Refusal r = star_rule(mesh, midpoint); r != Refusal::kNone) {
    count(out, r);
  } else if (const Refusal s = smoother_.plan(mesh, midpoint, 0.0, tool_, candidate_); s != Refusal::kNone) {
    count(out, s);
  } else if (admit(mesh, candidate_, out) == Refusal::kNone) {
    candidate_.apply(mesh, created_);
  }
  // The insertion as it ends: the midpoint's star, the split's halves, moved.
  mesh.vertex_shell(midpoint, star_);
  insertion_.worst_after = worst_quality(mesh, star_);
  if (!(insertion_.worst_after > insertion_.worst_before * (1.0 + kMargin))) {
    count(out, Refusal::kNotBetter);
  } else {
    // Shown to the rules and the hook as it ends: the tets split, the new vertex's star where it
    // now is.
    insertion_.added.clear();
    for (TetId u : star_) insertion_.added.push_back(mesh.tet(u));
    insertion_.placed = midpoint;
    insertion_.placed_at = mesh.position(midpoint);
    if (admit(mesh, insertion_, out) == Refusal::kNone) {
      made_.insert(made_.end(), created_.begin() + static_cast<std::ptrdiff_t>(before), created_.end());
      return true;
    }
  }
  mesh.rollback_to(point);
  made_tets_.forget_from(point.tet_births);  // the births it undid may come back as other tets
  created_.resize(before);
  return false;
}

void Improver::remove_slivers(TetMesh& mesh, ImproveOutcome& out) {
  for (TetId t : made_) {
    if (!mesh.is_live(t) || !below_floor(mesh, t)) continue;
    if (const Refusal r = plan_sliver_removal(mesh, t, tool_, *tissue_, candidate_); r != Refusal::kNone) {
      count(out, r);
      continue;
    }
    if (admit(mesh, candidate_, out) != Refusal::kNone) continue;
    candidate_.apply(mesh, created_);
    count_applied(out, Operator::kSliverRemoval);
  }
}

void Improver::lift(TetMesh& mesh, ImproveOutcome& out, std::uint32_t& operations) {
  for (bool progress = true; progress && operations < kMaxOperations;) {
    progress = false;
    // The made tets below their floors, worst first (ties by id: deterministic).
    bad_.clear();
    for (TetId t : made_)
      if (mesh.is_live(t) && below_floor(mesh, t)) bad_.push_back({quality(mesh, t), t});
    if (bad_.empty()) break;
    std::sort(bad_.begin(), bad_.end());
    for (const auto& [q, t] : bad_) {
      if (!mesh.is_live(t) || !below_floor(mesh, t)) continue;
      const std::optional<Operator> applied = improve_tet(mesh, t, out);
      if (!applied) continue;
      progress = true;
      count_applied(out, *applied);
      if (++operations == kMaxOperations) break;
    }
  }
  // Slivers left at the cut's surface go with the tissue (the header says when).
  remove_slivers(mesh, out);
}

ImproveOutcome Improver::run(TetMesh& mesh, const TetMesh::Savepoint& start, const ImproveParams& params) {
  ImproveOutcome out;
  host_shapes_.forget();
  made_tets_.forget();
  tool_ = params.reach;
  cut_tool_ = params.tool;
  old_vertex_plans_ = kOldVertexPlans;
  uncuttable_ = params.uncuttable;
  veto_ = params.veto;
  tissue_ = params.tissue;
  if (!tissue_) {
    own_tissue_.begin(nullptr, 0.0);
    tissue_ = &own_tissue_;
  }
  // quality() weighs the angle for this run's floors, and for the default ones again after it.
  struct WeightScope {
    ~WeightScope() { t_dihedral_sine_weight = kDihedralSineWeight; }
  } weight_scope;
  set_theta(params.min_dihedral_deg, params.floor);
  out.floor = params.floor;
  out.dihedral_floor_deg = params.min_dihedral_deg;
  out.min_dihedral_held_deg = params.min_dihedral_deg;
  if (measure(mesh, start, params, out)) return out;
  spread_rule_ = params.hold_plans_to_mesh_rule;
  lift_to_floors(mesh, start, params, out);
  // The mesh rule (header), weighed once: the caller makes the transaction again with every plan
  // held to it when this one grew the volume below theta.
  if (params.improve && !spread_rule_) out.grew_bad_volume = grows_bad_volume(mesh);
  spread_rule_ = false;
  return out;
}

bool Improver::measure(TetMesh& mesh, const TetMesh::Savepoint& start, const ImproveParams& params, ImproveOutcome& out) {
  const auto [worst, cosine] = collect_made(mesh, start);
  out.worst_before = out.worst_after = worst;
  out.min_dihedral_before_deg = out.min_dihedral_after_deg = made_.empty() ? 180.0 : degrees_of_cosine(cosine);
  // Every made tet at or above F and theta is above its floors: met, without locating hosts.
  return worst >= params.floor * (1.0 + 1e-9) && cosine <= std::cos(params.min_dihedral_deg * std::numbers::pi / 180.0) + 1e-12;
}

void Improver::lift_to_floors(TetMesh& mesh, const TetMesh::Savepoint& start, const ImproveParams& params, ImproveOutcome& out) {
  judge(mesh, out);
  bool changed = false;  // whether the made set was taken again since the measure before
  std::pair<double, double> after{};
  if (params.improve && !out.met) {
    std::uint32_t operations = 0;
    // theta, then kFallbackDihedralDeg, then none: the cap on refused cuts wins over the angle.
    // Each lower theta goes on from where the last left the mesh (every operation it applied
    // was valid and lifted a tet), with an objective weighed for it.
    const double ladder[] = {params.min_dihedral_deg, std::min(params.min_dihedral_deg, kFallbackDihedralDeg), 0.0};
    for (std::size_t step = 0; step < std::size(ladder); ++step) {
      if (step > 0) {
        if (ladder[step] == ladder[step - 1]) continue;
        ++out.angle_retries;
        set_theta(ladder[step], params.floor);
        judge(mesh, out);
        if (out.met) break;
      }
      created_.clear();
      // Each made tet's floors are its host's: an operation that replaces made tets by others in
      // other hosts moves them. So: lift, take the made set and its floors again, and lift again
      // while some made tet is below (a few rounds).
      for (int round = 0; round < 3 && !out.met; ++round) {
        lift(mesh, out, operations);
        after = collect_made(mesh, start);
        changed = true;
        judge(mesh, out);
      }
      if (out.met) break;
    }
  }
  out.min_dihedral_held_deg = theta_;
  if (changed) {
    out.worst_after = after.first;
    out.min_dihedral_after_deg = made_.empty() ? 180.0 : degrees_of_cosine(after.second);
  }
}

bool Improver::grows_bad_volume(TetMesh& mesh) {
  if (!(theta_ > 0.0)) return false;
  // After: the made tets below theta outside the tool (within rounding of theta counts as below:
  // the checker's strict side). Most transactions have none and stop here.
  double after = 0.0, scale = 0.0, before = 0.0;
  outside_.clear();
  for (TetId t : made_) {
    if (!mesh.is_live(t)) continue;
    const TetMesh::TetVerts v = mesh.tet(t);
    if (in_tool({mesh.position(v[0]), mesh.position(v[1]), mesh.position(v[2]), mesh.position(v[3])})) continue;
    const double volume = mesh.volume(t);
    scale += volume;
    if (shape_of(mesh, t).max_cosine > cos_theta_ - 1e-12) {
      after += volume;
      // Most of them are children of a tet below theta, which covered all of them before.
      if (shares_bad_volume(mesh, t, before)) continue;
    }
    outside_.push_back(t);
  }
  // Stricter than the checker's tolerance (1e-9 of the region's volume) by a factor of 10.
  const double tolerance = 1e-10 * scale;
  if (after <= before + tolerance) return false;
  // The rest of before: what the other made tets outside the tool cover of tets below theta.
  for (TetId t : outside_) {
    if (!shares_bad_volume(mesh, t, before)) continue;
    if (after <= before + tolerance) return false;
  }
  return after > before + tolerance;
}

bool Improver::shares_bad_volume(TetMesh& mesh, TetId t, double& before) {
  // A made tet lies in the union of its ancestors (a split's child in its parent, a flip's tets
  // in the polytope they replaced, a move's star in the star it replaced), whose interiors are
  // disjoint: only they can share volume with it, and a child of one ancestor shares all of its
  // own. (A vertex moved within the cut surface's tolerance may take a tet a little outside
  // them: what it shares there is not counted, the strict side of the checker's rule.) Below
  // theta as they were, at their old positions; within rounding of theta counts as good.
  ancestors_.clear();
  mesh.ancestors_at_start(t, ancestors_);
  if (ancestors_.size() == 1) {
    if (!(shape_at_start(mesh, ancestors_[0]).cosine > cos_theta_ + 1e-12)) return false;
    before += mesh.volume(t);
    return true;
  }
  const TetMesh::TetVerts v = mesh.tet(t);
  const std::array<Vec3, 4> p{mesh.position(v[0]), mesh.position(v[1]), mesh.position(v[2]), mesh.position(v[3])};
  bool shared = false;
  for (TetId r : ancestors_) {
    if (!(shape_at_start(mesh, r).cosine > cos_theta_ + 1e-12)) continue;
    const TetMesh::TetVerts c = mesh.tet_at_start(r);
    before += tet_intersection_volume(p, {mesh.position_at_start(c[0]), mesh.position_at_start(c[1]),
                                          mesh.position_at_start(c[2]), mesh.position_at_start(c[3])});
    shared = true;
  }
  return shared;
}

}  // namespace tetcut::detail
