// `tetcut gen KIND [OPTIONS] -o OUT` (design: the command line). KIND is
// cylinder, sheet, box, sphere (TetGen on surfaces we build), surface FILE (TetGen on a closed .off, .stl,
// .obj or VTK POLYDATA .vtk/.vtp surface) or liver (CGAL Mesh_3 on Debian's segmented liver image, then repair). The mesh
// is validated with the mesh builder before it is written, and its canonical hash printed.
#include <algorithm>
#include <cstdint>
#include <iomanip>
#include <limits>
#include <optional>
#include <ostream>
#include <sstream>
#include <string>
#include <string_view>

#include "command.hpp"
#include "command_parser.hpp"
#include "core/quality.hpp"
#include "tetcut/canonical_hash.hpp"
#include "tetcut/generators/liver.hpp"
#include "tetcut/generators/shapes.hpp"
#include "tetcut/io.hpp"
#include "tetcut/mesh_builder.hpp"

namespace tetcut::cli {
namespace {

using namespace tetcut::generators;

// TetGen's quality options, shared by the kinds TetGen meshes.
void tetgen_options(CLI::App& kind, double& max_volume, double& quality, double& min_dihedral) {
  opt::number_into(kind, "--max-volume", max_volume, "largest tet volume (0: from the boundary spacing)", "V");
  opt::number_into(kind, "--quality", quality, "TetGen's radius-edge ratio bound (-q)", "Q");
  opt::number_into(kind, "--min-dihedral", min_dihedral, "TetGen's minimum dihedral angle in degrees", "DEG");
}

CLI::App* kind(CLI::App& gen, const std::string& name, const std::string& synopsis, const std::string& what) {
  CLI::App* sub = gen.add_subcommand(name, what);
  sub->fallthrough();  // -o OUT may come after the kind's own options
  set_synopsis(*sub, "tetcut gen " + synopsis);
  return sub;
}

std::string format_double(double x) {
  std::ostringstream s;
  s << std::setprecision(4) << x;
  return s.str();
}

}  // namespace

int cmd_gen(Args args, std::ostream& out, std::ostream& err) {
  std::optional<std::string> out_path, surface_path, image;
  CylinderOptions cylinder;
  SheetOptions sheet;
  BoxOptions box;
  SphereOptions sphere;
  std::optional<Vec3> box_size;
  SurfaceOptions surface;
  LiverOptions liver;
  std::optional<double> liver_size;
  std::optional<std::uint64_t> liver_tets;
  CommandParser parser("gen", "tetcut gen KIND [OPTIONS] -o OUT",
                       "Generates a mesh: cylinder, sheet, box, sphere (TetGen), surface FILE (any closed .off/.stl/.obj\n"
                       "surface, or a VTK POLYDATA surface .vtk/.vtp, through TetGen), liver (CGAL Mesh_3).\n"
                       "Prints the canonical hash.\n",
                       "exit: 0, 2 bad parameters or unwritable output");
  CLI::App& app = parser.app();
  app.require_subcommand(1, 1);
  opt::text(app, "-o,--out", out_path, "the mesh to write", "OUT")->required();

  CLI::App* c = kind(app, "cylinder", "cylinder [--radius R] [--height H] [--segments N] -o OUT", "a cylinder (TetGen)");
  opt::number_into(*c, "--radius", cylinder.radius, "radius", "R");
  opt::number_into(*c, "--height", cylinder.height, "height", "H");
  opt::count_into(*c, "--segments", cylinder.segments, 4096, "polygon sides approximating the circle");
  tetgen_options(*c, cylinder.max_volume, cylinder.radius_edge_ratio, cylinder.min_dihedral_deg);

  CLI::App* sh = kind(app, "sheet", "sheet [--length L] [--width W] [--thickness T] -o OUT", "a thin sheet (TetGen)");
  opt::number_into(*sh, "--length", sheet.length, "along x", "L");
  opt::number_into(*sh, "--width", sheet.width, "along y", "W");
  opt::number_into(*sh, "--thickness", sheet.thickness, "along z", "T");
  opt::number_into(*sh, "--quality", sheet.radius_edge_ratio, "TetGen's radius-edge ratio bound (-q)", "Q");

  CLI::App* b = kind(app, "box", "box [--size X,Y,Z] [--spacing S] -o OUT", "a box (TetGen)");
  opt::point(*b, "--size", box_size, "the box's extent");
  opt::number_into(*b, "--spacing", box.spacing, "boundary edge length; the tet size follows it", "S");
  tetgen_options(*b, box.max_volume, box.radius_edge_ratio, box.min_dihedral_deg);

  CLI::App* sp = kind(app, "sphere", "sphere [--radius R] [--subdivisions N] -o OUT", "an icosphere (TetGen)");
  opt::number_into(*sp, "--radius", sphere.radius, "radius", "R");
  opt::count_into(*sp, "--subdivisions", sphere.subdivisions, 7, "of the icosahedron: 20 x 4^N surface triangles");
  tetgen_options(*sp, sphere.max_volume, sphere.radius_edge_ratio, sphere.min_dihedral_deg);

  CLI::App* sf = kind(app, "surface", "surface FILE [--preserve-boundary] -o OUT", "a closed surface file, meshed by TetGen");
  opt::text(*sf, "FILE", surface_path, "a closed .off, .stl, .obj, or VTK POLYDATA .vtk/.vtp surface", "")->required();
  tetgen_options(*sf, surface.tetgen.max_volume, surface.tetgen.radius_edge_ratio, surface.tetgen.min_dihedral_deg);
  opt::flag(*sf, "--preserve-boundary", surface.tetgen.preserve_boundary, "keep the input triangles (TetGen -Y)");

  CLI::App* l = kind(app, "liver", "liver [--size S | --tets N] [--seed S] [--image FILE] -o OUT",
                     "CGAL Mesh_3 on Debian's segmented liver image, then repair");
  CLI::Option* size = opt::number(*l, "--size", liver_size, "Mesh_3 cell size in mm (smaller: more tets)", "S");
  opt::count(*l, "--tets", liver_tets, "about this many tets (100 to 10000000)")->excludes(size);
  opt::count_into(*l, "--seed", liver.seed, std::numeric_limits<std::uint32_t>::max(), "Mesh_3's random seed", "S");
  opt::text(*l, "--image", image, "an .inr/.inr.gz image instead of the bundled liver", "FILE");

  if (const auto code = parser.parse(args, out, err)) return *code;
  GenResult result;
  std::string extra;  // a line about repair, for the liver
  const std::string kind_name = app.get_subcommands().front()->get_name();
  if (c->parsed()) {
    result = generate_cylinder(cylinder);
  } else if (sh->parsed()) {
    result = generate_sheet(sheet);
  } else if (b->parsed()) {
    if (box_size) box.size = *box_size;
    result = generate_box(box);
  } else if (sp->parsed()) {
    result = generate_sphere(sphere);
  } else if (sf->parsed()) {
    const SurfaceReadResult read = read_surface(*surface_path);
    for (const auto& note : read.notices) err << "tetcut: " << *surface_path << ": note: " << note << '\n';
    if (!read.surface) {
      err << "tetcut: " << (read.error ? read.error->message() : *surface_path + ": cannot read") << '\n';
      return kExitBadInput;
    }
    result = generate_from_surface(*read.surface, surface);
    if (!result.ok()) result.error = *surface_path + ": " + result.error;
  } else {  // liver
    if (liver_size) liver.cell_size = *liver_size;
    if (liver_tets) {
      if (*liver_tets < 100 || *liver_tets > 10'000'000) return parser.usage_error("--tets: from 100 to 10000000", err);
      liver.cell_size = liver_cell_size_for_tets(static_cast<std::uint32_t>(*liver_tets));
    }
    if (image) liver.image_path = *image;
    RepairReport repair;
    result = generate_liver(liver, &repair);
    extra = "Mesh_3 cell size " + format_double(liver.cell_size) + "; repair removed " +
            std::to_string(repair.removed_tets()) + " tets at " + std::to_string(repair.singular_vertices_fixed) +
            " singular vertices and " + std::to_string(repair.singular_edges_fixed) + " singular edges";
  }
  if (!result.ok()) {
    err << "tetcut: gen: " << result.error << '\n';
    return kExitBadInput;
  }
  const RawMesh& mesh = *result.mesh;

  // The generators promise a manifold, positively oriented mesh: hold them to it.
  const BuildResult built = build_mesh(mesh, BuildOptions{.reorient_inverted = false, .require_manifold = true});
  if (!built.ok()) {
    err << "tetcut: gen " << kind_name << ": the generated mesh is invalid: "
        << built.problems.front().message << '\n';
    return kExitViolated;
  }
  const WriteResult written = write_mesh(*out_path, mesh);
  if (!written.ok) {
    err << "tetcut: " << (written.error.empty() ? *out_path + ": cannot write" : written.error) << '\n';
    return kExitBadInput;
  }
  double min_rr = 1.0;
  for (const auto& t : mesh.tets)
    min_rr = std::min(min_rr, radius_ratio(mesh.positions[t[0]], mesh.positions[t[1]],
                                           mesh.positions[t[2]], mesh.positions[t[3]]));
  if (!extra.empty()) out << extra << '\n';
  out << *out_path << ": " << mesh.positions.size() << " vertices, " << mesh.tets.size()
      << " tets, min radius ratio " << format_double(min_rr) << ", hash "
      << hash_to_hex(canonical_hash(mesh)) << '\n';
  return kExitOk;
}

}  // namespace tetcut::cli
