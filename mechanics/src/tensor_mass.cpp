// The tensor-mass model (tensor_mass.hpp). Tensors are kept in mesh units and scaled by the
// length unit where they are used (K scales with length, mass with its cube), so that the
// model's rest positions are the mesh's own bits (label_rule.hpp compares them exactly).
#include "tetcut/mechanics/tensor_mass.hpp"

#include <algorithm>
#include <bit>
#include <utility>
#include <cmath>
#include <limits>

#include "tetcut/detail/local_tables.hpp"
#include "tetcut/mechanics/label_rule.hpp"

namespace tetcut::mechanics {
namespace {

Vec3 mul(const Tensor3& k, const Vec3& u) {
  return {k[0] * u.x + k[1] * u.y + k[2] * u.z, k[3] * u.x + k[4] * u.y + k[5] * u.z,
          k[6] * u.x + k[7] * u.y + k[8] * u.z};
}
Vec3 mul_transposed(const Tensor3& k, const Vec3& u) {
  return {k[0] * u.x + k[3] * u.y + k[6] * u.z, k[1] * u.x + k[4] * u.y + k[7] * u.z,
          k[2] * u.x + k[5] * u.y + k[8] * u.z};
}
double max_abs(const Tensor3& k) {
  double m = 0;
  for (double x : k) m = std::max(m, std::abs(x));
  return m;
}

// V (lambda mi mj^T + mu mj mi^T + mu (mi . mj) I): the block (i, j) of a tet's stiffness.
Tensor3 block(const Vec3& mi, const Vec3& mj, double volume, const Lame& l) {
  const double a[3] = {mi.x, mi.y, mi.z}, b[3] = {mj.x, mj.y, mj.z};
  const double d = dot(mi, mj);
  Tensor3 k{};
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c)
      k[3 * r + c] = volume * (l.lambda * a[r] * b[c] + l.mu * b[r] * a[c] + (r == c ? l.mu * d : 0.0));
  return k;
}

// The index slot an edge's probe starts at. Edges are homed by their lower vertex, a window of
// 2^kEdgeWindowShift slots per vertex id (the higher vertex picks the slot in it), so the edges
// of the vertices a cut touches share cache lines and pages: the slots a cut reads lie where the
// same cut on a smaller mesh reads them, however large the mesh around it. A hash of the whole
// pair scattered them over the index (32 MB at 1M tets, one page each), and the same update took
// 1.3 times as long on 64 livers as on one (mechanics_bench BM_UpdateScalingSameWork).
// 32 slots for the ~6 edges a vertex is lower of (up to ~20 on the low ids Gmsh gives boundary
// vertices) keep the probes as short as the hash's; reserve() sizes the index to every window.
constexpr unsigned kEdgeWindowShift = 5;
std::size_t edge_home(VertId a, VertId b, std::size_t mask) {
  std::uint64_t x = b.value;
  x *= 0x9E3779B97F4A7C15ULL;
  return ((std::size_t{a.value} << kEdgeWindowShift) + static_cast<std::size_t>(x >> (64 - kEdgeWindowShift))) & mask;
}

}  // namespace

std::optional<std::string> validate(const ModelParams& params) {
  if (params.materials.empty()) return "at least one material is needed";
  for (const Material& m : params.materials)
    if (auto problem = validate(m)) return problem;
  for (std::size_t i = 0; i < params.label_materials.size(); ++i) {
    const auto& [label, m] = params.label_materials[i];
    if (i > 0 && label <= params.label_materials[i - 1].first)
      return "label materials must be sorted by label, each label once (label " + std::to_string(label) + ")";
    if (auto problem = validate(m)) return "label " + std::to_string(label) + ": " + *problem;
  }
  if (!std::isfinite(params.length_unit) || params.length_unit <= 0) return "the length unit must be positive";
  if (!std::isfinite(params.damping) || params.damping < 0) return "damping must be non-negative";
  if (!is_finite(params.gravity)) return "gravity must be finite";
  return std::nullopt;
}

