#include "tetcut/generators/shapes.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <utility>
#include <vector>

namespace tetcut::generators {
namespace {

using Tri = std::array<std::uint32_t, 3>;
constexpr std::uint32_t kUnset = 0xFFFFFFFFu;

// Appends triangle (a, b, c), flipped if needed so that its normal points along `outward`.
void add_oriented(TriSurface& s, std::uint32_t a, std::uint32_t b, std::uint32_t c,
                  const Vec3& outward) {
  const Vec3& pa = s.positions[a];
  const Vec3 n = cross(s.positions[b] - pa, s.positions[c] - pa);
  if (dot(n, outward) < 0.0) std::swap(b, c);
  s.triangles.push_back(Tri{a, b, c});
}

// The boundary of an nx * ny * nz lattice over [0, size]: every face a grid of squares split
// into two triangles, diagonals alternating so that no direction is preferred.
TriSurface lattice_box_surface(Vec3 size, std::uint32_t nx, std::uint32_t ny, std::uint32_t nz) {
  TriSurface s;
  const std::uint32_t n[3] = {nx, ny, nz};
  const auto lattice_index = [&](std::uint32_t i, std::uint32_t j, std::uint32_t k) {
    return (static_cast<std::size_t>(k) * (ny + 1) + j) * (nx + 1) + i;
  };
  std::vector<std::uint32_t> id((nx + 1) * static_cast<std::size_t>(ny + 1) * (nz + 1),
                                kUnset);
  const auto vertex = [&](std::uint32_t i, std::uint32_t j, std::uint32_t k) {
    auto& v = id[lattice_index(i, j, k)];
    if (v == kUnset) {
      v = static_cast<std::uint32_t>(s.positions.size());
      s.positions.push_back({size.x * i / nx, size.y * j / ny, size.z * k / nz});
    }
    return v;
  };
  for (int axis = 0; axis < 3; ++axis) {
    const int u = (axis + 1) % 3, w = (axis + 2) % 3;
    for (int side = 0; side < 2; ++side) {
      Vec3 outward{0, 0, 0};
      (axis == 0 ? outward.x : axis == 1 ? outward.y : outward.z) = side == 0 ? -1.0 : 1.0;
      for (std::uint32_t a = 0; a < n[u]; ++a)
        for (std::uint32_t b = 0; b < n[w]; ++b) {
          std::uint32_t corner[4];
          const std::uint32_t da[4] = {0, 1, 1, 0}, db[4] = {0, 0, 1, 1};
          for (int c = 0; c < 4; ++c) {
            std::uint32_t ijk[3];
            ijk[axis] = side == 0 ? 0 : n[axis];
            ijk[u] = a + da[c];
            ijk[w] = b + db[c];
            corner[c] = vertex(ijk[0], ijk[1], ijk[2]);
          }
          if ((a + b) % 2 == 0) {
            add_oriented(s, corner[0], corner[1], corner[2], outward);
            add_oriented(s, corner[0], corner[2], corner[3], outward);
          } else {
            add_oriented(s, corner[0], corner[1], corner[3], outward);
            add_oriented(s, corner[1], corner[2], corner[3], outward);
          }
        }
    }
  }
  return s;
}

// The -a bound in regular tets of the boundary spacing: with the quality bound TetGen refines
// well below it anyway, and a tighter bound only multiplies the tets (measured on the cylinder).
constexpr double kVolumeInRegularTets = 3.0;

std::uint32_t divisions(double length, double spacing) {
  return std::max<std::uint32_t>(1, static_cast<std::uint32_t>(std::lround(length / spacing)));
}

}  // namespace

double regular_tet_volume(double edge) { return edge * edge * edge / (6.0 * std::numbers::sqrt2); }

TriSurface cylinder_surface(const CylinderOptions& o) {
  TriSurface s;
  const std::uint32_t n = o.segments;
  const double pi = std::numbers::pi;
  const double spacing = 2.0 * o.radius * std::sin(pi / n);  // side length of the polygon
  const std::uint32_t rings = divisions(o.height, spacing);
  // Side: rings + 1 circles; odd circles turned by half a segment so side triangles are
  // near equilateral rather than right-angled.
  for (std::uint32_t r = 0; r <= rings; ++r) {
    const double z = o.height * r / rings;
    const double turn = (r % 2 == 1) ? 0.5 : 0.0;
    for (std::uint32_t k = 0; k < n; ++k) {
      const double a = 2.0 * pi * (k + turn) / n;
      s.positions.push_back({o.radius * std::cos(a), o.radius * std::sin(a), z});
    }
  }
  const auto ring_vertex = [&](std::uint32_t r, std::uint32_t k) { return r * n + k % n; };
  for (std::uint32_t r = 0; r < rings; ++r)
    for (std::uint32_t k = 0; k < n; ++k) {
      const double zmid = o.height * (r + 0.5) / rings;
      const double a = 2.0 * pi * (k + 0.5) / n;
      const Vec3 outward{std::cos(a), std::sin(a), 0.0 * zmid};
      if (r % 2 == 0) {  // lower circle straight, upper turned
        add_oriented(s, ring_vertex(r, k), ring_vertex(r, k + 1), ring_vertex(r + 1, k), outward);
        add_oriented(s, ring_vertex(r, k + 1), ring_vertex(r + 1, k + 1), ring_vertex(r + 1, k),
                     outward);
      } else {  // lower circle turned
        add_oriented(s, ring_vertex(r, k), ring_vertex(r + 1, k + 1), ring_vertex(r + 1, k),
                     outward);
        add_oriented(s, ring_vertex(r, k), ring_vertex(r, k + 1), ring_vertex(r + 1, k + 1),
                     outward);
      }
    }
  // Caps: a fan around a centre vertex; TetGen refines them (no -Y) to reach the quality bound.
  for (int cap = 0; cap < 2; ++cap) {
    const std::uint32_t r = cap == 0 ? 0 : rings;
    const auto centre = static_cast<std::uint32_t>(s.positions.size());
    s.positions.push_back({0.0, 0.0, cap == 0 ? 0.0 : o.height});
    const Vec3 outward{0.0, 0.0, cap == 0 ? -1.0 : 1.0};
    for (std::uint32_t k = 0; k < n; ++k)
      add_oriented(s, centre, ring_vertex(r, k), ring_vertex(r, k + 1), outward);
  }
  return s;
}

GenResult generate_cylinder(const CylinderOptions& o) {
  if (!(o.radius > 0.0) || !(o.height > 0.0) || !std::isfinite(o.radius) ||
      !std::isfinite(o.height))
    return GenResult::failure("cylinder: radius and height must be positive numbers");
  if (o.segments < 3 || o.segments > 4096)
    return GenResult::failure("cylinder: segments must be between 3 and 4096");
  TetgenOptions t;
  t.radius_edge_ratio = o.radius_edge_ratio;
  t.min_dihedral_deg = o.min_dihedral_deg;
  const double spacing = 2.0 * o.radius * std::sin(std::numbers::pi / o.segments);
  t.max_volume = o.max_volume > 0.0 ? o.max_volume : kVolumeInRegularTets * regular_tet_volume(spacing);
  return tetrahedralize_surface(cylinder_surface(o), t);
}

TriSurface sheet_surface(const SheetOptions& o) {
  // Boundary spacing = thickness, the side walls split at mid-height, and one isolated point at
  // mid-height above the centre of every boundary square, which TetGen inserts (-p keeps
  // isolated input points). The tets then span half the thickness each on average: two tets thick.
  const std::uint32_t nx = divisions(o.length, o.thickness), ny = divisions(o.width, o.thickness);
  TriSurface s = lattice_box_surface({o.length, o.width, o.thickness}, nx, ny, 2);
  for (std::uint32_t i = 0; i < nx; ++i)
    for (std::uint32_t j = 0; j < ny; ++j)
      s.positions.push_back({o.length * (i + 0.5) / nx, o.width * (j + 0.5) / ny, 0.5 * o.thickness});
  return s;
}

GenResult generate_sheet(const SheetOptions& o) {
  if (!(o.length > 0.0) || !(o.width > 0.0) || !(o.thickness > 0.0))
    return GenResult::failure("sheet: length, width and thickness must be positive");
  if (o.length / o.thickness > 1000.0 || o.width / o.thickness > 1000.0)
    return GenResult::failure("sheet: at most 1000 thicknesses long and wide");
  TetgenOptions t;
  t.radius_edge_ratio = o.radius_edge_ratio;
  // Keep the sampled faces: Steiner points on them would make the sheet thicker in tets.
  t.preserve_boundary = true;
  return tetrahedralize_surface(sheet_surface(o), t);
}

TriSurface box_surface(const BoxOptions& o) {
  return lattice_box_surface(o.size, divisions(o.size.x, o.spacing), divisions(o.size.y, o.spacing),
                             divisions(o.size.z, o.spacing));
}

GenResult generate_box(const BoxOptions& o) {
  if (!(o.size.x > 0.0) || !(o.size.y > 0.0) || !(o.size.z > 0.0) || !(o.spacing > 0.0))
    return GenResult::failure("box: sizes and spacing must be positive");
  const double cells = (o.size.x / o.spacing) * (o.size.y / o.spacing) * (o.size.z / o.spacing);
  if (cells > 1e7) return GenResult::failure("box: spacing too small for the size (over 10^7 cells)");
  TetgenOptions t;
  t.radius_edge_ratio = o.radius_edge_ratio;
  t.min_dihedral_deg = o.min_dihedral_deg;
  t.max_volume =
      o.max_volume > 0.0 ? o.max_volume : kVolumeInRegularTets * regular_tet_volume(o.spacing);
  return tetrahedralize_surface(box_surface(o), t);
}

TriSurface sphere_surface(const SphereOptions& o) {
  TriSurface s;
  // The icosahedron: the cyclic permutations of (0, +-1, +-phi).
  const double phi = std::numbers::phi;
  for (const double a : {-1.0, 1.0})
    for (const double b : {-phi, phi}) {
      s.positions.push_back({0.0, a, b});
      s.positions.push_back({a, b, 0.0});
      s.positions.push_back({b, 0.0, a});
    }
  // Its 20 faces: the triples of vertices at the shortest distance (2) from one another.
  const std::size_t n = s.positions.size();
  auto adjacent = [&](std::size_t i, std::size_t j) { return std::abs(norm(s.positions[i] - s.positions[j]) - 2.0) < 1e-9; };
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      for (std::size_t k = j + 1; k < n; ++k)
        if (adjacent(i, j) && adjacent(j, k) && adjacent(i, k)) {
          const Vec3 centre = (1.0 / 3.0) * (s.positions[i] + s.positions[j] + s.positions[k]);
          add_oriented(s, static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j), static_cast<std::uint32_t>(k), centre);
        }
  for (Vec3& p : s.positions) p = (o.radius / norm(p)) * p;
  for (std::uint32_t level = 0; level < o.subdivisions; ++level) {
    // One midpoint per edge, found again from either side by the pair (lower, higher).
    std::map<std::uint64_t, std::uint32_t> midpoints;
    auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
      const std::uint64_t key = (static_cast<std::uint64_t>(std::min(a, b)) << 32) | std::max(a, b);
      const auto [it, inserted] = midpoints.try_emplace(key, static_cast<std::uint32_t>(s.positions.size()));
      if (inserted) {
        const Vec3 m = 0.5 * (s.positions[a] + s.positions[b]);
        s.positions.push_back((o.radius / norm(m)) * m);
      }
      return it->second;
    };
    std::vector<Tri> finer;
    for (const Tri& t : s.triangles) {
      const std::uint32_t ab = midpoint(t[0], t[1]), bc = midpoint(t[1], t[2]), ca = midpoint(t[2], t[0]);
      finer.insert(finer.end(), {Tri{t[0], ab, ca}, Tri{ab, t[1], bc}, Tri{ca, bc, t[2]}, Tri{ab, bc, ca}});
    }
    s.triangles = std::move(finer);
  }
  return s;
}

GenResult generate_sphere(const SphereOptions& o) {
  if (!(o.radius > 0.0) || !std::isfinite(o.radius)) return GenResult::failure("sphere: the radius must be positive");
  if (o.subdivisions > 7) return GenResult::failure("sphere: at most 7 subdivisions (327,680 triangles)");
  const TriSurface surface = sphere_surface(o);
  double edges = 0.0;
  for (const Tri& t : surface.triangles) edges += norm(surface.positions[t[1]] - surface.positions[t[0]]);
  const double spacing = edges / static_cast<double>(surface.triangles.size());
  TetgenOptions t;
  t.radius_edge_ratio = o.radius_edge_ratio;
  t.min_dihedral_deg = o.min_dihedral_deg;
  t.max_volume = o.max_volume > 0.0 ? o.max_volume : kVolumeInRegularTets * regular_tet_volume(spacing);
  return tetrahedralize_surface(surface, t);
}

GenResult generate_from_surface(const TriSurface& surface, const SurfaceOptions& options) {
  return tetrahedralize_surface(surface, options.tetgen);
}

}  // namespace tetcut::generators
