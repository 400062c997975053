#include "refine/edge_split.hpp"

#include <algorithm>
#include <cassert>
#include <tuple>

#include "core/quality.hpp"
#include "refine/split_templates.hpp"
#include "tetcut/detail/local_tables.hpp"
#include "tetcut/detail/reserve_touched.hpp"
#include "tetcut/predicates.hpp"

namespace tetcut {
namespace {

// The midpoint exactly as TetMesh::add_vertex_on_edge(a, b, 0.5) will compute it, so that the
// orientation checked while planning is the orientation applied (the same bits from either end).
Vec3 midpoint(const Vec3& a, const Vec3& b) { return (1.0 - 0.5) * a + 0.5 * b; }

using Labels = std::array<std::uint8_t, 4>;

// Sequential bisection of one tet, restricted to it: each split edge in global order halves
// every sub-tet containing it. Identical to bisecting edge after edge across whole shells, and
// planned without touching the mesh.
void bisect_locally(std::uint8_t mask, const std::array<std::uint32_t, 4>& ids, std::vector<Labels>& out) {
  out.assign(1, Labels{0, 1, 2, 3});
  std::array<int, 6> order{};
  int n = 0;
  for (int e = 0; e < 6; ++e)
    if ((mask >> e) & 1) order[n++] = e;
  auto key = [&](int e) { return std::minmax(ids[kEdgeVerts[e][0]], ids[kEdgeVerts[e][1]]); };
  // Insertion sort of at most 6 entries (std::sort on a part of a 6-array makes GCC 12 warn
  // -Warray-bounds about the 16 entries of its own insertion-sort threshold).
  for (int i = 1; i < n; ++i)
    for (int j = i; j > 0 && key(order[j]) < key(order[j - 1]); --j) std::swap(order[j], order[j - 1]);
  for (int k = 0; k < n; ++k) {
    const int e = order[k];
    const std::uint8_t x = kEdgeVerts[e][0], y = kEdgeVerts[e][1], m = static_cast<std::uint8_t>(4 + e);
    const std::size_t count = out.size();
    for (std::size_t i = 0; i < count; ++i) {
      Labels t = out[i];
      const auto px = std::find(t.begin(), t.end(), x), py = std::find(t.begin(), t.end(), y);
      if (px == t.end() || py == t.end()) continue;
      Labels with_x = t, with_y = t;
      with_x[static_cast<std::size_t>(py - t.begin())] = m;  // keeps x: same orientation
      with_y[static_cast<std::size_t>(px - t.begin())] = m;
      out[i] = with_x;
      out.push_back(with_y);
    }
  }
}

// The worst radius ratio among a template's children, placed on the points `p` (labels).
double worst_child(const SplitTemplate& tpl, const Vec3 (&p)[10]) {
  double worst = 1.0;
  for (int c = 0; c < tpl.count; ++c) {
    const Labels& l = tpl.children[static_cast<std::size_t>(c)];
    worst = std::min(worst, radius_ratio(p[l[0]], p[l[1]], p[l[2]], p[l[3]]));
  }
  return worst;
}

}  // namespace

const char* to_string(SplitRefusal refusal) {
  switch (refusal) {
    case SplitRefusal::kNone: return "none";
    case SplitRefusal::kNotAnEdge: return "the two vertices are not joined by an edge of the mesh";
    case SplitRefusal::kDegenerateChild: return "a child tet would be inverted or flat";
    case SplitRefusal::kOverBudget: return "it would create more tets than the per-cut budget (max_tets_created) allows";
  }
  return "unknown";
}

void EdgeSplitter::reserve(std::uint32_t tets) {
  using detail::reserve_touched;
  affected_slot_.reserve(tets);
  reserve_touched(edges_, kPlannedChildren / 4);
  reserve_touched(affected_, kPlannedChildren / 2);
  reserve_touched(shell_, 256);
  reserve_touched(parents_, kPlannedChildren / 2);
  reserve_touched(labels_, 64);
  reserve_touched(all_labels_, kPlannedChildren);
  reserve_touched(children_, kPlannedChildren);
  reserve_touched(children_per_parent_, kPlannedChildren / 2);
  reserve_touched(child_parent_, kPlannedChildren);
}

int EdgeSplitter::find_edge(std::uint32_t lo, std::uint32_t hi) const {
  const auto it = std::lower_bound(edges_.begin(), edges_.end(), std::make_pair(lo, hi),
                                   [](const PlannedEdge& e, const std::pair<std::uint32_t, std::uint32_t>& k) {
                                     return std::make_pair(e.lo, e.hi) < k;
                                   });
  if (it == edges_.end() || it->lo != lo || it->hi != hi) return -1;
  return static_cast<int>(it - edges_.begin());
}

// Adds the tets around edge e to affected_, with the edge's bit in their mask.
bool EdgeSplitter::collect_shell(const TetMesh& mesh, const PlannedEdge& e) {
  const EdgeRef edge = mesh.find_edge(VertId{e.lo}, VertId{e.hi}, e.hint, shell_);
  if (!edge.valid()) return false;
  mesh.edge_shell(edge.tet, edge.edge, shell_);
  for (TetId t : shell_) {
    std::uint32_t slot;
    if (const std::uint32_t* known = affected_slot_.find(t)) {
      slot = *known;
    } else {
      slot = static_cast<std::uint32_t>(affected_.size());
      affected_.push_back({t, 0});
      affected_slot_.set(t, slot);
    }
    affected_[slot].mask = static_cast<std::uint8_t>(affected_[slot].mask | (1u << mesh.local_edge(t, VertId{e.lo}, VertId{e.hi})));
  }
  return true;
}

SplitResult EdgeSplitter::split(TetMesh& mesh, std::span<const Edge> edges, SplitMethod method,
                                std::vector<TetId>* created, std::uint64_t max_created, SplitPoint point) {
  SplitResult result;
  edges_.clear();
  all_midpoints_ = true;
  for (const Edge& e : edges) {
    if (e.a == e.b || !mesh.is_live(e.a) || !mesh.is_live(e.b)) {
      result.refusal = SplitRefusal::kNotAnEdge;
      result.offending = e;
      return result;
    }
    edges_.push_back({std::min(e.a.value, e.b.value), std::max(e.a.value, e.b.value), kNoVert, e.hint});
  }
  std::sort(edges_.begin(), edges_.end(),
            [](const PlannedEdge& x, const PlannedEdge& y) { return std::tie(x.lo, x.hi) < std::tie(y.lo, y.hi); });
  edges_.erase(std::unique(edges_.begin(), edges_.end(),
                           [](const PlannedEdge& x, const PlannedEdge& y) { return x.lo == y.lo && x.hi == y.hi; }),
               edges_.end());

  affected_slot_.clear();
  affected_.clear();
  bool all_edges = true;
  for (const PlannedEdge& e : edges_)
    if (!collect_shell(mesh, e)) {
      result.refusal = SplitRefusal::kNotAnEdge;
      result.offending = {VertId{e.lo}, VertId{e.hi}};
      all_edges = false;
      break;
    }
  if (all_edges) {
    result = plan(mesh, method, max_created);
    if (result.refusal == SplitRefusal::kDegenerateChild && point == SplitPoint::kPositiveChildren) {
      choose_split_points(mesh, method);
      result = plan(mesh, method, max_created);
    }
    if (result.ok()) apply(mesh, created, result);
  }
  return result;
}

void EdgeSplitter::tet_points(const TetMesh& mesh, const AffectedTet& a, Vec3 (&p)[10]) const {
  const TetMesh::TetVerts v = mesh.tet(a.tet);
  for (int i = 0; i < 4; ++i) p[i] = mesh.position(v[i]);
  for (int e = 0; e < 6; ++e) p[4 + e] = midpoint(p[kEdgeVerts[e][0]], p[kEdgeVerts[e][1]]);
  if (all_midpoints_) return;
  for (int e = 0; e < 6; ++e)
    if ((a.mask >> e) & 1) {
      const std::uint32_t x = v[kEdgeVerts[e][0]].value, y = v[kEdgeVerts[e][1]].value;
      const PlannedEdge& planned = edges_[static_cast<std::size_t>(find_edge(std::min(x, y), std::max(x, y)))];
      // Exactly as TetMesh::add_vertex_on_edge(lo, hi, t) will compute it, in every tet around
      // the edge, so that the orientation checked while planning is the orientation applied.
      p[4 + e] = (1.0 - planned.t) * mesh.position(VertId{planned.lo}) + planned.t * mesh.position(VertId{planned.hi});
    }
}

void EdgeSplitter::plan_tet(const AffectedTet& a, const std::array<std::uint32_t, 4>& ids, const Vec3 (&p)[10],
                            SplitMethod method) {
  if (method != SplitMethod::kTemplates) {
    bisect_locally(a.mask, ids, labels_);
    return;
  }
  std::uint8_t diagonal = 0;
  if (a.mask == 63) {  // 1:8, cut the central octahedron along its shortest diagonal
    double best = 0.0;
    for (std::uint8_t d = 0; d < 3; ++d) {
      const Vec3 delta = p[4 + d] - p[4 + opposite_edge(d)];
      const double len2 = dot(delta, delta);
      if (d == 0 || len2 < best) {
        best = len2;
        diagonal = d;
      }
    }
  }
  FaceFans fans = 0;
  if (two_split_faces(a.mask) != 0) {
    std::array<double, 6> length2{};
    if (face_rule_ == FaceRule::kLongerEdge)
      for (int e = 0; e < 6; ++e) {
        const Vec3 d = p[kEdgeVerts[e][1]] - p[kEdgeVerts[e][0]];
        length2[static_cast<std::size_t>(e)] = dot(d, d);
      }
    fans = face_fans(face_rule_, a.mask, ids, length2);
  }
  const SplitTemplate* tpl = &split_template_with_fans(a.mask, fans, diagonal);
  assert(tpl->has_cone_point() && "the fans of an order on edges always have a cone point");
  // The interior is free in some four- and five-edge configurations: the better children.
  if (const SplitTemplate& other = split_template_alternative(a.mask, fans); other.count > 0)
    if (worst_child(other, p) > worst_child(*tpl, p)) tpl = &other;
  labels_.assign(tpl->children.begin(), tpl->children.begin() + tpl->count);
}

double EdgeSplitter::children_score(const TetMesh& mesh, const AffectedTet& a, SplitMethod method) {
  const TetMesh::TetVerts v = mesh.tet(a.tet);
  Vec3 p[10];
  tet_points(mesh, a, p);
  plan_tet(a, {v[0].value, v[1].value, v[2].value, v[3].value}, p, method);
  int not_positive = 0;
  double worst = 1.0;
  for (const Labels& c : labels_) {
    if (orientation(p[c[0]], p[c[1]], p[c[2]], p[c[3]]) <= 0)
      ++not_positive;
    else
      worst = std::min(worst, radius_ratio(p[c[0]], p[c[1]], p[c[2]], p[c[3]]));
  }
  return not_positive > 0 ? -static_cast<double>(not_positive) : worst;
}

void EdgeSplitter::choose_split_points(const TetMesh& mesh, SplitMethod method) {
  // The edges that may move: those of the tets with a child that is not positive at the midpoints.
  for (const AffectedTet& a : affected_) {
    if (children_score(mesh, a, method) > 0.0) continue;
    const TetMesh::TetVerts v = mesh.tet(a.tet);
    for (int e = 0; e < 6; ++e)
      if ((a.mask >> e) & 1) {
        const std::uint32_t x = v[kEdgeVerts[e][0]].value, y = v[kEdgeVerts[e][1]].value;
        edges_[static_cast<std::size_t>(find_edge(std::min(x, y), std::max(x, y)))].free = true;
      }
  }
  all_midpoints_ = false;
  // Coordinate ascent: an edge's point changes the children of its shell only.
  auto shell_score = [&] {
    double worst = 1.0;
    for (TetId u : shell_) worst = std::min(worst, children_score(mesh, affected_[*affected_slot_.find(u)], method));
    return worst;
  };
  for (int pass = 0; pass < 2; ++pass)
    for (PlannedEdge& e : edges_) {
      if (!e.free) continue;
      const EdgeRef edge = mesh.find_edge(VertId{e.lo}, VertId{e.hi}, e.hint, shell_);
      mesh.edge_shell(edge.tet, edge.edge, shell_);  // an edge of the plan: collect_shell found it
      const double kept = e.t;
      double best_t = kept, best = shell_score();
      for (double t : kSplitParameters) {
        if (t == kept) continue;
        e.t = t;
        if (const double s = shell_score(); s > best) {
          best = s;
          best_t = t;
        }
      }
      e.t = best_t;
    }
}

// Plans the children of every affected tet in labels (0..3 corners, 4 + e split points), checks
// them with the exact predicate; the mesh is not changed.
SplitResult EdgeSplitter::plan(const TetMesh& mesh, SplitMethod method, std::uint64_t max_created) {
  SplitResult result;
  all_labels_.clear();
  children_per_parent_.clear();
  for (const AffectedTet& a : affected_) {
    const TetMesh::TetVerts v = mesh.tet(a.tet);
    Vec3 p[10];
    tet_points(mesh, a, p);
    plan_tet(a, {v[0].value, v[1].value, v[2].value, v[3].value}, p, method);
    for (const Labels& c : labels_) {
      if (orientation(p[c[0]], p[c[1]], p[c[2]], p[c[3]]) <= 0) {
        for (int e = 0; e < 6; ++e)
          if ((a.mask >> e) & 1) result.offending = {v[kEdgeVerts[e][0]], v[kEdgeVerts[e][1]]};
        result.refusal = SplitRefusal::kDegenerateChild;
        return result;
      }
      all_labels_.push_back(c);
    }
    children_per_parent_.push_back(static_cast<std::uint8_t>(labels_.size()));
    if (all_labels_.size() > max_created) {  // stop planning: the rest would be thrown away
      result.refusal = SplitRefusal::kOverBudget;
      return result;
    }
  }
  return result;
}

// Applies the plan: new vertices first, then one replace_tets() for all parents.
void EdgeSplitter::apply(TetMesh& mesh, std::vector<TetId>* created, SplitResult& result) {
  // New vertices in global edge order, so their ids do not depend on the input order.
  for (PlannedEdge& e : edges_) e.vertex = mesh.add_vertex_on_edge(VertId{e.lo}, VertId{e.hi}, e.t);
  parents_.clear();
  children_.clear();
  child_parent_.clear();
  std::size_t next = 0;
  for (std::size_t k = 0; k < affected_.size(); ++k) {
    const TetMesh::TetVerts v = mesh.tet(affected_[k].tet);
    parents_.push_back(affected_[k].tet);
    // The parent's labels: its corners, then the points of its split edges (looked up once
    // per parent, not once per child that uses them).
    VertId label_vertex[10];
    for (int i = 0; i < 4; ++i) label_vertex[i] = v[i];
    for (int e = 0; e < 6; ++e)
      if ((affected_[k].mask >> e) & 1) {
        const VertId x = v[kEdgeVerts[e][0]], y = v[kEdgeVerts[e][1]];
        label_vertex[4 + e] = edges_[static_cast<std::size_t>(find_edge(std::min(x.value, y.value), std::max(x.value, y.value)))].vertex;
      }
    for (int c = 0; c < children_per_parent_[k]; ++c, ++next) {
      TetMesh::TetVerts child;
      for (int i = 0; i < 4; ++i) child[i] = label_vertex[all_labels_[next][i]];
      children_.push_back(child);
      child_parent_.push_back(affected_[k].tet);
    }
  }
  mesh.replace_tets(parents_, children_, created, child_parent_);
  result.edges_split = static_cast<std::uint32_t>(edges_.size());
  result.tets_removed = static_cast<std::uint32_t>(parents_.size());
  result.tets_created = static_cast<std::uint32_t>(children_.size());
}

}  // namespace tetcut