TensorMassModel::TensorMassModel(const TetMesh& mesh, ModelParams params, std::span<const std::uint32_t> tet_labels)
    : params_(std::move(params)) {
  reserve(mesh.tet_capacity() + mesh.tet_capacity() / 2, mesh.vertex_capacity() + mesh.vertex_capacity() / 2);
  grow(mesh.tet_capacity(), mesh.vertex_capacity());
  for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v) rest_[v] = mesh.position(VertId{v});
  for (std::uint32_t t = 0; t < mesh.tet_capacity(); ++t) {
    const TetId id{t};
    if (!mesh.is_live(id)) continue;
    const auto verts = mesh.tet(id);
    tets_[t] = {verts[0].value, verts[1].value, verts[2].value, verts[3].value};
    labels_[t] = tet_labels.empty() ? 0 : tet_labels[t];
    accumulate(id, +1.0);
  }
}

void TensorMassModel::reserve(std::uint32_t tets, std::uint32_t vertices) {
  tets_.reserve(tets);
  labels_.reserve(tets);
  created_labels_.reserve(std::max<std::size_t>(created_labels_.capacity(), 4096));
  interpolated_.reserve(std::max<std::size_t>(interpolated_.capacity(), 4096));
  for (auto* a : {&rest_, &u_, &v_, &force_}) a->reserve(vertices);
  vertex_k_.reserve(vertices);
  vertex_scale_.reserve(vertices);
  mass_.reserve(vertices);
  vertex_tets_.reserve(vertices);
  fixed_.reserve(vertices);
  // About 7 edges per vertex in a tet mesh (Euler: E ~ V + T, T ~ 5-6 V).
  const std::size_t edges = std::size_t{vertices} * 8;
  edges_.reserve(edges);
  free_edges_.reserve(edges);
  const std::size_t slots = std::bit_ceil(std::max(2 * edges, std::size_t{vertices} << kEdgeWindowShift));
  if (edge_index_.size() < slots) grow_edge_index(slots);
}

void TensorMassModel::grow(std::uint32_t tets, std::uint32_t vertices) {
  if (tets > tets_.size()) {
    tets_.resize(tets, {kDead, kDead, kDead, kDead});
    labels_.resize(tets, kNoLabel);
  }
  if (vertices > mass_.size()) {
    for (auto* a : {&rest_, &u_, &v_, &force_}) a->resize(vertices);
    vertex_k_.resize(vertices);
    vertex_scale_.resize(vertices, 0.0);
    mass_.resize(vertices, 0.0);
    vertex_tets_.resize(vertices, 0);
    fixed_.resize(vertices, 0);
  }
}

const Material& TensorMassModel::material_of(std::uint32_t label) const {
  const auto& listed = params_.label_materials;
  if (!listed.empty()) {  // a few regions: a binary search, no allocation
    const auto it = std::lower_bound(listed.begin(), listed.end(), label,
                                     [](const auto& entry, std::uint32_t l) { return entry.first < l; });
    if (it != listed.end() && it->first == label) return it->second;
  }
  return params_.materials[std::min<std::size_t>(label, params_.materials.size() - 1)];
}

void TensorMassModel::accumulate(TetId t, double sign) {
  const auto& tv = tets_[t.value];
  const Vec3 p[4] = {rest_[tv[0]], rest_[tv[1]], rest_[tv[2]], rest_[tv[3]]};
  const double six_v = dot(cross(p[1] - p[0], p[2] - p[0]), p[3] - p[0]);
  const double volume = six_v / 6.0;
  // Gradient of vertex i's barycentric coordinate: minus its opposite face's outward area
  // vector over 3V (kFaceVerts is counter-clockwise from outside), i.e. -cross / six_v.
  Vec3 m[4];
  for (int i = 0; i < 4; ++i) {
    const auto& f = kFaceVerts[i];
    m[i] = (-1.0 / six_v) * cross(p[f[1]] - p[f[0]], p[f[2]] - p[f[0]]);
  }
  const Material& material = material_of(labels_[t.value]);
  const Lame l = lame(material);
  const double unit = params_.length_unit;
  const double quarter_mass = material.density * volume * unit * unit * unit / 4.0;
  for (int i = 0; i < 4; ++i) {
    const std::uint32_t vi = tv[i];
    const Tensor3 k = block(m[i], m[i], volume * unit, l);
    for (int e = 0; e < 9; ++e) vertex_k_[vi][e] += sign * k[e];
    vertex_scale_[vi] += sign * max_abs(k);
    mass_[vi] += sign * quarter_mass;
    if (sign > 0) {
      ++vertex_tets_[vi];
    } else if (--vertex_tets_[vi] == 0) {
      // No tet left: exactly nothing, not the residue of the subtractions.
      vertex_k_[vi] = Tensor3{};
      vertex_scale_[vi] = mass_[vi] = 0.0;
    }
  }
  for (const auto& ev : kEdgeVerts) {
    int i = ev[0], j = ev[1];
    if (tv[i] > tv[j]) std::swap(i, j);
    const VertId a{tv[i]}, b{tv[j]};
    const std::uint32_t slot = edge_slot(a, b, sign > 0);
    if (slot == kEmpty) continue;  // subtracting an edge the model does not have: a corrupt log
    Edge& edge = edges_[slot];
    const Tensor3 k = block(m[i], m[j], volume * unit, l);
    for (int e = 0; e < 9; ++e) edge.k[e] += sign * k[e];
    edge.scale += sign * max_abs(k);
    if (sign > 0) {
      ++edge.tets;
    } else if (--edge.tets == 0) {
      release_edge(slot);
    }
  }
}

