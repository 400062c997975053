#include "tetcut/mechanics/differential.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "tetcut/mechanics/label_rule.hpp"

namespace tetcut::mechanics {
namespace {

std::string say(const auto&... parts) {
  std::ostringstream out;
  out.precision(17);
  (out << ... << parts);
  return out.str();
}

// max |a - b| over the entries, as a fraction of `scale` (raising *worst); false past tolerance.
bool close(const Tensor3& a, const Tensor3& b, double scale, double tolerance, double& worst) {
  double d = 0;
  for (int e = 0; e < 9; ++e) d = std::max(d, std::abs(a[e] - b[e]));
  const double r = scale > 0 ? d / scale : (d > 0 ? INFINITY : 0.0);
  worst = std::max(worst, r);
  return r <= tolerance;
}

}  // namespace

std::optional<std::string> compare(const TensorMassModel& inc, const TensorMassModel& ref, const TetMesh& mesh,
                                   double tolerance, double* worst_out) {
  double worst = 0;
  const std::uint32_t tets = std::max(inc.tet_capacity(), ref.tet_capacity());
  for (std::uint32_t t = 0; t < tets; ++t) {
    const TetId id{t};
    const bool a = t < inc.tet_capacity() && inc.has_tet(id), b = t < ref.tet_capacity() && ref.has_tet(id);
    if (a != b) return say("tet ", t, a ? " is in the incremental model only" : " is missing from the incremental model");
    if (a && inc.label(id) != ref.label(id))
      return say("tet ", t, ": label ", inc.label(id), " incrementally, ", ref.label(id), " rebuilt");
  }
  const std::uint32_t verts = std::max(inc.vertex_capacity(), ref.vertex_capacity());
  for (std::uint32_t v = 0; v < verts; ++v) {
    const VertId id{v};
    const std::uint32_t na = v < inc.vertex_capacity() ? inc.tets_at(id) : 0;
    const std::uint32_t nb = v < ref.vertex_capacity() ? ref.tets_at(id) : 0;
    if (na != nb) return say("vertex ", v, ": ", na, " tets incrementally, ", nb, " rebuilt");
    if (na == 0) continue;
    if (!close(inc.vertex_stiffness(id), ref.vertex_stiffness(id), ref.vertex_scale(id), tolerance, worst))
      return say("vertex ", v, ": stiffness tensor differs from the rebuild's beyond ", tolerance, " of its scale ",
                 ref.vertex_scale(id));
    const double dm = std::abs(inc.mass(id) - ref.mass(id)) / ref.mass(id);
    worst = std::max(worst, dm);
    if (!(dm <= tolerance)) return say("vertex ", v, ": mass ", inc.mass(id), " incrementally, ", ref.mass(id), " rebuilt");
    if (mesh.is_live(id) != (na > 0)) return say("vertex ", v, ": live in the mesh ", mesh.is_live(id), ", tets ", na);
  }
  if (inc.edge_count() != ref.edge_count())
    return say(inc.edge_count(), " edges incrementally, ", ref.edge_count(), " rebuilt");
  for (const TensorMassModel::Edge& e : ref.edge_slots()) {
    if (e.tets == 0) continue;
    const TensorMassModel::Edge* mine = inc.find_edge(e.a, e.b);
    if (mine == nullptr) return say("edge (", e.a.value, ", ", e.b.value, ") is missing from the incremental model");
    if (mine->tets != e.tets)
      return say("edge (", e.a.value, ", ", e.b.value, "): ", mine->tets, " tets incrementally, ", e.tets, " rebuilt");
    if (!close(mine->k, e.k, e.scale, tolerance, worst))
      return say("edge (", e.a.value, ", ", e.b.value, "): stiffness tensor differs from the rebuild's");
  }
  if (worst_out) *worst_out = std::max(*worst_out, worst);
  return std::nullopt;
}

std::optional<std::string> compare(const RenderedSurface& inc, const RenderedSurface& ref, const TetMesh& mesh,
                                   double tolerance, double* worst_out) {
  double worst = 0;
  if (inc.triangle_count() != ref.triangle_count())
    return say(inc.triangle_count(), " surface triangles incrementally, ", ref.triangle_count(), " rebuilt");
  for (const RenderedSurface::Triangle& t : ref.triangle_slots())
    if (t.v[0].valid() && !inc.contains(t))
      return say("surface triangle (", t.v[0].value, ", ", t.v[1].value, ", ", t.v[2].value,
                 ") is missing from the incremental surface");
  const std::uint32_t verts = std::max(inc.vertex_capacity(), ref.vertex_capacity());
  for (std::uint32_t v = 0; v < verts; ++v) {
    const VertId id{v};
    const std::uint32_t na = v < inc.vertex_capacity() ? inc.triangles_at(id) : 0;
    const std::uint32_t nb = v < ref.vertex_capacity() ? ref.triangles_at(id) : 0;
    if (na != nb) return say("vertex ", v, ": ", na, " surface triangles incrementally, ", nb, " rebuilt");
    if (na == 0) continue;
    const double scale = ref.normal_scale(id);
    const double d = norm(inc.normal_sum(id) - ref.normal_sum(id)) / scale;
    worst = std::max(worst, d);
    if (!(d <= tolerance)) return say("vertex ", v, ": normal sum differs from the rebuild's by ", d, " of its scale");
    if (!mesh.is_boundary_vertex(id)) return say("vertex ", v, " has surface triangles but is not on the boundary");
    // Against the mesh's own normal, to the conditioning of the normalisation.
    const double length = norm(ref.normal_sum(id));
    const double off = norm(inc.normal(id) - mesh.boundary_normal(id));
    if (!(off <= 1e-9 * scale / length))
      return say("vertex ", v, ": normal differs from the mesh's boundary_normal by ", off);
  }
  if (worst_out) *worst_out = std::max(*worst_out, worst);
  return std::nullopt;
}

std::optional<std::string> fan_problem(const RenderedSurface& surface) {
  // Per vertex, the far edges (b -> c) of its triangles (a, b, c), grouped by vertex.
  const std::uint32_t n = surface.vertex_capacity();
  std::vector<std::uint32_t> begin(n + 1, 0);
  for (const auto& t : surface.triangle_slots())
    if (t.v[0].valid())
      for (VertId v : t.v) ++begin[v.value + 1];
  for (std::uint32_t v = 0; v < n; ++v) begin[v + 1] += begin[v];
  std::vector<std::array<std::uint32_t, 2>> far(begin[n]);
  std::vector<std::uint32_t> fill(begin.begin(), begin.end() - 1);
  for (const auto& t : surface.triangle_slots())
    if (t.v[0].valid())
      for (int r = 0; r < 3; ++r) far[fill[t.v[r].value]++] = {t.v[(r + 1) % 3].value, t.v[(r + 2) % 3].value};
  for (std::uint32_t v = 0; v < n; ++v) {
    auto first = far.begin() + begin[v], last = far.begin() + begin[v + 1];
    if (first == last) continue;
    std::sort(first, last);
    // A single cycle: every tail once, and following next() from the first returns after all.
    for (auto it = first; it + 1 < last; ++it)
      if ((*it)[0] == (*(it + 1))[0]) return say("vertex ", v, ": two surface triangles leave it by the same edge");
    std::uint32_t at = (*first)[1];
    std::size_t steps = 1;
    while (at != (*first)[0] && steps <= static_cast<std::size_t>(last - first)) {
      const auto next = std::lower_bound(first, last, std::array<std::uint32_t, 2>{at, 0});
      if (next == last || (*next)[0] != at) return say("vertex ", v, ": its surface triangles do not close around it");
      at = (*next)[1];
      ++steps;
    }
    if (steps != static_cast<std::size_t>(last - first))
      return say("vertex ", v, ": its surface triangles form more than one fan");
  }
  return std::nullopt;
}

// ---- the check -------------------------------------------------------------------------------

DifferentialCheck::DifferentialCheck(TetMesh& mesh, ModelParams params, std::vector<std::uint32_t> labels,
                                     double tolerance)
    : params_(std::move(params)), tolerance_(tolerance), model_(mesh, params_, labels), surface_(mesh),
      labels_(std::move(labels)) {
  labels_.resize(mesh.tet_capacity(), 0);
  // The affine fields, centred on the mesh so that their values are of the order of the mesh.
  double extent = 0;
  for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v)
    if (mesh.is_live(VertId{v})) origin_ = mesh.position(VertId{v});
  for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v)
    if (mesh.is_live(VertId{v})) extent = std::max(extent, norm(mesh.position(VertId{v}) - origin_));
  field_scale_ = std::max(extent, 1e-300);
  channel_u_ = mesh.attributes().add_channel("differential_u", 3).value_or(0);
  channel_v_ = mesh.attributes().add_channel("differential_v", 3).value_or(0);
  for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v) {
    if (!mesh.is_live(VertId{v})) continue;
    const Vec3 u = field_u(mesh.position(VertId{v})), w = field_v(mesh.position(VertId{v}));
    model_.set_displacement(VertId{v}, u);
    model_.set_velocity(VertId{v}, w);
    const auto cu = mesh.attributes().value(channel_u_, VertId{v}), cv = mesh.attributes().value(channel_v_, VertId{v});
    cu[0] = u.x, cu[1] = u.y, cu[2] = u.z;
    cv[0] = w.x, cv[1] = w.y, cv[2] = w.z;
  }
}

