#include "cut/walking_locator.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "tetcut/detail/local_tables.hpp"
#include "tetcut/detail/reserve_touched.hpp"
#include "tetcut/predicates.hpp"

namespace tetcut {
namespace {

// Steps a walk takes before it is called lost: a walk from the last answer or a coarse cell's
// tet crosses a few cells; a visibility walk that cycles (it can, in a mesh that is not
// Delaunay) is handed to the straight walk long before this.
constexpr int kMaxSteps = 4096;
// Coarse cells of 4 x 4 x 4 index cells: about 500 tets each, so that the grid is a few
// thousand entries for a million tets.
constexpr double kCoarseCells = 4.0;

bool has_boundary_face(const TetMesh& mesh, TetId t) { return mesh.boundary_face_count(t) > 0; }

void corners(const TetMesh& mesh, TetId t, Vec3 (&q)[4]) {
  const auto v = mesh.tet(t);
  for (int i = 0; i < 4; ++i) q[i] = mesh.position(v[i]);
}

Vec3 centroid(const TetMesh& mesh, TetId t) {
  Vec3 q[4];
  corners(mesh, t, q);
  return 0.25 * (q[0] + q[1] + q[2] + q[3]);
}

// Whether p is strictly beyond face i of the positive tet q: on the side its outward normal
// points to (kFaceVerts lists the face counter-clockwise seen from outside).
bool beyond_face(const Vec3 (&q)[4], int i, const Vec3& p) {
  return orientation(q[kFaceVerts[i][0]], q[kFaceVerts[i][1]], q[kFaceVerts[i][2]], p) > 0;
}

// How the line through x and p meets the triangle (u, v, w): the signs of the three tets it
// makes with the triangle's edges agree (+1 or -1: through the interior), agree where not zero
// (0: through an edge or a corner), or differ (-2: past it).
int line_through_triangle(const Vec3& x, const Vec3& p, const Vec3& u, const Vec3& v, const Vec3& w) {
  const int e1 = orientation(x, p, u, v), e2 = orientation(x, p, v, w), e3 = orientation(x, p, w, u);
  if (e1 > 0 && e2 > 0 && e3 > 0) return 1;
  if (e1 < 0 && e2 < 0 && e3 < 0) return -1;
  if ((e1 >= 0 && e2 >= 0 && e3 >= 0) || (e1 <= 0 && e2 <= 0 && e3 <= 0)) return 0;
  return -2;
}

}  // namespace

void WalkingLocator::build(const TetMesh& mesh, double cell_size) {
  cell_size_ = cell_size;
  boundary_.build(mesh, cell_size, has_boundary_face);
  // The coarse grid: the first vertex (by id) in each coarse cell. Vertices, not tets: a
  // refinement replaces the tets around a point and keeps its vertices, so a vertex stays a
  // start until a removal takes its last tet. Built once with a hash map, then kept as a sorted
  // array for binary search.
  std::unordered_map<std::uint64_t, VertId> first;
  for (std::uint32_t i = 0; i < mesh.vertex_capacity(); ++i)
    if (mesh.is_live(VertId{i})) first.emplace(coarse_key(mesh.position(VertId{i})), VertId{i});
  starts_.assign(first.begin(), first.end());
  std::sort(starts_.begin(), starts_.end());
  last_ = kNoTet;
}

void WalkingLocator::reserve(std::uint32_t tets) {
  seen_.reserve(tets);
  // Touched, as the pipeline's own lists are: the first cut must not fault its pages in.
  constexpr std::size_t kCutScratch = 16384;
  for (auto* list : {&queue_, &seeds_, &crossings_}) detail::reserve_touched(*list, kCutScratch);
}

void WalkingLocator::update(const TetMesh& mesh, std::span<const TetId> removed, std::span<const TetId> created,
                            std::span<const TetId> rewired) {
  for (TetId t : removed) boundary_.erase(t);
  // A made tet is new, or an old id whose vertex moved (ChangeLog: removed and made again): its
  // entry is made afresh. A rewired tet kept its shape: only whether it has a boundary face can
  // have changed, and an entry it has stays right.
  for (TetId t : created)
    if (mesh.is_live(t) && has_boundary_face(mesh, t)) boundary_.insert(mesh, t);
  for (TetId t : rewired) {
    if (!mesh.is_live(t) || !has_boundary_face(mesh, t)) {
      boundary_.erase(t);
    } else if (!boundary_.holds(t)) {
      boundary_.insert(mesh, t);
    }
  }
}

std::uint64_t WalkingLocator::coarse_key(const Vec3& p) const {
  return SpatialIndex::key_of(p, kCoarseCells * cell_size_);
}

double WalkingLocator::margin(const Tool& tool) const {
  // Far above the rounding of intersects() (a few units in the last place of the coordinates),
  // far below any edge.
  const double magnitude = std::max({std::abs(tool.a.x), std::abs(tool.a.y), std::abs(tool.a.z), std::abs(tool.b.x),
                                     std::abs(tool.b.y), std::abs(tool.b.z)});
  return 1e-7 * (magnitude + tool.radius + cell_size_);
}

TetId WalkingLocator::start_for(const TetMesh& mesh, const Vec3& p) const {
  TetId best = kNoTet;
  double best_d2 = 0.0;
  auto consider = [&](TetId t) {
    if (!t.valid() || t.value >= mesh.tet_capacity() || !mesh.is_live(t)) return;
    const Vec3 d = centroid(mesh, t) - p;
    if (!best.valid() || dot(d, d) < best_d2) best = t, best_d2 = dot(d, d);
  };
  auto tet_of = [&](VertId v) { return mesh.is_live(v) ? mesh.vertex_tet(v) : kNoTet; };
  consider(last_);
  const auto key = coarse_key(p);
  const auto it = std::lower_bound(starts_.begin(), starts_.end(), std::pair{key, VertId{0}});
  if (it != starts_.end() && it->first == key) consider(tet_of(it->second));
  if (best.valid()) return best;
  // Both gone (a removal took the cell's vertex, and the last answer): any start still used, the
  // grid being a few thousand entries; then any live tet.
  for (const auto& start : starts_)
    if (const TetId t = tet_of(start.second); t.valid()) return t;
  for (std::uint32_t i = 0; i < mesh.tet_capacity(); ++i)
    if (mesh.is_live(TetId{i})) return TetId{i};
  return kNoTet;
}

WalkingLocator::Walk WalkingLocator::visibility_walk(const TetMesh& mesh, const Vec3& p, TetId& t) const {
  for (int step = 0; step < kMaxSteps; ++step) {
    Vec3 q[4];
    corners(mesh, t, q);
    bool moved = false, blocked = false;
    // The faces in turn from a rotating first one: a walk that always tried face 0 first could
    // cycle in a mesh that is not Delaunay.
    for (int k = 0; k < 4 && !moved; ++k) {
      const int i = (step + k) & 3;
      if (!beyond_face(q, i, p)) continue;
      const auto n = mesh.neighbour(t, i);
      if (n.tet.valid()) {
        t = n.tet;
        moved = true;
      } else {
        blocked = true;
      }
    }
    if (!moved) return blocked ? Walk::kBlocked : Walk::kArrived;
  }
  return Walk::kLost;
}

WalkingLocator::Walk WalkingLocator::straight_walk(const TetMesh& mesh, const Vec3& from, const Vec3& p, TetId& t) const {
  for (int step = 0; step < kMaxSteps; ++step) {
    Vec3 q[4];
    corners(mesh, t, q);
    int beyond = 0, exit = -1, only = -1;
    for (int i = 0; i < 4; ++i) {
      if (!beyond_face(q, i, p)) continue;
      ++beyond;
      only = i;
      // The face the line leaves by: of the faces p is beyond, the one it pierces (it enters by a
      // face p is in front of).
      const int through = line_through_triangle(from, p, q[kFaceVerts[i][0]], q[kFaceVerts[i][1]], q[kFaceVerts[i][2]]);
      if (through == 1 || through == -1) exit = i;
    }
    if (beyond == 0) return Walk::kArrived;
    if (exit < 0) exit = beyond == 1 ? only : -1;
    if (exit < 0) return Walk::kLost;  // the line passes through an edge or a corner
    const auto n = mesh.neighbour(t, exit);
    if (!n.tet.valid()) return Walk::kBlocked;
    t = n.tet;
  }
  return Walk::kLost;
}

TetId WalkingLocator::past_last_crossing(const TetMesh& mesh, const Vec3& p, TetId blocked) {
  ++blocked_walks_;
  const Vec3 x = centroid(mesh, blocked);
  const double tiny = margin(Tool::capsule(x, p, 0.0));
  boundary_.query(mesh, Tool::capsule(x, p, tiny), crossings_);
  // The crossing of the segment x-p with a boundary face nearest p.
  double last = -1.0;
  TetId behind = kNoTet;
  bool p_outside = false, degenerate = false;
  for (TetId b : crossings_) {
    Vec3 q[4];
    corners(mesh, b, q);
    for (int f = 0; f < 4; ++f) {
      if (!mesh.is_boundary_face(b, f)) continue;
      const Vec3 &u = q[kFaceVerts[f][0]], &v = q[kFaceVerts[f][1]], &w = q[kFaceVerts[f][2]];
      const int ox = orientation(u, v, w, x), op = orientation(u, v, w, p);
      if (ox == op && ox != 0) continue;  // both ends on one side of the plane
      const int through = line_through_triangle(x, p, u, v, w);
      if (through == -2) continue;
      if (through == 0 || (ox == 0 && op == 0)) {
        degenerate = true;  // through an edge or a corner, or in the face's plane
        continue;
      }
      if (op == 0) return b;  // p is on this boundary face: in b
      const double vx = signed_volume(u, v, w, x), vp = signed_volume(u, v, w, p);
      const double s = vx / (vx - vp);
      if (std::abs(s - last) <= 1e-12) degenerate = true;  // two faces crossed at one point
      if (s > last) last = s, behind = b, p_outside = op > 0;
    }
  }
  if (degenerate) return scan_for_point(mesh, p);
  TetId t = blocked;
  if (behind.valid()) {
    if (p_outside) return kNoTet;  // past its last crossing the segment is outside the mesh
    t = behind;
  }
  // Past the last crossing (or from x, when it crosses none) the segment is inside the mesh.
  return straight_walk(mesh, x, p, t) == Walk::kArrived ? t : scan_for_point(mesh, p);
}

TetId WalkingLocator::scan_for_point(const TetMesh& mesh, const Vec3& p) {
  ++scans_;
  const Tool point = Tool::ball(p, 0.0);
  for (std::uint32_t i = 0; i < mesh.tet_capacity(); ++i)
    if (mesh.is_live(TetId{i}) && tet_meets_tool(mesh, TetId{i}, point)) return TetId{i};
  return kNoTet;
}

TetId WalkingLocator::locate_point(const TetMesh& mesh, const Vec3& p, TetId start) {
  if (!start.valid()) return kNoTet;
  TetId t = start;
  const Walk walk = visibility_walk(mesh, p, t);
  return walk == Walk::kArrived ? t : past_last_crossing(mesh, p, t);
}

void WalkingLocator::query(const TetMesh& mesh, const Tool& tool, std::vector<TetId>& out) {
  out.clear();
  const Tool grown = tool.grown(margin(tool));
  boundary_.query(mesh, grown, seeds_);
  if (seeds_.empty()) {
    const TetId inside = locate_point(mesh, tool.a, start_for(mesh, tool.a));
    if (!inside.valid()) return;  // no boundary near, and the tool's end outside: nothing meets it
    seeds_.push_back(inside);
  }
  seen_.clear();
  queue_.clear();
  for (TetId s : seeds_)
    if (seen_.insert(s)) queue_.push_back(s);
  // The boundary seeds meet the grown tool (the index tested them); a located end's tet holds it.
  const std::size_t seeded = queue_.size();
  for (std::size_t i = 0; i < queue_.size(); ++i) {
    const TetId t = queue_[i];
    // The grown tool first: a tet past it (most of the ring around the answer) costs one test,
    // and a tet within it mostly answers both tests at its corners.
    if (i >= seeded && !tet_meets_tool(mesh, t, grown)) continue;
    if (tet_meets_tool(mesh, t, tool)) out.push_back(t);
    for (int f = 0; f < 4; ++f) {
      const auto n = mesh.neighbour(t, f);
      if (n.tet.valid() && seen_.insert(n.tet)) queue_.push_back(n.tet);
    }
  }
  std::sort(out.begin(), out.end());
  if (!out.empty()) last_ = out.front();
}

}  // namespace tetcut
