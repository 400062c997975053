// The one translation unit of the benchmarks that includes CGAL (cgal_peer.hpp says why).
//
// Not defined here: CGAL_ALWAYS_ROUND_TO_NEAREST. It keeps CGAL's interval filters in
// round-to-nearest so that valgrind, which does not emulate rounding-mode switches, gives exact
// answers; it also makes CGAL slower, and this file exists to time CGAL. To run the peers under
// valgrind, configure with -DCMAKE_CXX_FLAGS=-DCGAL_ALWAYS_ROUND_TO_NEAREST.
#include "cgal_peer.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <map>
#include <tuple>
#include <vector>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_3/tet_soup_to_c3t3.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Tetrahedral_remeshing/Remeshing_triangulation_3.h>
#include <CGAL/tetrahedral_remeshing.h>

namespace tetcut::peers {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Triangulation = CGAL::Tetrahedral_remeshing::Remeshing_triangulation_3<Kernel>;
using C3t3 = CGAL::Mesh_complex_3_in_triangulation_3<Triangulation>;
using CellHandle = Triangulation::Cell_handle;
using VertexHandle = Triangulation::Vertex_handle;
using Facet = Triangulation::Facet;
using Point = Triangulation::Point;

constexpr int kDomain = 1;    // the subdomain of every loaded cell
constexpr int kSelected = 2;  // the subdomain of the cells remesh() works on
constexpr int kSurface = 1;   // the surface patch of every boundary facet

// The selection is the subdomain, so that it follows CGAL's operations by itself: a split or a
// flip gives the new cells their parent's subdomain (CGAL's example
// tetrahedral_remeshing_of_one_subdomain.cpp does the same). CGAL 5.5 calls the selection as a
// functor; later versions read it as a property map (get, put): both are given.
struct SelectedCells {
  using key_type = CellHandle;
  using value_type = bool;
  using reference = bool;
  using category = boost::read_write_property_map_tag;

  bool operator()(const CellHandle& c) const { return c->subdomain_index() == kSelected; }
  friend bool get(const SelectedCells& selection, const CellHandle& c) { return selection(c); }
  friend void put(SelectedCells&, const CellHandle&, bool) {}
};

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// A vertex's position as a sortable key: a kept vertex keeps its point bit for bit.
using PointKey = std::tuple<double, double, double>;
PointKey key_of(const Point& p) { return {p.x(), p.y(), p.z()}; }

// A vertex of a selected cell that also belongs to a cell outside the selection (an unselected
// cell, or an infinite one: the vertex is on the mesh surface). remesh_boundaries(false) keeps
// these where they are; the caller is told if one moved.
bool is_frozen(const Triangulation& tr, const VertexHandle& v, std::vector<CellHandle>& scratch) {
  scratch.clear();
  tr.incident_cells(v, std::back_inserter(scratch));
  return std::any_of(scratch.begin(), scratch.end(),
                     [](const CellHandle& c) { return c->subdomain_index() != kSelected; });
}

// The sorted positions of the frozen vertices of the selected cells.
std::vector<PointKey> frozen_points(const Triangulation& tr) {
  std::vector<VertexHandle> vertices;
  for (const CellHandle c : tr.finite_cell_handles())
    if (c->subdomain_index() == kSelected)
      for (int i = 0; i < 4; ++i) vertices.push_back(c->vertex(i));
  std::sort(vertices.begin(), vertices.end());
  vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
  std::vector<PointKey> points;
  std::vector<CellHandle> scratch;
  for (const VertexHandle& v : vertices)
    if (is_frozen(tr, v, scratch)) points.push_back(key_of(v->point()));
  std::sort(points.begin(), points.end());
  return points;
}

// CGAL 5.5's remesher writes "Resolution reached" to std::cout when no edge it may change is
// outside the length bounds (Adaptive_remesher::resolution_reached()); a library of ours prints
// nothing, so std::cout has no buffer while CGAL runs (writes then only set badbit, which
// rdbuf() clears when the buffer is given back).
class MutedStdout {
 public:
  MutedStdout() : saved_(std::cout.rdbuf(nullptr)) {}
  ~MutedStdout() { std::cout.rdbuf(saved_); }
  MutedStdout(const MutedStdout&) = delete;
  MutedStdout& operator=(const MutedStdout&) = delete;

 private:
  std::streambuf* saved_;
};

}  // namespace

const char* cgal_version() { return CGAL_VERSION_STR; }

struct CgalTetMesh::Impl {
  C3t3 c3t3;
  std::vector<CellHandle> cell_of_tet;  // cell i is tet i of the last load; empty after remesh()
  std::vector<std::uint32_t> pending;    // remove_cells(): the cells not yet removed
};

CgalTetMesh::CgalTetMesh() : impl_(std::make_unique<Impl>()) {}
CgalTetMesh::~CgalTetMesh() = default;
CgalTetMesh::CgalTetMesh(CgalTetMesh&&) noexcept = default;
CgalTetMesh& CgalTetMesh::operator=(CgalTetMesh&&) noexcept = default;