Vec3 DifferentialCheck::field_u(const Vec3& x) const {
  const Vec3 d = x - origin_;
  return Vec3{0.5 * d.x - 0.25 * d.y + 0.125 * d.z + 1.0, -0.3 * d.x + 0.7 * d.z - 2.0, 0.2 * d.y + 0.1 * d.z};
}
Vec3 DifferentialCheck::field_v(const Vec3& x) const {
  const Vec3 d = x - origin_;
  return Vec3{-0.6 * d.z + 0.5, 0.4 * d.x + 0.9 * d.y, -0.2 * d.x + 0.3 * d.y - 0.8 * d.z + 3.0};
}

void DifferentialCheck::before(const TetMesh& mesh) {
  const auto raw = mesh.raw_tets();
  before_tets_.assign(raw.begin(), raw.end());
  before_positions_.assign(mesh.positions().begin(), mesh.positions().end());
  before_labels_ = labels_;
  before_boxes_.resize(before_tets_.size());
  for (std::uint32_t t = 0; t < before_tets_.size(); ++t) {
    if (!mesh.is_live(TetId{t})) continue;
    auto& box = before_boxes_[t];
    box = {before_positions_[before_tets_[t][0]], before_positions_[before_tets_[t][0]]};
    for (int i = 1; i < 4; ++i) {
      const Vec3& p = before_positions_[before_tets_[t][i]];
      box[0] = {std::min(box[0].x, p.x), std::min(box[0].y, p.y), std::min(box[0].z, p.z)};
      box[1] = {std::max(box[1].x, p.x), std::max(box[1].y, p.y), std::max(box[1].z, p.z)};
    }
  }
}

