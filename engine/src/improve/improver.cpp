#include "improve/improver.hpp"

#include <algorithm>

#include "core/host_location.hpp"
#include "core/quality.hpp"
#include "remove/removability.hpp"
#include "tetcut/detail/local_tables.hpp"
#include "tetcut/detail/reserve_touched.hpp"

namespace tetcut::detail {
namespace {

// A flip or a move must lift the worst tet it touches by this much (relative): what makes the
// pass end, and keeps it from trading places between equal tets.
constexpr double kMargin = 1e-6;
// Operations per pass: far above what a cut needs (a few dozen), a bound for pathological ones.
constexpr std::uint32_t kMaxOperations = 512;

}  // namespace

void Improver::reserve(std::uint32_t tets) {
  flipper_.reserve();
  splitter_.reserve(tets);
  collapser_.reserve();
  smoother_.reserve();
  reserve_touched(star_, 128);
  reserve_touched(neighbours_, 128);
  collapse_.removed.reserve(128);
  collapse_.added.reserve(128);
  collapse_candidate_.removed.reserve(128);
  collapse_candidate_.added.reserve(128);
  for (auto* v : {&made_, &created_}) reserve_touched(*v, 4096);
  reserve_touched(bad_, 4096);
  reserve_touched(ancestors_, 64);
  host_quality_.reserve(tets);
}

double Improver::collect_made(TetMesh& mesh, const TetMesh::Savepoint& start) {
  made_.clear();
  double worst = 1.0;
  for (const TetMesh::TetBirth& b : mesh.tets_made_since(start))
    if (mesh.is_live(b.tet)) {
      made_.push_back(b.tet);
      worst = std::min(worst, quality(mesh, b.tet));
    }
  return worst;
}

double Improver::floor_of(TetMesh& mesh, double floor_f) {
  double floor = floor_f;
  for (TetId t : made_) {
    ancestors_.clear();
    mesh.ancestors_at_start(t, ancestors_);
    TetId host = ancestors_.front();
    if (ancestors_.size() > 1) {
      // After a flip: the ancestor that holds the tet's centroid.
      const TetMesh::TetVerts v = mesh.tet(t);
      const Vec3 centroid = 0.25 * (mesh.position(v[0]) + mesh.position(v[1]) + mesh.position(v[2]) + mesh.position(v[3]));
      if (const DeepestTet deepest = deepest_at_start(mesh, ancestors_, centroid); deepest.found()) host = deepest.tet();
    }
    double q = 0.0;
    if (const double* known = host_quality_.find(host)) {
      q = *known;
    } else {
      // The host as it was: its vertices were there before the transaction and never move.
      q = quality(mesh, mesh.tet_at_start(host));
      host_quality_.set(host, q);
    }
    floor = std::min(floor, q);
  }
  return floor;
}

bool Improver::may_reshape_star(TetMesh& mesh, VertId v) {
  if (!uncuttable_ || uncuttable_->empty()) return true;
  mesh.vertex_shell(v, star_);
  return !uncuttable_->any_of(mesh, star_);
}

bool Improver::may_flip(TetMesh& mesh, const FlipPlan& plan) const {
  if (!uncuttable_ || uncuttable_->empty()) return true;
  return !uncuttable_->any_of(mesh, plan.removed_tets()) || uncuttable_->all_of(mesh, plan.removed_tets());
}

bool Improver::improve_tet(TetMesh& mesh, TetId t) {
  // Every operation that would lift the tet, planned; the one whose worst touched tet ends best
  // is applied (ties: a flip, then a collapse, then a move, in the order they are tried).
  enum class Best : std::uint8_t { kNone, kFlip, kCollapse, kMove } best = Best::kNone;
  double best_after = 0.0;
  for (int e = 0; e < 6; ++e)
    if (flipper_.plan_edge_removal(mesh, t, e, kMargin, candidate_) && candidate_.worst_after > best_after &&
        may_flip(mesh, candidate_)) {
      plan_ = candidate_;
      best_after = candidate_.worst_after;
      best = Best::kFlip;
    }
  for (int f = 0; f < 4; ++f)
    if (flipper_.plan_face_flip(mesh, t, f, kMargin, candidate_) && candidate_.worst_after > best_after &&
        may_flip(mesh, candidate_)) {
      plan_ = candidate_;
      best_after = candidate_.worst_after;
      best = Best::kFlip;
    }
  // A flip that lifts the tet well past the goal is taken as it is (the dearer plans below would
  // rarely beat it by much).
  if (best_after >= 2.0 * goal_) {
    Flipper::apply(mesh, plan_, created_);
    made_.insert(made_.end(), created_.end() - static_cast<std::ptrdiff_t>(plan_.added_count), created_.end());
    last_ = Operation::kFlip;
    return true;
  }
  const TetMesh::TetVerts corners = mesh.tet(t);
  for (VertId v : corners) {
    if (!mesh.made_in_transaction(v) || !may_reshape_star(mesh, v)) continue;
    // Into any neighbour: v's going removes the tet whichever way it goes.
    mesh.vertex_neighbours(v, neighbours_, star_);
    for (VertId w : neighbours_)
      if (collapser_.plan(mesh, v, w, kMargin, best_after, collapse_candidate_)) {
        std::swap(collapse_, collapse_candidate_);
        best_after = collapse_.worst_after;
        best = Best::kCollapse;
      }
    if (smoother_.plan(mesh, v, kMargin, tool_, smooth_candidate_) && smooth_candidate_.worst_after > best_after) {
      smooth_ = smooth_candidate_;
      best_after = smooth_.worst_after;
      best = Best::kMove;
    }
  }
  const std::size_t before = created_.size();
  switch (best) {
    case Best::kNone:
      if (!insert_on_longest_edge(mesh, t)) return false;
      last_ = Operation::kInsert;
      break;
    case Best::kFlip: Flipper::apply(mesh, plan_, created_); last_ = Operation::kFlip; break;
    case Best::kCollapse: Collapser::apply(mesh, collapse_, created_); last_ = Operation::kCollapse; break;
    case Best::kMove: Smoother::apply(mesh, smooth_, created_); last_ = Operation::kMove; break;
  }
  made_.insert(made_.end(), created_.begin() + static_cast<std::ptrdiff_t>(before), created_.end());
  return true;
}

bool Improver::insert_on_longest_edge(TetMesh& mesh, TetId t) {
  int longest = 0;
  double length = -1.0;
  const TetMesh::TetVerts v = mesh.tet(t);
  for (int e = 0; e < 6; ++e)
    if (const double l = norm(mesh.position(v[kEdgeVerts[e][1]]) - mesh.position(v[kEdgeVerts[e][0]])); l > length) {
      length = l;
      longest = e;
    }
  const Edge edge{v[kEdgeVerts[longest][0]], v[kEdgeVerts[longest][1]], t};
  mesh.edge_shell(t, longest, star_);
  const double worst_before = worst_quality(mesh, star_);
  const TetMesh::Savepoint point = mesh.savepoint();
  const std::size_t before = created_.size();
  if (!splitter_.split(mesh, std::span<const Edge>(&edge, 1), SplitMethod::kTemplates, &created_).ok()) return false;
  const VertId midpoint = mesh.vertices_made_since(point).front().vertex;
  if (may_reshape_star(mesh, midpoint) && smoother_.plan(mesh, midpoint, 0.0, tool_, smooth_candidate_))
    Smoother::apply(mesh, smooth_candidate_, created_);
  // The worst of the midpoint's star now (the split's children, moved).
  mesh.vertex_shell(midpoint, star_);
  const double worst_after = worst_quality(mesh, star_);
  if (worst_after > worst_before * (1.0 + kMargin)) return true;
  mesh.rollback_to(point);
  created_.resize(before);
  return false;
}

void Improver::lift(TetMesh& mesh, ImproveOutcome& out, std::uint32_t& operations) {
  // The checker compares with its own formula: aim a rounding above the floor.
  const double goal = out.floor * (1.0 + 1e-9);
  goal_ = goal;
  for (bool progress = true; progress && operations < kMaxOperations;) {
    progress = false;
    // The made tets below the goal, worst first (ties by id: deterministic).
    bad_.clear();
    for (TetId t : made_)
      if (mesh.is_live(t))
        if (const double q = quality(mesh, t); q < goal) bad_.push_back({q, t});
    if (bad_.empty()) break;
    std::sort(bad_.begin(), bad_.end());
    for (const auto& [ratio, t] : bad_) {
      if (!mesh.is_live(t) || quality(mesh, t) >= goal) continue;
      if (!improve_tet(mesh, t)) continue;
      progress = true;
      (last_ == Operation::kFlip       ? out.flips
       : last_ == Operation::kCollapse ? out.collapses
       : last_ == Operation::kInsert   ? out.insertions
                                       : out.moves) += 1;
      if (++operations == kMaxOperations) break;
    }
  }
  // Slivers left at the cut's surface go with the tissue (the header says when).
  for (TetId t : made_) {
    if (!mesh.is_live(t) || quality(mesh, t) >= goal || mesh.boundary_face_count(t) == 0) continue;
    if (tool_) {
      const TetMesh::TetVerts c = mesh.tet(t);
      if (!intersects(*tool_, mesh.position(c[0]), mesh.position(c[1]), mesh.position(c[2]), mesh.position(c[3]))) continue;
    }
    if (!removability(mesh, t).removable()) continue;
    if (uncuttable_ && uncuttable_->contains(mesh, t)) continue;
    tissue_->remove(mesh, std::span<const TetId>(&t, 1));
    ++out.removed;
  }
}

ImproveOutcome Improver::run(TetMesh& mesh, const TetMesh::Savepoint& start, double floor_f, bool improve,
                             const Ball* reach, const UncuttableTets* uncuttable, TissueRemoval* tissue) {
  ImproveOutcome out;
  host_quality_.clear();
  tool_ = reach;
  uncuttable_ = uncuttable;
  tissue_ = tissue;
  if (!tissue_) {
    own_tissue_.begin(nullptr, 0.0);
    tissue_ = &own_tissue_;
  }
  out.worst_before = out.worst_after = collect_made(mesh, start);
  if (made_.empty()) return out;
  // Every made tet at or above F is above min(F, any host): met, without locating the hosts.
  if (out.worst_before >= floor_f) {
    out.floor = floor_f;
    return out;
  }
  out.floor = floor_of(mesh, floor_f);
  if (improve) {
    created_.clear();
    std::uint32_t operations = 0;
    // The floor is the hosts' of what the transaction made in the end: an operation that leaves
    // a poor host with no made tet in it raises it. So: lift to the floor, measure it again, and
    // lift again while it rose (a few rounds; each only raises the goal).
    for (int round = 0; round < 3 && out.worst_after < out.floor * (1.0 + 1e-9); ++round) {
      lift(mesh, out, operations);
      // The made set again: flips replaced some made tets and some that were there before,
      // whose hosts now count too.
      out.worst_after = collect_made(mesh, start);
      out.floor = floor_of(mesh, floor_f);
    }
  }
  out.met = out.worst_after >= out.floor * (1.0 + 1e-9);
  return out;
}

}  // namespace tetcut::detail
