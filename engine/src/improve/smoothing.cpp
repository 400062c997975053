#include "improve/smoothing.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/quality.hpp"
#include "tetcut/detail/local_tables.hpp"
#include "tetcut/detail/reserve_touched.hpp"
#include "tetcut/predicates.hpp"

namespace tetcut::detail {
namespace {

Vec3 unit(const Vec3& x) {
  const double n = norm(x);
  return n > 0.0 ? (1.0 / n) * x : Vec3{};
}

// Two unit normals within this angle (sine) are one plane.
constexpr double kCoplanar = 1e-9;

}  // namespace

void Smoother::reserve() {
  reserve_touched(shell_, 128);
  reserve_touched(star_, 128);
  reserve_touched(active_, kMaxActive);
  reserve_touched(surface_normals_, kMaxSurfaceNormals);
}

double Smoother::evaluate(const Vec3& p, double floor) const {
  double q = 1.0;
  for (const StarTet& t : star_) {
    std::array<Vec3, 4> c = t.corners;
    c[static_cast<std::size_t>(t.slot)] = p;
    // The quality first (cheap): a tet at or below the floor ends the evaluation; the exact
    // orientation only for a candidate still in the running.
    const double r = quality(c[0], c[1], c[2], c[3]);
    if (r <= floor) return r;
    q = std::min(q, r);
  }
  for (const StarTet& t : star_) {
    std::array<Vec3, 4> c = t.corners;
    c[static_cast<std::size_t>(t.slot)] = p;
    if (orientation(c[0], c[1], c[2], c[3]) <= 0) return -1.0;
  }
  return q;
}

Vec3 Smoother::gradient(std::size_t i, const Vec3& p, int dims, double h) const {
  const StarTet& t = star_[i];
  auto ratio_at = [&](const Vec3& x) {
    std::array<Vec3, 4> c = t.corners;
    c[static_cast<std::size_t>(t.slot)] = x;
    return quality(c[0], c[1], c[2], c[3]);
  };
  Vec3 g{};
  for (int k = 0; k < dims; ++k) {
    const Vec3 e = basis_[static_cast<std::size_t>(k)];
    g = g + ((ratio_at(p + h * e) - ratio_at(p - h * e)) / (2.0 * h)) * e;
  }
  return g;
}

bool Smoother::near_surface(const Vec3& p) const {
  for (const Vec3& n : surface_normals_)
    if (std::abs(dot(n, p - start_)) > surface_tolerance_) return false;
  return true;
}

int Smoother::constraint(const TetMesh& mesh, VertId v, const Tool* tool) {
  surface_tolerance_ = 0.0;
  surface_normals_.clear();
  if (!mesh.is_boundary_vertex(v)) {
    basis_ = {Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}};
    return 3;
  }
  // The distinct planes of the boundary faces at v.
  bool too_many = false;
  for (TetId t : shell_) {
    const int lv = mesh.local_index(t, v);
    for (int f = 0; f < 4; ++f) {
      if (f == lv || !mesh.is_boundary_face(t, f)) continue;
      const Vec3 a = mesh.position(mesh.vertex(t, kFaceVerts[f][0]));
      const Vec3 n = unit(cross(mesh.position(mesh.vertex(t, kFaceVerts[f][1])) - a, mesh.position(mesh.vertex(t, kFaceVerts[f][2])) - a));
      const bool known = std::any_of(surface_normals_.begin(), surface_normals_.end(),
                                     [&](const Vec3& m) { return norm(cross(m, n)) <= kCoplanar && dot(m, n) > 0; });
      if (known) continue;
      if (surface_normals_.size() == kMaxSurfaceNormals) too_many = true;
      else surface_normals_.push_back(n);
    }
  }
  const std::size_t count = surface_normals_.size();
  if (count > 2) {
    // Curved: only on the cut's own surface, within the tolerance (the header says why).
    if (!tool || too_many) return 0;
    const Vec3 p = mesh.position(v);
    if (distance_to_axis(*tool, p) > tool->radius) return 0;
    double shortest = 0.0;
    for (TetId t : shell_)
      for (VertId w : mesh.tet(t))
        if (w != v) {
          const double l = norm(mesh.position(w) - p);
          shortest = shortest == 0.0 ? l : std::min(shortest, l);
        }
    surface_tolerance_ = kCutSurfaceTolerance * shortest;
    start_ = p;
    basis_ = {Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}};
    return 3;
  }
  if (count == 1) {
    // Two directions in the plane.
    const Vec3 n = surface_normals_[0];
    const Vec3 any = std::abs(n.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
    basis_[0] = unit(cross(n, any));
    basis_[1] = cross(n, basis_[0]);
    return 2;
  }
  basis_[0] = unit(cross(surface_normals_[0], surface_normals_[1]));
  return norm(basis_[0]) > 0.0 ? 1 : 0;
}

