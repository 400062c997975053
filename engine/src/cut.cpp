#include "tetcut/cut.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "tetcut/local_tables.hpp"
#include "tetcut/quality.hpp"

namespace tetcut {
namespace {

using Clock = std::chrono::steady_clock;

double micros(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double, std::micro>(b - a).count();
}

RemovalOptions removal_options(const CutParams& p) {
  RemovalOptions o;
  o.strategy = p.strategy;
  o.max_path_depth = static_cast<int>(p.search_depth);
  return o;
}


}  // namespace

std::optional<std::string> validate(const CutParams& p) {
  auto positive = [](double x) { return std::isfinite(x) && x > 0.0; };
  if (!positive(p.tool_diameter)) return "tool diameter must be a positive finite length";
  if (!positive(p.d_ref_factor)) return "D_ref factor must be a positive finite number";
  if (!std::isfinite(p.p) || p.p <= 1.0) return "p must be a finite number greater than 1";
  if (p.search_depth == 0 || p.search_depth > 64) return "search depth must be between 1 and 64";
  if (p.max_refine_iterations == 0 || p.max_refine_iterations > 64) return "refinement iteration bound must be between 1 and 64";
  if (p.max_tets_created == 0) return "the per-cut tet budget must be positive";
  return std::nullopt;
}

Cutter::Cutter(TetMesh& mesh, const CutParams& params)
    // The grid's cell is the mean edge length, so that a tet spans a few cells at most.
    : mesh_(mesh), params_(params), index_(mesh.mean_edge_length()), remover_(removal_options(params)) {
  // Headroom of half the mesh again: cuts grow it (refinement creates more than removal takes)
  // and a reallocation of a million-tet array in the middle of a cut is a latency spike.
  const std::uint32_t tets = mesh_.tet_capacity() + mesh_.tet_capacity() / 2 + 4096;
  const std::uint32_t vertices = mesh_.vertex_capacity() + mesh_.vertex_capacity() / 2 + 1024;
  mesh_.reserve(tets, vertices);
  index_.build(mesh_);
  scale_ = measure_scale(mesh_);
  refiner_.reserve(tets);
  remover_.reserve(tets, vertices);
}

std::optional<std::string> Cutter::set_params(const CutParams& params) {
  if (auto invalid = validate(params)) return invalid;
  const bool removal_changed = params.strategy != params_.strategy || params.search_depth != params_.search_depth;
  params_ = params;
  if (removal_changed) {
    remover_ = Remover(removal_options(params_));
    remover_.reserve(mesh_.tet_capacity() + mesh_.tet_capacity() / 2 + 4096,
                     mesh_.vertex_capacity() + mesh_.vertex_capacity() / 2 + 1024);
  }
  return std::nullopt;
}

TetId Cutter::tet_containing(const Vec3& p) {
  index_.query(mesh_, Ball{p, 0.0}, hit_);
  return hit_.empty() ? kNoTet : hit_.front();
}

CutReport Cutter::cut(const Vec3& centre, ChangeLog* log) {
  CutReport report;
  net_removed_.clear();
  net_created_.clear();
  auto invalid = validate(params_);
  if (!invalid) invalid = check_scale(scale_, params_.tool_diameter, params_.d_ref_factor, params_.max_tets_created);
  if (invalid) {
    report.ok = false;
    report.failure = *invalid;
    return report;
  }
  const Clock::time_point t0 = Clock::now();
  const Ball tool{centre, params_.tool_diameter / 2};
  const double d_ref = params_.d_ref_factor * params_.tool_diameter;

  // Locate (paper 3.1).
  index_.query(mesh_, tool, hit_);
  report.tets_hit = static_cast<std::uint32_t>(hit_.size());
  const Clock::time_point t1 = Clock::now();
  report.time.locate_us = micros(t0, t1);
  if (hit_.empty()) {
    report.time.total_us = report.time.locate_us;
    return report;
  }

  log_.clear();
  mesh_.begin_transaction();
  auto fail = [&](std::string why) {
    mesh_.rollback();
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
  refine.max_tets_created = params_.max_tets_created;
  const RefineReport refined = refiner_.refine(mesh_, hit_, refine, region_, &log_);
  if (refined.refusal != SplitRefusal::kNone)
    return fail(std::string("refinement refused: ") + to_string(refined.refusal));
  report.refine_iterations = refined.iterations;
  report.edges_split = refined.edges_split;
  report.tets_refined = refined.tets_removed;
  const Clock::time_point t2 = Clock::now();
  report.time.refine_us = micros(t1, t2);

  // Select T_removal (paper 3.3): inside the tool (centroid in the ball), no edge over D_ref.
  removal_.clear();
  removal_verts_.clear();
  for (TetId t : region_) {
    if (!mesh_.is_live(t)) continue;
    const auto v = mesh_.tet(t);
    Vec3 centroid{};
    for (VertId x : v) centroid = centroid + 0.25 * mesh_.position(x);
    if (norm(centroid - tool.centre) > tool.radius) continue;
    bool short_edges = true;
    for (int e = 0; e < 6 && short_edges; ++e)
      short_edges = norm(mesh_.position(v[kEdgeVerts[e][1]]) - mesh_.position(v[kEdgeVerts[e][0]])) <= d_ref;
    if (short_edges) {
      removal_.push_back(t);
      removal_verts_.push_back(v);
    }
  }
  report.requested = static_cast<std::uint32_t>(removal_.size());
  const Clock::time_point t3 = Clock::now();
  report.time.select_us = micros(t2, t3);

  // Remove one by one (paper 3.3-3.7); a tet already taken by an earlier neighbour set is gone.
  remove_selected(report);
  if (!report.ok) return fail(report.failure);
  const Clock::time_point t4 = Clock::now();
  report.time.remove_us = micros(t3, t4);
  finish(report, log);
  report.time.total_us = micros(t0, Clock::now());
  return report;
}

CutReport Cutter::remove(TetId t, ChangeLog* log) {
  CutReport report;
  net_removed_.clear();
  net_created_.clear();
  if (!mesh_.is_live(t)) {
    report.ok = false;
    report.failure = "tet " + std::to_string(t.value) + " is not live";
    return report;
  }
  const Clock::time_point t0 = Clock::now();
  log_.clear();
  mesh_.begin_transaction();
  removal_.assign(1, t);
  removal_verts_.assign(1, mesh_.tet(t));
  report.requested = 1;
  remove_selected(report);
  if (!report.ok) {
    mesh_.rollback();
    return report;
  }
  report.time.remove_us = micros(t0, Clock::now());
  finish(report, log);
  report.time.total_us = report.time.remove_us;
  return report;
}

void Cutter::remove_selected(CutReport& report) {
  const RemovalReport before = remover_.report();
  // Counted per request here: the Remover's running total of unresolved tets goes down when a
  // tet left unresolved by an earlier cut goes now, so its difference can be negative.
  std::uint32_t unresolved = 0;
  tried_.assign(removal_.size(), 0);
  // An id whose tet an earlier request removed may now name a tet a refinement made elsewhere.
  auto selected = [&](std::size_t i) {
    return mesh_.is_live(removal_[i]) && mesh_.tet(removal_[i]) == removal_verts_[i];
  };
  auto request = [&](std::size_t i) {
    tried_[i] = 1;
    if (remover_.remove(mesh_, removal_[i], &log_).outcome == RemovalOutcome::kUnresolved) ++unresolved;
    if (log_.created.size() <= params_.max_tets_created) return true;
    report.ok = false;
    report.failure = "the removal would exceed the per-cut tet budget";
    return false;
  };
  // Outside in, as the cautery burns: in rounds, every selected tet that is on the surface now,
  // until a round finds none; then the rest (a tool inside the mesh) in id order. Taking a tet
  // before the tets between it and the surface would open a cavity under a thin roof, and the
  // paper's statistics are about "removing a tetrahedron on the mesh surface" (3.3, Table 1).
  for (bool progress = true; progress;) {
    progress = false;
    for (std::size_t i = 0; i < removal_.size(); ++i) {
      if (tried_[i] || !selected(i) || mesh_.boundary_face_count(removal_[i]) == 0) continue;
      progress = true;
      if (!request(i)) return;
    }
  }
  for (std::size_t i = 0; i < removal_.size(); ++i)
    if (!tried_[i] && selected(i) && !request(i)) return;
  const RemovalReport& after = remover_.report();
  auto delta = [](std::uint64_t a, std::uint64_t b) { return static_cast<std::uint32_t>(a - b); };
  report.tets_removed = delta(after.tets_removed, before.tets_removed);
  report.direct = delta(after.direct, before.direct);
  report.vertex_singularities = delta(after.vertex_singularities, before.vertex_singularities);
  report.edge_singularities = delta(after.edge_singularities, before.edge_singularities);
  report.resolved_by_neighbours = delta(after.resolved_by_neighbours, before.resolved_by_neighbours);
  report.resolved_by_refinement = delta(after.resolved_by_refinement, before.resolved_by_refinement);
  report.resolved_by_flood = delta(after.resolved_by_flood, before.resolved_by_flood);
  report.unresolved = unresolved;
}

// Commits the transaction, brings the index up to date with the net changes, and reports the
// worst new tet.
void Cutter::finish(CutReport& report, ChangeLog* log) {
  mesh_.transaction_changes(net_removed_, net_created_);
  mesh_.commit();
  for (TetId t : net_removed_) index_.erase(t);
  for (TetId t : net_created_) index_.insert(mesh_, t);
  for (TetId t : net_created_) {
    const auto v = mesh_.tet(t);
    report.min_radius_ratio = std::min(
        report.min_radius_ratio, radius_ratio(mesh_.position(v[0]), mesh_.position(v[1]), mesh_.position(v[2]), mesh_.position(v[3])));
  }
  report.tets_created = static_cast<std::uint32_t>(net_created_.size());
  if (log) {
    log->removed.insert(log->removed.end(), log_.removed.begin(), log_.removed.end());
    log->created.insert(log->created.end(), log_.created.begin(), log_.created.end());
    log->vertices.insert(log->vertices.end(), log_.vertices.begin(), log_.vertices.end());
  }
}

}  // namespace tetcut
