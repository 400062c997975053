#include "vertex_link.hpp"

#include <algorithm>
#include <string>

#include "tet_tables.hpp"

namespace tetcut::invariants::detail {
namespace {

constexpr std::uint32_t kNone = 0xFFFFFFFFu;

bool touched(const LinkContext& ctx, std::uint32_t w) {
  return ctx.touched_stamp == nullptr || ctx.touched_stamp[w] == ctx.stamp;
}

// v owns a face or edge through it when no other touched vertex of it is smaller.
bool owns(const LinkContext& ctx, std::uint32_t v, std::uint32_t a) { return !(a < v && touched(ctx, a)); }

std::uint32_t index_of(const std::vector<std::uint32_t>& sorted, std::uint32_t w) {
  return static_cast<std::uint32_t>(std::lower_bound(sorted.begin(), sorted.end(), w) - sorted.begin());
}

}  // namespace

std::uint32_t VertexLinkChecker::find(std::vector<std::uint32_t>& parent, std::uint32_t x) {
  while (parent[x] != x) {
    parent[x] = parent[parent[x]];  // path halving
    x = parent[x];
  }
  return x;
}

std::uint32_t VertexLinkChecker::check(const LinkContext& ctx, std::uint32_t v,
                                       std::span<const std::uint32_t> shell) {
  report_duplicates(ctx, v, shell);
  const std::uint32_t k = build_link(ctx, v, shell);
  if (k == 0) return 0;
  const FaceCounts faces = check_faces(ctx, v);
  const bool link_is_surface = check_edge_shells(ctx, v, k);
  check_vertex_shell(ctx, v, k, faces, link_is_surface);
  // I8: the engine's O(1) classification and its shell seed.
  if (ctx.engine != nullptr) compare_vertex(*ctx.engine, ctx.tets, v, faces.boundary, *ctx.report);
  return faces.boundary;
}

void VertexLinkChecker::report_duplicates(const LinkContext& ctx, std::uint32_t v, std::span<const std::uint32_t> shell) {
  ReportBuilder& report = *ctx.report;
  // I1, duplicates: two tets with the same four vertices have the same link triangle at every
  // vertex; compare them once, at their smallest vertex, and leave the later copy out of
  // everything else (it would otherwise make every face look shared twice).
  keys_.clear();
  for (std::uint32_t t : shell) {
    if (ctx.excluded[t]) continue;
    const RawTet& q = ctx.tets[t];
    if (v != std::min({q[0], q[1], q[2], q[3]})) continue;
    TetKey key{{}, t};
    int n = 0;
    for (std::uint32_t x : q)
      if (x != v) key.others[n++] = x;
    std::sort(key.others.begin(), key.others.end());
    keys_.push_back(key);
  }
  if (keys_.size() > 1) {
    std::sort(keys_.begin(), keys_.end(), [](const TetKey& a, const TetKey& b) {
      return a.others != b.others ? a.others < b.others : a.tet < b.tet;
    });
    for (std::size_t i = 1; i < keys_.size(); ++i) {
      if (keys_[i].others != keys_[i - 1].others) continue;
      const std::uint32_t first = keys_[i - 1].tet;
      const std::uint32_t dup = keys_[i].tet;
      ctx.excluded[dup] = 1;
      const auto& o = keys_[i].others;
      report.add(Invariant::kI1References, {first, dup}, {v, o[0], o[1], o[2]}, [&] {
        return "tets " + str(first) + " and " + str(dup) + " have the same vertices (" + str(v) + ", " +
               str(o[0]) + ", " + str(o[1]) + ", " + str(o[2]) + ")";
      });
      keys_[i].tet = first;  // a third copy is compared with the first
    }
  }
}

std::uint32_t VertexLinkChecker::build_link(const LinkContext& ctx, std::uint32_t v, std::span<const std::uint32_t> shell) {
  // The link triangles and link edges.
  shell_.clear();
  triangle_.clear();
  edges_.clear();
  link_verts_.clear();
  for (std::uint32_t t : shell) {
    if (ctx.excluded[t]) continue;
    const RawTet& q = ctx.tets[t];
    int lv = 0;
    while (lv < 4 && q[lv] != v) ++lv;
    if (lv == 4) continue;  // a stale index entry; the caller's bookkeeping check reports it
    const auto i = static_cast<std::uint32_t>(shell_.size());
    shell_.push_back(t);
    const auto& local = kTetFaces[lv];
    const std::array<std::uint32_t, 3> tri{q[local[0]], q[local[1]], q[local[2]]};
    triangle_.push_back(tri);
    for (int p = 0; p < 3; ++p) {
      const int r = (p + 2) % 3;  // the slot not on link edge (p, p + 1)
      const int p1 = (p + 1) % 3;
      std::uint32_t a = tri[p], b = tri[p1];
      std::uint8_t sa = static_cast<std::uint8_t>(p), sb = static_cast<std::uint8_t>(p1);
      if (a > b) {
        std::swap(a, b);
        std::swap(sa, sb);
      }
      // The face {v, a, b} is the tet's face opposite its vertex in slot r.
      edges_.push_back({(static_cast<std::uint64_t>(a) << 32) | b, i, sa, sb, local[r]});
      link_verts_.push_back(tri[p]);
    }
  }
  const auto k = static_cast<std::uint32_t>(shell_.size());
  if (k == 0) return 0;

  std::sort(edges_.begin(), edges_.end(), [](const LinkEdge& a, const LinkEdge& b) {
    return a.key != b.key ? a.key < b.key : a.tet < b.tet;
  });
  std::sort(link_verts_.begin(), link_verts_.end());
  link_verts_.erase(std::unique(link_verts_.begin(), link_verts_.end()), link_verts_.end());
  const auto link_vertex_count = static_cast<std::uint32_t>(link_verts_.size());
  // Each wedge's link vertex as an index into link_verts_, searched once.
  wedge_vertex_.resize(3 * static_cast<std::size_t>(k));
  for (std::uint32_t i = 0; i < k; ++i)
    for (std::uint32_t s = 0; s < 3; ++s) wedge_vertex_[3 * i + s] = index_of(link_verts_, triangle_[i][s]);

  shell_parent_.resize(k);
  wedge_parent_.resize(3 * static_cast<std::size_t>(k));
  for (std::uint32_t i = 0; i < k; ++i) shell_parent_[i] = i;
  for (std::uint32_t i = 0; i < 3 * k; ++i) wedge_parent_[i] = i;
  boundary_faces_.assign(link_vertex_count, 0);
  bad_.assign(link_vertex_count, 0);
  first_root_.assign(link_vertex_count, kNone);
  return k;
}

VertexLinkChecker::FaceCounts VertexLinkChecker::check_faces(const LinkContext& ctx, std::uint32_t v) {
  ReportBuilder& report = *ctx.report;
  FaceCounts counts;
  std::uint32_t& face_count = counts.faces;
  std::uint32_t& boundary_count = counts.boundary;
  for (std::size_t j = 0; j < edges_.size();) {
    std::size_t j2 = j + 1;
    while (j2 < edges_.size() && edges_[j2].key == edges_[j].key) ++j2;
    const std::size_t c = j2 - j;
    const auto a = static_cast<std::uint32_t>(edges_[j].key >> 32);
    const auto b = static_cast<std::uint32_t>(edges_[j].key & 0xFFFFFFFFu);
    const std::uint32_t ia = wedge_vertex_[3 * edges_[j].tet + edges_[j].slot_a];
    const std::uint32_t ib = wedge_vertex_[3 * edges_[j].tet + edges_[j].slot_b];
    const bool mine = owns(ctx, v, a) && owns(ctx, v, b);
    ++face_count;
    const LinkEdge& e0 = edges_[j];
    const std::uint32_t t0 = shell_[e0.tet];
    if (c == 1) {
      ++boundary_count;
      if (boundary_faces_[ia] < 255) ++boundary_faces_[ia];
      if (boundary_faces_[ib] < 255) ++boundary_faces_[ib];
      if (mine && ctx.engine != nullptr) {
        const TetFace face[] = {{t0, e0.face}};
        compare_face(*ctx.engine, face, v, a, b, report);
      }
      if (mine && ctx.boundary != nullptr) {
        const RawTet& q = ctx.tets[t0];
        const auto& f = kTetFaces[e0.face];
        ctx.boundary->push_back({{q[f[0]], q[f[1]], q[f[2]]}, t0});
      }
    } else if (c == 2) {
      const LinkEdge& e1 = edges_[j + 1];
      const std::uint32_t t1 = shell_[e1.tet];
      shell_parent_[find(shell_parent_, e0.tet)] = find(shell_parent_, e1.tet);
      const std::uint32_t wa0 = 3 * e0.tet + e0.slot_a, wa1 = 3 * e1.tet + e1.slot_a;
      const std::uint32_t wb0 = 3 * e0.tet + e0.slot_b, wb1 = 3 * e1.tet + e1.slot_b;
      wedge_parent_[find(wedge_parent_, wa0)] = find(wedge_parent_, wa1);
      wedge_parent_[find(wedge_parent_, wb0)] = find(wedge_parent_, wb1);
      if (mine && ctx.engine != nullptr) {
        const TetFace faces[] = {{t0, e0.face}, {t1, e1.face}};
        compare_face(*ctx.engine, faces, v, a, b, report);
      }
    } else {
      bad_[ia] |= 2;
      bad_[ib] |= 2;
      if (mine) {
        const std::uint32_t t1 = shell_[edges_[j + 1].tet];
        const std::uint32_t t2 = shell_[edges_[j + 2].tet];
        report.add(Invariant::kI3Conformity, {t0, t1, t2}, {v, a, b}, [&] {
          return "face (" + str(v) + ", " + str(a) + ", " + str(b) + ") belongs to " + str(static_cast<std::uint32_t>(c)) +
                 " tets (" + str(t0) + ", " + str(t1) + ", " + str(t2) + (c > 3 ? ", ..." : "") + ")";
        });
      }
    }
    j = j2;
  }
  return counts;
}

bool VertexLinkChecker::check_edge_shells(const LinkContext& ctx, std::uint32_t v, std::uint32_t k) {
  ReportBuilder& report = *ctx.report;
  const auto link_vertex_count = static_cast<std::uint32_t>(link_verts_.size());
  // I6. The tets around edge (v, w) are face-adjacent exactly when they share a face through
  // both v and w, which is a link edge at w shared by two link triangles: the wedges (i, slot of
  // w) were united along those. One root per link vertex means one face-connected edge shell.
  for (std::uint32_t i = 0; i < k; ++i) {
    for (std::uint32_t s = 0; s < 3; ++s) {
      const std::uint32_t iw = wedge_vertex_[3 * i + s];
      const std::uint32_t root = find(wedge_parent_, 3 * i + s);
      if (first_root_[iw] == kNone) first_root_[iw] = root;
      else if (first_root_[iw] != root) bad_[iw] |= 1;
    }
  }
  bool link_is_surface = true;
  for (std::uint32_t iw = 0; iw < link_vertex_count; ++iw) {
    const std::uint32_t nb = boundary_faces_[iw];
    if (bad_[iw] == 0 && (nb == 0 || nb == 2)) continue;
    link_is_surface = false;
    const std::uint32_t w = link_verts_[iw];
    if (!owns(ctx, v, w)) continue;
    const std::uint8_t why = bad_[iw];
    report.add(Invariant::kI6EdgeShell, {}, {std::min(v, w), std::max(v, w)}, [&] {
      std::string what;
      if (why & 1) what = "its tets are not one face-connected component";
      else if (why & 2) what = "a face through it belongs to more than two tets";
      else what = "it has " + str(nb) + " boundary faces (a boundary edge has exactly two)";
      return "edge (" + str(std::min(v, w)) + ", " + str(std::max(v, w)) + "): " + what;
    });
  }
  return link_is_surface;
}

void VertexLinkChecker::check_vertex_shell(const LinkContext& ctx, std::uint32_t v, std::uint32_t k,
                                           const FaceCounts& faces, bool link_is_surface) {
  ReportBuilder& report = *ctx.report;
  const auto link_vertex_count = static_cast<std::uint32_t>(link_verts_.size());
  const std::uint32_t face_count = faces.faces, boundary_count = faces.boundary;
  // I5. The shell is face-connected iff the link is connected. Then, when every link vertex is
  // a single fan and every link edge has at most two triangles (the I6 and I3 checks above), the
  // link is a connected compact surface, and its Euler characteristic decides which one:
  //   chi = V - E + F of the link = E_v - F_v + T_v (edges, faces and tets through v).
  // A connected compact surface with boundary has chi = 2 - 2g - b (orientable) or 2 - g - b
  // (non-orientable, g >= 1); with b >= 1, chi = 1 leaves only g = 0, b = 1: the disk. A closed
  // one has chi = 2 only for the sphere. So: chi must be 1 for a boundary vertex (some face
  // through v has one tet) and 2 for an interior vertex. A tunnel pinched to a point has a
  // connected shell and a manifold annulus link (chi = 0): only this test catches it.
  std::uint32_t components = 0;
  for (std::uint32_t i = 0; i < k; ++i)
    if (find(shell_parent_, i) == i) ++components;
  if (components > 1) {
    report.add(Invariant::kI5VertexShell, {}, {v}, [&] {
      return "vertex " + str(v) + ": its " + str(k) + " tets form " + str(components) +
             " face-connected components";
    });
  } else if (!link_is_surface) {
    report.add(Invariant::kI5VertexShell, {}, {v}, [&] {
      return "vertex " + str(v) + ": its link is not a surface (a singular edge or face through it)";
    });
  } else {
    const long chi = static_cast<long>(link_vertex_count) - static_cast<long>(face_count) + static_cast<long>(k);
    const long want = boundary_count > 0 ? 1 : 2;
    if (chi != want) {
      report.add(Invariant::kI5VertexShell, {}, {v}, [&] {
        return "vertex " + str(v) + ": its link has Euler characteristic " + std::to_string(chi) + ", expected " +
               std::to_string(want) + (want == 1 ? " (a disk: boundary vertex)" : " (a sphere: interior vertex)");
      });
    }
  }
}

}  // namespace tetcut::invariants::detail
