#include "tetcut/generators/tetgen_mesher.hpp"

#include <tetgen.h>

#include <cstdio>
#include <utility>
#include <vector>

#include "tetcut/predicates.hpp"

namespace tetcut::generators {
namespace {

// TetGen's terminatetetgen() throws these codes in library mode (tetgen.h).
std::string tetgen_error_text(int code) {
  switch (code) {
    case 1: return "TetGen ran out of memory";
    case 2: return "TetGen hit an internal error";
    case 3: return "the surface intersects itself (TetGen code 3)";
    case 4: return "the surface has very small input features (TetGen code 4)";
    case 5: return "the surface has two very close input facets (TetGen code 5)";
    case 10: return "TetGen found an input error (code 10)";
    default: return "TetGen failed with code " + std::to_string(code);
  }
}

// Copies the surface into TetGen's input structure (one single-polygon facet per triangle).
void fill_tetgenio(const TriSurface& surface, tetgenio& in) {
  in.firstnumber = 0;
  in.numberofpoints = static_cast<int>(surface.positions.size());
  in.pointlist = new REAL[3 * surface.positions.size()];
  for (std::size_t i = 0; i < surface.positions.size(); ++i) {
    in.pointlist[3 * i + 0] = surface.positions[i].x;
    in.pointlist[3 * i + 1] = surface.positions[i].y;
    in.pointlist[3 * i + 2] = surface.positions[i].z;
  }
  in.numberoffacets = static_cast<int>(surface.triangles.size());
  in.facetlist = new tetgenio::facet[surface.triangles.size()];
  for (std::size_t f = 0; f < surface.triangles.size(); ++f) {
    tetgenio::facet& facet = in.facetlist[f];
    tetgenio::init(&facet);
    facet.numberofpolygons = 1;
    facet.polygonlist = new tetgenio::polygon[1];
    tetgenio::init(&facet.polygonlist[0]);
    facet.polygonlist[0].numberofvertices = 3;
    facet.polygonlist[0].vertexlist = new int[3];
    for (int k = 0; k < 3; ++k)
      facet.polygonlist[0].vertexlist[k] = static_cast<int>(surface.triangles[f][k]);
  }
}

}  // namespace

std::string tetgen_switches(const TetgenOptions& options) {
  std::string s = "pzQ";
  char buffer[64];
  if (options.radius_edge_ratio > 0.0) {
    if (options.min_dihedral_deg > 0.0)
      std::snprintf(buffer, sizeof buffer, "q%.6g/%.6g", options.radius_edge_ratio,
                    options.min_dihedral_deg);
    else
      std::snprintf(buffer, sizeof buffer, "q%.6g", options.radius_edge_ratio);
    s += buffer;
  }
  if (options.max_volume > 0.0) {
    std::snprintf(buffer, sizeof buffer, "a%.17g", options.max_volume);
    s += buffer;
  }
  if (options.preserve_boundary) s += "Y";
  return s;
}

GenResult tetrahedralize_surface(const TriSurface& surface, const TetgenOptions& options) {
  if (auto problem = closed_surface_problem(surface)) return GenResult::failure(*problem);
  if (options.radius_edge_ratio != 0.0 && options.radius_edge_ratio < 1.0)
    return GenResult::failure("the radius-edge ratio bound must be at least 1.0");
  if (options.max_volume < 0.0) return GenResult::failure("the maximum volume must be positive");

  // TetGen 1.5 can crash on a self-intersecting surface instead of reporting it: ask its -d
  // detector first, which only lists the intersecting triangles.
  {
    tetgenio in;
    tetgenio out;
    fill_tetgenio(surface, in);
    std::string detect = "pdzQ";
    try {
      tetrahedralize(detect.data(), &in, &out);
    } catch (int code) {
      return GenResult::failure(tetgen_error_text(code));
    }
    if (out.numberoftrifaces > 0)
      return GenResult::failure("the surface intersects itself (" +
                                std::to_string(out.numberoftrifaces) +
                                " triangles involved, found by TetGen -d)");
  }

  tetgenio in;
  tetgenio out;
  fill_tetgenio(surface, in);
  std::string switches = tetgen_switches(options);
  try {
    tetrahedralize(switches.data(), &in, &out);
  } catch (int code) {
    return GenResult::failure(tetgen_error_text(code));
  }
  if (out.numberoftetrahedra <= 0 || out.numberofcorners < 4)
    return GenResult::failure("TetGen produced no tetrahedra");

  // TetGen may keep input points no tet uses (e.g. duplicates it merged): renumber the used ones
  // in their TetGen order, which is deterministic.
  const auto npoints = static_cast<std::size_t>(out.numberofpoints);
  std::vector<std::uint32_t> new_index(npoints, kDeadTetMarker);
  RawMesh mesh;
  mesh.tets.reserve(static_cast<std::size_t>(out.numberoftetrahedra));
  for (int t = 0; t < out.numberoftetrahedra; ++t) {
    std::array<std::uint32_t, 4> tet{};
    for (int k = 0; k < 4; ++k) {
      const int p = out.tetrahedronlist[t * out.numberofcorners + k];
      if (p < 0 || static_cast<std::size_t>(p) >= npoints)
        return GenResult::failure("TetGen returned a dangling vertex index");
      auto& idx = new_index[static_cast<std::size_t>(p)];
      if (idx == kDeadTetMarker) {
        idx = static_cast<std::uint32_t>(mesh.positions.size());
        mesh.positions.push_back(
            {out.pointlist[3 * p + 0], out.pointlist[3 * p + 1], out.pointlist[3 * p + 2]});
      }
      tet[k] = idx;
    }
    // TetGen's positive orientation is the opposite of ours; decide each tet exactly anyway.
    const auto& P = mesh.positions;
    const int o = orientation(P[tet[0]], P[tet[1]], P[tet[2]], P[tet[3]]);
    if (o == 0) return GenResult::failure("TetGen produced a flat tetrahedron");
    if (o < 0) std::swap(tet[2], tet[3]);
    mesh.tets.push_back(tet);
  }
  return GenResult::success(std::move(mesh));
}

}  // namespace tetcut::generators