Refusal Smoother::plan(const TetMesh& mesh, VertId v, double margin, const Tool* tool, Plan& plan) {
  plan.start(Operator::kSmoothing);
  mesh.vertex_shell(v, shell_);
  const int dims = constraint(mesh, v, tool);
  if (dims == 0) return Refusal::kSurfaceConstraint;
  star_.clear();
  double shortest = 0.0;
  for (TetId t : shell_) {
    StarTet s;
    s.slot = mesh.local_index(t, v);
    for (int i = 0; i < 4; ++i) {
      s.corners[static_cast<std::size_t>(i)] = mesh.position(mesh.vertex(t, i));
      if (i != s.slot) {
        const double l = norm(s.corners[static_cast<std::size_t>(i)] - mesh.position(v));
        shortest = shortest == 0.0 ? l : std::min(shortest, l);
      }
    }
    star_.push_back(s);
  }
  const Vec3 start = mesh.position(v);
  Vec3 p = start;
  double q = evaluate(p);
  const double q_start = q;
  const double h = 1e-7 * shortest;
  // Rounds of: the active set (the star's tets within 2 % of its worst), a direction that raises
  // all of them (the best of their gradients, their mean and the mean of each pair, judged by the
  // least rate of rise it gives any of them), then the longest step along it, from a third of v's
  // shortest edge down, that lifts the worst tet of the star.
  for (int round = 0; round < 5; ++round) {
    active_.clear();
    for (std::size_t i = 0; i < star_.size(); ++i) {
      std::array<Vec3, 4> c = star_[i].corners;
      c[static_cast<std::size_t>(star_[i].slot)] = p;
      if (quality(c[0], c[1], c[2], c[3]) <= q * 1.02) active_.push_back(gradient(i, p, dims, h));
      if (active_.size() == kMaxActive) break;
    }
    Vec3 direction{};
    double best_rate = 0.0;
    auto consider = [&](const Vec3& d) {
      const double n = norm(d);
      if (!(n > 0.0)) return;
      const Vec3 u = (1.0 / n) * d;
      double rate = std::numeric_limits<double>::infinity();
      for (const Vec3& g : active_) rate = std::min(rate, dot(g, u));
      if (rate > best_rate) {
        best_rate = rate;
        direction = u;
      }
    };
    Vec3 mean{};
    for (std::size_t i = 0; i < active_.size(); ++i) {
      consider(active_[i]);
      mean = mean + active_[i];
      for (std::size_t j = i + 1; j < active_.size(); ++j) consider(active_[i] + active_[j]);
    }
    consider(mean);
    if (!(best_rate > 0.0)) break;
    bool moved = false;
    for (double step = shortest / 3.0; step > shortest * 1e-3; step *= 0.5) {
      const Vec3 candidate = p + step * direction;
      if (surface_tolerance_ > 0.0 && !near_surface(candidate)) continue;
      const double cq = evaluate(candidate, q * (1.0 + 1e-6));
      if (cq > q * (1.0 + 1e-6)) {
        p = candidate;
        q = cq;
        moved = true;
        break;
      }
    }
    if (!moved) break;
  }
  plan.placed = v;
  plan.placed_at = p;
  plan.worst_before = q_start;
  plan.worst_after = q;
  if (!(q > q_start * (1.0 + margin))) return Refusal::kNotBetter;
  // The star, as it goes and as it comes back around v's new position.
  plan.removed.assign(shell_.begin(), shell_.end());
  for (TetId t : shell_) plan.added.push_back(mesh.tet(t));
  return Refusal::kNone;
}

}  // namespace tetcut::detail
