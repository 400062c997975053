// The liver of the paper's test set (section 3.6), made from a real segmented liver: CGAL Mesh_3
// on `liver.inr.gz`, the image Debian ships in libcgal-demo's data.tar.gz. Mesh_3's complex has a
// few singular vertices and edges (and its manifold() criterion does not finish on this image in
// reasonable memory), so the result goes through repair_mesh, which removes the few tets at the
// singularities. Deterministic: Mesh_3's random generators are seeded.
#pragma once

#include <cstdint>
#include <string>

#include "tetcut/generators/gen_result.hpp"
#include "tetcut/generators/repair.hpp"

namespace tetcut::generators {

// Where Debian's libcgal-dev puts the tarball holding the image.
inline constexpr const char* kCgalDataTarball = "/usr/share/doc/libcgal-dev/data.tar.gz";
inline constexpr const char* kLiverImageMember = "data/images/liver.inr.gz";

struct LiverOptions {
  // Mesh_3 cell_size in image units (mm); facet size and distance follow it. Smaller = more tets.
  double cell_size = 10.0;
  // An .inr/.inr.gz image; empty: extract the liver from kCgalDataTarball into a temporary
  // directory with tar.
  std::string image_path;
  std::uint32_t seed = 0;
  // false: return Mesh_3's complex as it comes, singularities and all (tests use it as a real
  // non-manifold mesh from another tool).
  bool repair = true;
};

// The cell size that yields about `target_tets` tets (calibrated on the Debian image; see
// corpus/meshes/README.md).
double liver_cell_size_for_tets(std::uint32_t target_tets);

// `repair`, when given, receives what repair_mesh changed in Mesh_3's output.
GenResult generate_liver(const LiverOptions& options, RepairReport* repair = nullptr);

}  // namespace tetcut::generators