// ---- the edge table ------------------------------------------------------------------------

void TensorMassModel::grow_edge_index(std::size_t capacity) {
  edge_index_.assign(capacity, kEmpty);
  const std::size_t mask = capacity - 1;
  for (std::uint32_t s = 0; s < edges_.size(); ++s) {
    if (edges_[s].tets == 0) continue;
    std::size_t h = edge_home(edges_[s].a, edges_[s].b, mask);
    while (edge_index_[h] != kEmpty) h = (h + 1) & mask;
    edge_index_[h] = s;
  }
}

std::uint32_t TensorMassModel::edge_slot(VertId a, VertId b, bool create) {
  std::size_t mask = edge_index_.size() - 1;
  std::size_t h = edge_home(a, b, mask);
  while (edge_index_[h] != kEmpty) {
    const Edge& e = edges_[edge_index_[h]];
    if (e.a == a && e.b == b) return edge_index_[h];
    h = (h + 1) & mask;
  }
  if (!create) return kEmpty;
  if (2 * (live_edges_ + 1) > edge_index_.size()) {  // keep the load under one half
    grow_edge_index(2 * edge_index_.size());
    mask = edge_index_.size() - 1;
    h = edge_home(a, b, mask);
    while (edge_index_[h] != kEmpty) h = (h + 1) & mask;
  }
  std::uint32_t slot;
  if (!free_edges_.empty()) {
    slot = free_edges_.back();
    free_edges_.pop_back();
  } else {
    slot = static_cast<std::uint32_t>(edges_.size());
    edges_.push_back({});
  }
  edges_[slot] = Edge{a, b, Tensor3{}, 0.0, 0};
  edge_index_[h] = slot;
  ++live_edges_;
  return slot;
}

void TensorMassModel::release_edge(std::uint32_t slot) {
  const Edge& e = edges_[slot];
  const std::size_t mask = edge_index_.size() - 1;
  std::size_t h = edge_home(e.a, e.b, mask);
  while (edge_index_[h] != slot) h = (h + 1) & mask;
  // Backward-shift deletion (linear probing keeps no tombstones).
  std::size_t hole = h, next = (h + 1) & mask;
  while (edge_index_[next] != kEmpty) {
    const Edge& moved = edges_[edge_index_[next]];
    const std::size_t home = edge_home(moved.a, moved.b, mask);
    // Move it into the hole unless its home lies cyclically in (hole, next].
    const bool stays = hole <= next ? (home > hole && home <= next) : (home > hole || home <= next);
    if (!stays) {
      edge_index_[hole] = edge_index_[next];
      hole = next;
    }
    next = (next + 1) & mask;
  }
  edge_index_[hole] = kEmpty;
  edges_[slot] = Edge{};
  free_edges_.push_back(slot);
  --live_edges_;
}

const TensorMassModel::Edge* TensorMassModel::find_edge(VertId a, VertId b) const {
  if (b < a) std::swap(a, b);
  const std::size_t mask = edge_index_.size() - 1;
  std::size_t h = edge_home(a, b, mask);
  while (edge_index_[h] != kEmpty) {
    const Edge& e = edges_[edge_index_[h]];
    if (e.a == a && e.b == b) return &e;
    h = (h + 1) & mask;
  }
  return nullptr;
}

// ---- the change log ------------------------------------------------------------------------