CgalLoadResult CgalTetMesh::load(std::span<const Vec3> positions,
                                 std::span<const std::array<std::uint32_t, 4>> tets) {
  const auto start = std::chrono::steady_clock::now();
  CgalLoadResult out;
  impl_->cell_of_tet.clear();
  impl_->c3t3.clear();
  auto fail = [&out](std::string why) {
    out.ok = false;
    out.error = std::move(why);
    return out;
  };
  if (tets.empty()) return fail("no tets to load");

  // CGAL makes a vertex of every point it is given, and a vertex without a cell breaks the
  // triangulation: only the used positions go in, in id order.
  std::vector<int> cgal_id(positions.size(), -1);
  for (std::size_t t = 0; t < tets.size(); ++t)
    for (std::uint32_t v : tets[t]) {
      if (v >= positions.size())
        return fail("tet " + std::to_string(t) + " names vertex " + std::to_string(v) + " of " +
                    std::to_string(positions.size()));
      cgal_id[v] = 0;
    }
  std::vector<Point> points;
  for (std::size_t v = 0; v < positions.size(); ++v) {
    if (cgal_id[v] < 0) continue;
    cgal_id[v] = static_cast<int>(points.size());
    points.emplace_back(positions[v].x, positions[v].y, positions[v].z);
  }
  std::vector<std::array<int, 5>> cells;  // 4 vertices and the subdomain
  cells.reserve(tets.size());
  for (const auto& t : tets) cells.push_back({cgal_id[t[0]], cgal_id[t[1]], cgal_id[t[2]], cgal_id[t[3]], kDomain});

  // The boundary facets go into the complex below, from the infinite cells, rather than through
  // build_triangulation's map keyed by vertex triples (which would need the surface found first).
  // `true`: do not run tds().is_valid() at the end. It checks Euler's relation of a triangulated
  // 3-sphere, which the mesh closed by one infinite vertex only satisfies while its surface is a
  // single sphere; a cut that tunnels through the organ (the gated sweep's passes do) makes it a
  // torus. Nothing CGAL does below walks around the infinite vertex itself.
  const std::map<std::array<int, 3>, int> no_patches;
  std::vector<VertexHandle> handles;
  Triangulation& tr = impl_->c3t3.triangulation();
  if (!CGAL::build_triangulation<Triangulation, true>(tr, points, cells, no_patches, handles, false))
    return fail("CGAL::build_triangulation refused the tets: a face is shared by more than two of them");

  // A cleared TDS hands out its cells in creation order, finite ones first: cell i is tet i. Each
  // is checked, and looked up by its vertices should that ever not hold.
  impl_->cell_of_tet.reserve(tets.size());
  auto cell = tr.tds().cells().begin();
  for (const auto& t : cells) {
    const std::array<VertexHandle, 4> v = {handles[t[0] + 1], handles[t[1] + 1], handles[t[2] + 1], handles[t[3] + 1]};
    CellHandle c = cell;
    if (cell == tr.tds().cells().end() || c->vertex(0) != v[0] || c->vertex(1) != v[1] || c->vertex(2) != v[2] ||
        c->vertex(3) != v[3]) {
      int i0 = 0, i1 = 0, i2 = 0, i3 = 0;
      if (!tr.tds().is_cell(v[0], v[1], v[2], v[3], c, i0, i1, i2, i3))
        return fail("CGAL lost tet " + std::to_string(impl_->cell_of_tet.size()));
    } else {
      ++cell;
    }
    impl_->cell_of_tet.push_back(c);
  }

  for (const CellHandle c : tr.all_cell_handles()) {
    if (!tr.is_infinite(c)) continue;
    impl_->c3t3.add_to_complex(tr.mirror_facet(Facet(c, c->index(tr.infinite_vertex()))), kSurface);
    ++out.boundary_facets;
  }
  impl_->c3t3.rescan_after_load_of_triangulation();  // the complex's cell count
  // face_status() counts each edge's facets in the complex once, on its first call, O(#facets),
  // and keeps the counts as facets come and go: paid here rather than by the first removal.
  (void)impl_->c3t3.face_status(*tr.finite_edges_begin());

  out.cells = static_cast<std::uint32_t>(tets.size());
  out.vertices = static_cast<std::uint32_t>(points.size());
  out.seconds = seconds_since(start);
  return out;
}

namespace {

// Takes cell `c` out of the complex, or puts it back (`in`), with its facets: a facet is in the
// complex when exactly one of its two cells is (the domain's boundary).
void set_cell_in_complex(C3t3& c3t3, const CellHandle& c, bool in) {
  if (in) c3t3.add_to_complex(c, kDomain);
  else c3t3.remove_from_complex(c);
  for (int i = 0; i < 4; ++i) {
    const Facet f(c, i);
    const bool other_in = c3t3.is_in_complex(c->neighbor(i));
    if (in != other_in) c3t3.add_to_complex(f, kSurface);
    else c3t3.remove_from_complex(f);
  }
}

bool touches_singularity(const C3t3& c3t3, const CellHandle& c) {
  for (int i = 0; i < 4; ++i)
    if (c3t3.face_status(c->vertex(i)) == C3t3::SINGULAR) return true;
  for (int a = 0; a < 4; ++a)
    for (int b = a + 1; b < 4; ++b)
      if (c3t3.face_status(Triangulation::Edge(c, a, b)) == C3t3::SINGULAR) return true;
  return false;
}

}  // namespace

