// `tetcut gen KIND [OPTIONS] -o OUT` (design: the command line; issue 3: generators). KIND is
// cylinder, sheet, box (TetGen on surfaces we build), surface FILE (TetGen on a closed .off, .stl,
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

#include "args.hpp"
#include "command.hpp"
#include "tetcut/canonical_hash.hpp"
#include "tetcut/generators/liver.hpp"
#include "tetcut/generators/shapes.hpp"
#include "tetcut/io.hpp"
#include "tetcut/mesh_builder.hpp"
#include "detail/quality.hpp"

namespace tetcut::cli {
namespace {

using namespace tetcut::generators;

constexpr OptionSpec kOptions[] = {
    {"-o", true},          {"--out", true},        {"--radius", true},
    {"--height", true},    {"--segments", true},   {"--length", true},
    {"--width", true},     {"--thickness", true},  {"--size", true},
    {"--spacing", true},   {"--max-volume", true}, {"--quality", true},
    {"--min-dihedral", true}, {"--preserve-boundary", false}, {"--tets", true},
    {"--seed", true},      {"--image", true},
};

// Which options each kind accepts (besides -o/--out).
struct KindSpec {
  std::string_view kind;
  std::initializer_list<std::string_view> options;
};
const KindSpec kKinds[] = {
    {"cylinder", {"--radius", "--height", "--segments", "--max-volume", "--quality", "--min-dihedral"}},
    {"sheet", {"--length", "--width", "--thickness", "--quality"}},
    {"box", {"--size", "--spacing", "--max-volume", "--quality", "--min-dihedral"}},
    {"surface", {"--max-volume", "--quality", "--min-dihedral", "--preserve-boundary"}},
    {"liver", {"--size", "--tets", "--seed", "--image"}},
};

// Reads the optional numeric option `name` into `value`; false (with a message) if malformed.
bool read_double(const ParsedArgs& a, std::string_view name, double& value, std::string& error) {
  const auto text = a.value(name);
  if (!text) return true;
  const auto v = parse_double(*text);
  if (!v) {
    error = std::string(name) + " needs a number, not '" + *text + "'";
    return false;
  }
  value = *v;
  return true;
}

bool read_uint(const ParsedArgs& a, std::string_view name, std::uint64_t max, std::uint64_t& value,
               std::string& error) {
  const auto text = a.value(name);
  if (!text) return true;
  const auto v = parse_uint(*text);
  if (!v || *v > max) {
    error = std::string(name) + " needs an integer up to " + std::to_string(max) + ", not '" +
            *text + "'";
    return false;
  }
  value = *v;
  return true;
}

std::string format_double(double x) {
  std::ostringstream s;
  s << std::setprecision(4) << x;
  return s.str();
}

}  // namespace

int cmd_gen(Args args, std::ostream& out, std::ostream& err) {
  const ArgParseResult parsed = parse_args(args, kOptions);
  if (!parsed.ok()) return usage_error("gen", parsed.error, err);
  const ParsedArgs& a = parsed.args;
  const auto& pos = a.positionals;
  if (pos.empty()) return usage_error("gen", "needs a KIND: cylinder, sheet, box, surface FILE or liver", err);
  const std::string& kind = pos[0];
  const KindSpec* spec = nullptr;
  for (const auto& k : kKinds)
    if (k.kind == kind) spec = &k;
  if (spec == nullptr)
    return usage_error("gen", "unknown KIND '" + kind + "' (cylinder, sheet, box, surface, liver)", err);
  for (const auto& [name, value] : a.options) {
    if (name == "-o" || name == "--out") continue;
    if (std::find(spec->options.begin(), spec->options.end(), name) == spec->options.end())
      return usage_error("gen", "option " + name + " does not apply to " + kind, err);
  }
  if (pos.size() != (kind == "surface" ? 2u : 1u))
    return usage_error("gen", kind == "surface" ? "surface needs exactly one FILE" : "too many arguments", err);
  auto out_path = a.value("-o");
  if (!out_path) out_path = a.value("--out");
  if (!out_path || (a.has("-o") && a.has("--out")))
    return usage_error("gen", "needs exactly one output file: -o OUT", err);

  std::string error;
  GenResult result;
  std::string extra;  // a line about repair, for the liver
  if (kind == "cylinder") {
    CylinderOptions o;
    std::uint64_t segments = o.segments;
    if (!read_double(a, "--radius", o.radius, error) || !read_double(a, "--height", o.height, error) ||
        !read_uint(a, "--segments", 4096, segments, error) ||
        !read_double(a, "--max-volume", o.max_volume, error) ||
        !read_double(a, "--quality", o.radius_edge_ratio, error) ||
        !read_double(a, "--min-dihedral", o.min_dihedral_deg, error))
      return usage_error("gen", error, err);
    o.segments = static_cast<std::uint32_t>(segments);
    result = generate_cylinder(o);
  } else if (kind == "sheet") {
    SheetOptions o;
    if (!read_double(a, "--length", o.length, error) || !read_double(a, "--width", o.width, error) ||
        !read_double(a, "--thickness", o.thickness, error) ||
        !read_double(a, "--quality", o.radius_edge_ratio, error))
      return usage_error("gen", error, err);
    result = generate_sheet(o);
  } else if (kind == "box") {
    BoxOptions o;
    if (const auto text = a.value("--size")) {
      const auto v = parse_vec3(*text);
      if (!v) return usage_error("gen", "--size needs X,Y,Z, not '" + *text + "'", err);
      o.size = *v;
    }
    if (!read_double(a, "--spacing", o.spacing, error) ||
        !read_double(a, "--max-volume", o.max_volume, error) ||
        !read_double(a, "--quality", o.radius_edge_ratio, error) ||
        !read_double(a, "--min-dihedral", o.min_dihedral_deg, error))
      return usage_error("gen", error, err);
    result = generate_box(o);
  } else if (kind == "surface") {
    SurfaceOptions o;
    if (!read_double(a, "--max-volume", o.tetgen.max_volume, error) ||
        !read_double(a, "--quality", o.tetgen.radius_edge_ratio, error) ||
        !read_double(a, "--min-dihedral", o.tetgen.min_dihedral_deg, error))
      return usage_error("gen", error, err);
    o.tetgen.preserve_boundary = a.has("--preserve-boundary");
    const SurfaceReadResult read = read_surface(pos[1]);
    for (const auto& note : read.notices) err << "tetcut: " << pos[1] << ": note: " << note << '\n';
    if (!read.surface) {
      err << "tetcut: " << (read.error ? read.error->message() : pos[1] + ": cannot read") << '\n';
      return kExitBadInput;
    }
    result = generate_from_surface(*read.surface, o);
    if (!result.ok()) result.error = pos[1] + ": " + result.error;
  } else {  // liver
    LiverOptions o;
    if (a.has("--size") && a.has("--tets"))
      return usage_error("gen", "give --size or --tets, not both", err);
    std::uint64_t tets = 0, seed = 0;
    if (!read_double(a, "--size", o.cell_size, error) ||
        !read_uint(a, "--tets", 10'000'000, tets, error) ||
        !read_uint(a, "--seed", std::numeric_limits<std::uint32_t>::max(), seed, error))
      return usage_error("gen", error, err);
    if (a.has("--tets")) {
      if (tets < 100) return usage_error("gen", "--tets needs at least 100", err);
      o.cell_size = liver_cell_size_for_tets(static_cast<std::uint32_t>(tets));
    }
    o.seed = static_cast<std::uint32_t>(seed);
    if (const auto image = a.value("--image")) o.image_path = *image;
    RepairReport repair;
    result = generate_liver(o, &repair);
    extra = "Mesh_3 cell size " + format_double(o.cell_size) + "; repair removed " +
            std::to_string(repair.removed_tets()) + " tets at " +
            std::to_string(repair.singular_vertices_fixed) + " singular vertices and " +
            std::to_string(repair.singular_edges_fixed) + " singular edges";
  }
  if (!result.ok()) {
    err << "tetcut: gen: " << result.error << '\n';
    return kExitBadInput;
  }
  const RawMesh& mesh = *result.mesh;

  // The generators promise a manifold, positively oriented mesh: hold them to it.
  const BuildResult built = build_mesh(mesh, BuildOptions{.reorient_inverted = false, .require_manifold = true});
  if (!built.ok()) {
    err << "tetcut: gen " << kind << ": the generated mesh is invalid: "
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