std::uint32_t TensorMassModel::inherited_label(const TetMesh& mesh, const ChangeLog& log, const CreatedTet& c,
                                               ApplyProblems& problems) const {
  const auto parents = log.parents_of(c);
  for (TetId p : parents)
    if (!std::binary_search(log.removed.begin(), log.removed.end(), p)) ++problems.parent_not_removed;
  const auto cv = mesh.tet(c.tet);
  const Vec3 centroid = tet_centroid(mesh.position(cv[0]), mesh.position(cv[1]), mesh.position(cv[2]),
                                     mesh.position(cv[3]));
  return mechanics::inherited_label(
      parents, log.removed, [&](TetId p) { return has_tet(p); }, [&](TetId p) { return labels_[p.value]; },
      [&](TetId p) {
        const auto& pv = tets_[p.value];
        return tet_contains(rest_[pv[0]], rest_[pv[1]], rest_[pv[2]], rest_[pv[3]], centroid);
      });
}

void TensorMassModel::keep_history(std::uint32_t logs) {
  if (logs == history_.size()) return;
  history_.assign(logs, Taken{});  // a ring of another size: what it held is forgotten
  history_top_ = history_count_ = 0;
}

// Before `log` is applied: the labels of the tets it removes and the state of the vertices it
// removes or moves, in the ring's next slot.
void TensorMassModel::keep(const ChangeLog& log) {
  if (history_.empty() || (log.removed.empty() && log.created.empty() && log.moved.empty())) return;
  history_top_ = static_cast<std::uint32_t>((history_top_ + 1) % history_.size());
  history_count_ = std::min<std::uint32_t>(history_count_ + 1, static_cast<std::uint32_t>(history_.size()));
  Taken& k = history_[history_top_];
  k.tets.clear();
  k.vertices.clear();
  for (TetId t : log.removed)
    if (has_tet(t)) k.tets.emplace_back(t, labels_[t.value]);
  std::sort(k.tets.begin(), k.tets.end());
  auto state = [&](VertId v) {
    if (v.value < u_.size()) k.vertices.push_back({v.value, u_[v.value], v_[v.value], fixed_[v.value] != 0});
  };
  for (VertId v : log.removed_vertices) state(v);
  for (const MovedVertex& mv : log.moved) state(mv.vertex);
  std::sort(k.vertices.begin(), k.vertices.end(),
            [](const Interpolated& a, const Interpolated& b) { return a.vertex < b.vertex; });
}

const TensorMassModel::Interpolated* TensorMassModel::taken_state(const Taken* taken, VertId v) const {
  if (!taken) return nullptr;
  const auto it = std::lower_bound(taken->vertices.begin(), taken->vertices.end(), v.value,
                                   [](const Interpolated& x, std::uint32_t id) { return x.vertex < id; });
  return it != taken->vertices.end() && it->vertex == v.value ? &*it : nullptr;
}