CgalRemovalResult CgalTetMesh::remove_cells(std::span<const std::uint32_t> cells,
                                            std::vector<std::uint32_t>& removed_out) {
  CgalRemovalResult out;
  C3t3& c3t3 = impl_->c3t3;
  const std::vector<CellHandle>& cell_of_tet = impl_->cell_of_tet;
  std::vector<std::uint32_t>& pending = impl_->pending;
  pending.clear();
  for (std::uint32_t i : cells)
    if (i < cell_of_tet.size() && c3t3.is_in_complex(cell_of_tet[i])) pending.push_back(i);
  for (bool progress = true; progress && !pending.empty();) {
    progress = false;
    std::size_t kept = 0;
    for (std::uint32_t i : pending) {
      const CellHandle c = cell_of_tet[i];
      if (!c3t3.is_in_complex(c)) continue;  // a repeat
      set_cell_in_complex(c3t3, c, false);
      if (touches_singularity(c3t3, c)) {
        set_cell_in_complex(c3t3, c, true);  // undone: the complex is as it was
        pending[kept++] = i;
        continue;
      }
      removed_out.push_back(i);
      ++out.removed;
      progress = true;
    }
    pending.resize(kept);
  }
  out.refused = static_cast<std::uint32_t>(pending.size());
  return out;
}

RemeshResult CgalTetMesh::remesh(std::span<const std::uint32_t> selected, const RemeshOptions& options) {
  RemeshResult out;
  std::vector<CellHandle>& cell_of_tet = impl_->cell_of_tet;
  C3t3& c3t3 = impl_->c3t3;
  if (cell_of_tet.empty()) {
    out.ok = false;
    out.error = "nothing loaded (load() again after each remesh())";
    return out;
  }
  for (std::uint32_t i : selected)
    if (i >= cell_of_tet.size()) {
      out.ok = false;
      out.error = "cell " + std::to_string(i) + " of " + std::to_string(cell_of_tet.size()) + " selected";
      return out;
    }

  double edge_sum = 0;
  for (std::uint32_t i : selected) {
    const CellHandle c = cell_of_tet[i];
    if (c->subdomain_index() == kSelected) continue;
    c3t3.remove_from_complex(c);
    c3t3.add_to_complex(c, kSelected);
    ++out.cells_selected;
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b)
        edge_sum += std::sqrt(CGAL::to_double(CGAL::squared_distance(c->vertex(a)->point(), c->vertex(b)->point())));
  }
  cell_of_tet.clear();  // handles die with the cells CGAL replaces
  if (out.cells_selected == 0) return out;
  out.target_edge_length = options.target_edge_length > 0 ? options.target_edge_length
                                                           : edge_sum / (6.0 * out.cells_selected);

  const Triangulation& tr = c3t3.triangulation();
  const std::vector<PointKey> frozen_before = frozen_points(tr);

  const auto start = std::chrono::steady_clock::now();
  {
    const MutedStdout muted;
    CGAL::tetrahedral_isotropic_remeshing(c3t3, out.target_edge_length,
                                          CGAL::parameters::remesh_boundaries(false)
                                              .number_of_iterations(options.iterations)
                                              .cell_is_selected_map(SelectedCells{}));
  }
  out.seconds = seconds_since(start);

  const std::vector<PointKey> frozen_after = frozen_points(tr);
  std::vector<PointKey> moved;
  std::set_difference(frozen_before.begin(), frozen_before.end(), frozen_after.begin(), frozen_after.end(),
                      std::back_inserter(moved));
  out.frozen_vertices = static_cast<std::uint32_t>(frozen_before.size());
  out.frozen_vertices_moved = static_cast<std::uint32_t>(moved.size());

  // The region, vertices numbered by first appearance in CGAL's cell order (deterministic: the
  // container's order, not addresses).
  std::map<VertexHandle, std::uint32_t> region_id;
  for (const CellHandle c : tr.finite_cell_handles()) {
    if (c->subdomain_index() != kSelected) continue;
    std::array<std::uint32_t, 4> tet{};
    for (int i = 0; i < 4; ++i) {
      const VertexHandle v = c->vertex(i);
      auto [it, added] = region_id.try_emplace(v, static_cast<std::uint32_t>(out.region.positions.size()));
      if (added) out.region.positions.push_back({v->point().x(), v->point().y(), v->point().z()});
      tet[static_cast<std::size_t>(i)] = it->second;
    }
    out.region.tets.push_back(tet);
  }
  return out;
}

}  // namespace tetcut::peers