std::uint32_t DifferentialCheck::locate_label(const Vec3& p) const {
  for (std::uint32_t t = 0; t < before_tets_.size(); ++t) {  // id order: the lowest containing tet
    if (gone_[t] == 0) continue;
    const auto& box = before_boxes_[t];
    if (p.x < box[0].x || p.y < box[0].y || p.z < box[0].z || p.x > box[1].x || p.y > box[1].y || p.z > box[1].z)
      continue;
    const auto& v = before_tets_[t];
    if (tet_contains(before_positions_[v[0]], before_positions_[v[1]], before_positions_[v[2]],
                     before_positions_[v[3]], p))
      return before_labels_[t];
  }
  return TensorMassModel::kNoLabel;
}

std::optional<std::string> DifferentialCheck::label_from_parents(const ChangeLog& log, TetId t,
                                                                  std::uint32_t& label) const {
  const auto entry = std::find_if(log.created.begin(), log.created.end(), [&](const CreatedTet& c) { return c.tet == t; });
  if (entry == log.created.end()) return say("tet ", t.value, ": new after the cut, but not in the log's created tets");
  const auto parents = log.parents_of(*entry);
  if (parents.empty()) return say("tet ", t.value, ": created without a parent");
  for (TetId p : parents)
    if (p.value >= gone_.size() || gone_[p.value] == 0)
      return say("tet ", t.value, ": parent ", p.value, " is not a pre-cut tet the cut took away");
  label = before_labels_[parents.front().value];
  return std::nullopt;
}