ApplyProblems TensorMassModel::apply(const TetMesh& mesh, const ChangeLog& log) {
  const MeshReadScope reading(mesh, "TensorMassModel::apply()");
  ApplyProblems problems;
  grow(mesh.tet_capacity(), mesh.vertex_capacity());
  // An undo takes the newest kept slot; any other log keeps what it takes.
  const Taken* taken = nullptr;
  if (log.undo && history_count_ > 0) {
    taken = &history_[history_top_];
    history_top_ = static_cast<std::uint32_t>((history_top_ + history_.size() - 1) % history_.size());
    --history_count_;
  } else if (!log.undo) {
    keep(log);
  }
  // Created and moved vertices: their origins are vertices from before, whose values are still
  // here. All are computed before any is written: a moved vertex is the origin of others.
  interpolated_.clear();
  auto interpolate = [&](const CreatedVertex& cv) {
    if (log.undo) {  // restored (count 0): the state kept, else at rest and free
      const Interpolated* kept = taken_state(taken, cv.vertex);
      interpolated_.push_back(kept ? *kept : Interpolated{cv.vertex.value, {}, {}, false});
      return;
    }
    Interpolated out{cv.vertex.value, {}, {}, cv.count > 0};
    for (std::uint8_t i = 0; i < cv.count; ++i) {
      const std::uint32_t f = cv.from[i].value;
      if (f >= vertex_tets_.size() || vertex_tets_[f] == 0) {
        ++problems.origin_not_live;
        out.fixed = false;
        continue;
      }
      out.u = out.u + cv.weight[i] * u_[f];
      out.v = out.v + cv.weight[i] * v_[f];
      out.fixed = out.fixed && fixed_[f] != 0;
    }
    interpolated_.push_back(out);
  };
  for (const CreatedVertex& cv : log.vertices) interpolate(cv);
  for (const MovedVertex& mv : log.moved) {
    if (!log.undo) {
      interpolate(mv);
    } else if (const Interpolated* kept = taken_state(taken, mv.vertex)) {  // moved back: its state then
      interpolated_.push_back(*kept);
    }
  }
  for (const Interpolated& x : interpolated_) {
    fixed_[x.vertex] = x.fixed ? 1 : 0;
    u_[x.vertex] = x.fixed ? Vec3{} : x.u;
    v_[x.vertex] = x.fixed ? Vec3{} : x.v;
  }
  created_labels_.clear();
  for (const CreatedTet& c : log.created) {
    if (taken) {  // restored: its label when the undone cut took it
      const auto it = std::lower_bound(taken->tets.begin(), taken->tets.end(), std::pair<TetId, std::uint32_t>{c.tet, 0});
      if (it != taken->tets.end() && it->first == c.tet) {
        created_labels_.push_back(it->second);
        continue;
      }
    }
    created_labels_.push_back(inherited_label(mesh, log, c, problems));
  }
  for (TetId t : log.removed) {
    if (!has_tet(t)) {
      ++problems.removed_not_live;
      continue;
    }
    accumulate(t, -1.0);
    tets_[t.value] = {kDead, kDead, kDead, kDead};
    labels_[t.value] = kNoLabel;
  }
  for (std::size_t k = 0; k < log.created.size(); ++k) {
    const TetId t = log.created[k].tet;
    if (has_tet(t)) {
      ++problems.created_already_live;
      accumulate(t, -1.0);
    }
    const auto verts = mesh.tet(t);
    for (VertId v : verts) rest_[v.value] = mesh.position(v);
    tets_[t.value] = {verts[0].value, verts[1].value, verts[2].value, verts[3].value};
    labels_[t.value] = created_labels_[k];
    accumulate(t, +1.0);
  }
  // Not on the way (a vertex whose tets are all replaced drops to none between removal and
  // creation and keeps its state): only a vertex the cut left without tets loses it.
  for (VertId v : log.removed_vertices) {
    if (v.value >= vertex_tets_.size() || vertex_tets_[v.value] != 0) continue;
    u_[v.value] = v_[v.value] = Vec3{};
    fixed_[v.value] = 0;
  }
  return problems;
}

// ---- boundary conditions, stepping, energy ---------------------------------------------------

void TensorMassModel::set_fixed(VertId v, bool fixed) {
  fixed_[v.value] = fixed ? 1 : 0;
  if (fixed) u_[v.value] = v_[v.value] = Vec3{};
}

std::uint32_t TensorMassModel::fix_where(const TetMesh& mesh, const std::function<bool(const Vec3&)>& predicate) {
  std::uint32_t n = 0;
  for (std::uint32_t v = 0; v < vertex_capacity(); ++v) {
    if (vertex_tets_[v] == 0 || !predicate(mesh.position(VertId{v}))) continue;
    set_fixed(VertId{v}, true);
    ++n;
  }
  return n;
}

// out = sign K x, one pass over the vertices and one over the edges.
template <int kSign>
void TensorMassModel::product(std::span<const Vec3> x, std::vector<Vec3>& out) const {
  out.resize(vertex_capacity());
  for (std::uint32_t i = 0; i < vertex_capacity(); ++i) out[i] = double{kSign} * mul(vertex_k_[i], x[i]);
  for (const Edge& e : edges_) {
    if (e.tets == 0) continue;
    out[e.a.value] = out[e.a.value] + double{kSign} * mul(e.k, x[e.b.value]);
    out[e.b.value] = out[e.b.value] + double{kSign} * mul_transposed(e.k, x[e.a.value]);
  }
}

void TensorMassModel::elastic_forces(std::vector<Vec3>& out) const { product<-1>(u_, out); }

void TensorMassModel::stiffness_product(std::span<const Vec3> x, std::vector<Vec3>& out) const {
  product<1>(x, out);
}

void TensorMassModel::step(double dt) {
  elastic_forces(force_);
  const double damp = 1.0 / (1.0 + params_.damping * dt);
  for (std::uint32_t i = 0; i < vertex_capacity(); ++i) {
    if (vertex_tets_[i] == 0 || fixed_[i]) continue;
    const Vec3 a = (1.0 / mass_[i]) * force_[i] + params_.gravity;
    v_[i] = damp * (v_[i] + dt * a);
    u_[i] = u_[i] + dt * v_[i];
  }
}

