// The paper's synthetic test shapes (section 3.6): a cylinder, a thin sheet whose average
// thickness is two tetrahedra, and a box. We construct each closed surface ourselves and let
// TetGen fill it, so the meshes are unstructured like real ones, unlike make_box_mesh.
#pragma once

#include <cstdint>

#include "tetcut/generators/gen_result.hpp"
#include "tetcut/generators/tetgen_mesher.hpp"
#include "tetcut/generators/tri_surface.hpp"
#include "tetcut/vec3.hpp"

namespace tetcut::generators {

struct CylinderOptions {
  double radius = 1.0;
  double height = 4.0;
  std::uint32_t segments = 16;  // polygon sides approximating the circle, >= 3
  // Largest tet volume; 0 picks three regular tets whose edge is the boundary spacing (about
  // 3,300 tets with the defaults).
  double max_volume = 0.0;
  double radius_edge_ratio = 1.4;
  double min_dihedral_deg = 12.0;
};

// Axis z, base centred on the origin. The side is subdivided into rings as tall as the circle's
// sides are long, the caps into concentric rings, so boundary triangles are near equilateral.
TriSurface cylinder_surface(const CylinderOptions& options);
GenResult generate_cylinder(const CylinderOptions& options);

struct SheetOptions {
  double length = 8.0;     // x
  double width = 8.0;      // y
  double thickness = 0.5;  // z
  double radius_edge_ratio = 1.4;
};

// A thin box in [0,length] x [0,width] x [0,thickness], boundary sampled at a spacing equal to
// the thickness, plus isolated points on the mid-plane (TetGen inserts them): the tets span half
// the thickness on average (paper 3.6: "a thin sheet with an average thickness of two
// tetrahedra"). The returned surface therefore has vertices no triangle uses.
TriSurface sheet_surface(const SheetOptions& options);
GenResult generate_sheet(const SheetOptions& options);

struct BoxOptions {
  Vec3 size{1.0, 1.0, 1.0};
  double spacing = 0.25;  // boundary edge length; the tet size follows it
  double max_volume = 0.0;  // 0: three regular tets of edge `spacing`
  double radius_edge_ratio = 1.4;
  double min_dihedral_deg = 12.0;
};

TriSurface box_surface(const BoxOptions& options);
GenResult generate_box(const BoxOptions& options);

struct SphereOptions {
  double radius = 1.0;
  // Subdivisions of the icosahedron: the surface has 20 * 4^n near-equilateral triangles whose
  // edges are about 1.1 radius / 2^n long (n = 3: 1,280 triangles).
  std::uint32_t subdivisions = 3;
  double max_volume = 0.0;  // 0: three regular tets of the surface's mean edge
  double radius_edge_ratio = 1.4;
  double min_dihedral_deg = 12.0;
};

// An icosphere centred on the origin: each subdivision splits every triangle into four at its
// edges' midpoints, pushed out onto the sphere. A curved organ-like boundary of even density that
// no mesher of ours wrote the surface of (the fine-tool sweeps cut it, bench/quality_sweeps.cpp).
TriSurface sphere_surface(const SphereOptions& options);
GenResult generate_sphere(const SphereOptions& options);

// Any closed surface (a file the user brings).
struct SurfaceOptions {
  TetgenOptions tetgen;
};
GenResult generate_from_surface(const TriSurface& surface, const SurfaceOptions& options);

// Volume of the regular tetrahedron with edge length `edge`: the natural -a bound for a spacing.
double regular_tet_volume(double edge);

}  // namespace tetcut::generators