void DifferentialCheck::keep_history(std::uint32_t logs) {
  model_.keep_history(logs);
  history_limit_ = logs;
  witness_history_.clear();
}

std::optional<std::string> DifferentialCheck::after(const TetMesh& mesh, const ChangeLog& log) {
  // An undo's witness is the snapshot before the cut it takes back; any other log that changed
  // something is kept for its own undo, as the model keeps it.
  std::optional<Witness> undone;
  if (log.undo && !witness_history_.empty()) {
    undone = std::move(witness_history_.back());
    witness_history_.pop_back();
  } else if (!log.undo && history_limit_ > 0 && (!log.removed.empty() || !log.created.empty() || !log.moved.empty())) {
    if (witness_history_.size() == history_limit_) witness_history_.erase(witness_history_.begin());
    witness_history_.push_back({before_tets_, before_labels_});
  }
  const ApplyProblems problems = model_.apply(mesh, log);
  const std::uint32_t unknown = surface_.apply(mesh, log);
  // The witness's labels: a tet there before keeps its own; another takes the label of the
  // pre-cut tet gone after the cut that contains its centroid (label_rule.hpp).
  gone_.assign(before_tets_.size(), 0);
  for (std::uint32_t t = 0; t < before_tets_.size(); ++t)
    gone_[t] = before_tets_[t][0] != kDeadTetMarker &&
               (!mesh.is_live(TetId{t}) || mesh.raw_tets()[t] != before_tets_[t]);
  labels_.assign(mesh.tet_capacity(), TensorMassModel::kNoLabel);
  for (std::uint32_t t = 0; t < mesh.tet_capacity(); ++t) {
    const TetId id{t};
    if (!mesh.is_live(id)) continue;
    const auto& now = mesh.raw_tets()[t];
    if (t < before_tets_.size() && before_tets_[t] == now) {
      labels_[t] = before_labels_[t];
      continue;
    }
    if (undone && t < undone->tets.size() && undone->tets[t] == now) {  // restored: its label before the cut
      labels_[t] = undone->labels[t];
      continue;
    }
    labels_[t] = locate_label(tet_centroid(mesh.position(VertId{now[0]}), mesh.position(VertId{now[1]}),
                                           mesh.position(VertId{now[2]}), mesh.position(VertId{now[3]})));
    if (labels_[t] == TensorMassModel::kNoLabel)
      if (auto d = label_from_parents(log, id, labels_[t])) return "mechanics: " + *d;
  }
  const TensorMassModel rebuilt(mesh, params_, labels_);
  if (auto d = compare(model_, rebuilt, mesh, tolerance_, &worst_)) return "mechanics: " + *d;
  const RenderedSurface rebuilt_surface(mesh);
  if (auto d = compare(surface_, rebuilt_surface, mesh, tolerance_, &worst_)) return "surface: " + *d;
  if (auto d = fan_problem(surface_)) return "surface: " + *d;
  for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v) {
    const VertId id{v};
    if (!mesh.is_live(id)) continue;
    const auto cu = mesh.attributes().value(channel_u_, id), cv = mesh.attributes().value(channel_v_, id);
    const double du = norm(model_.displacement(id) - Vec3{cu[0], cu[1], cu[2]});
    const double dv = norm(model_.velocity(id) - Vec3{cv[0], cv[1], cv[2]});
    if (!(du <= 1e-12 * field_scale_ && dv <= 1e-12 * field_scale_))
      return say("mechanics: vertex ", v, ": displacement or velocity is not the interpolation the mesh's attributes got (off by ",
                 std::max(du, dv), ")");
  }
  if (problems.total() != 0)
    return say("mechanics: the log does not fit the model: ", problems.removed_not_live, " removed tets it lacked, ",
               problems.created_already_live, " created tets it had, ", problems.parent_not_removed,
               " parents not removed, ", problems.origin_not_live, " vertex origins it lacked");
  if (unknown != 0) return say("surface: ", unknown, " removed tets it did not have");
  return std::nullopt;
}

}  // namespace tetcut::mechanics