Energy TensorMassModel::energy() const {
  Energy e;
  for (std::uint32_t i = 0; i < vertex_capacity(); ++i) {
    if (vertex_tets_[i] == 0) continue;
    e.kinetic += 0.5 * mass_[i] * dot(v_[i], v_[i]);
    e.elastic += 0.5 * dot(u_[i], mul(vertex_k_[i], u_[i]));
    e.gravity -= mass_[i] * dot(params_.gravity, u_[i]);
  }
  for (const Edge& edge : edges_)
    if (edge.tets != 0) e.elastic += dot(u_[edge.a.value], mul(edge.k, u_[edge.b.value]));
  return e;
}

TensorMassModel::StableStep TensorMassModel::stable_time_step(const TetMesh& mesh) const {
  (void)mesh;
  double h = std::numeric_limits<double>::infinity();
  for (const auto& tv : tets_) {
    if (tv[0] == kDead) continue;
    const Vec3 p[4] = {rest_[tv[0]], rest_[tv[1]], rest_[tv[2]], rest_[tv[3]]};
    const double six_v = dot(cross(p[1] - p[0], p[2] - p[0]), p[3] - p[0]);
    for (int i = 0; i < 4; ++i) {  // altitude over face i: 3V / area = six_v / |2 area|
      const auto& f = kFaceVerts[i];
      h = std::min(h, six_v / norm(cross(p[f[1]] - p[f[0]], p[f[2]] - p[f[0]])));
    }
  }
  double c = 0;
  for (const Material& m : params_.materials) c = std::max(c, pressure_wave_speed(m));
  for (const auto& entry : params_.label_materials) c = std::max(c, pressure_wave_speed(entry.second));
  StableStep s;
  s.min_altitude = h * params_.length_unit;
  s.wave_speed = c;
  s.dt = s.min_altitude / c;
  return s;
}

std::optional<Vec3> TensorMassModel::rest_point(const TetMesh& mesh, const Vec3& x,
                                                const std::function<TetId(const Vec3&)>& locate_at_rest,
                                                std::uint32_t max_steps) const {
  const double to_mesh = 1.0 / params_.length_unit;
  // Barycentric coordinates of p in tet t, the tet's vertices placed by `place`.
  auto barycentric = [&](TetId t, const Vec3& p, bool deformed, double (&bary)[4]) {
    const auto tv = mesh.tet(t);
    Vec3 q[4];
    for (int i = 0; i < 4; ++i) q[i] = mesh.position(tv[i]) + (deformed ? to_mesh * u_[tv[i].value] : Vec3{});
    const double six_v = dot(cross(q[1] - q[0], q[2] - q[0]), q[3] - q[0]);
    int worst = 0;
    for (int i = 0; i < 4; ++i) {
      const auto& f = kFaceVerts[i];
      bary[i] = dot(cross(q[f[1]] - q[f[0]], q[f[2]] - q[f[0]]), p - q[f[0]]) / -six_v;
      if (bary[i] < bary[worst]) worst = i;
    }
    return worst;
  };
  // The start: X <- x - u(X), u interpolated in the rest tet holding X.
  Vec3 guess = x;
  TetId t = locate_at_rest(guess);
  for (int k = 0; k < 4 && t.valid(); ++k) {
    double bary[4];
    barycentric(t, guess, false, bary);
    Vec3 u{};
    for (int i = 0; i < 4; ++i) u = u + bary[i] * u_[mesh.vertex(t, i).value];
    const TetId next = locate_at_rest(x - to_mesh * u);
    if (!next.valid()) break;
    guess = x - to_mesh * u;
    t = next;
  }
  for (std::uint32_t step = 0; step < max_steps && mesh.is_live(t); ++step) {
    double bary[4];
    const int worst = barycentric(t, x, true, bary);
    if (bary[worst] >= -1e-12) {
      Vec3 p{};
      for (int i = 0; i < 4; ++i) p = p + bary[i] * mesh.position(mesh.vertex(t, i));
      return p;
    }
    const FaceRef next = mesh.neighbour(t, worst);
    if (!next.valid()) return std::nullopt;
    t = next.tet;
  }
  return std::nullopt;
}

}  // namespace tetcut::mechanics
