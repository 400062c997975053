// `tetcut convert IN OUT`: between the supported formats, chosen by extension (design: formats),
// ASCII or binary (--binary, --compress for VTU), optionally reorienting inverted tets.
// Prints the canonical hash so that a user can see a round trip kept the mesh (the hash does not
// depend on numbering, which formats are free to change).
#include <ostream>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "command.hpp"
#include "command_parser.hpp"
#include "mesh_input.hpp"
#include "tetcut/canonical_hash.hpp"
#include "tetcut/io.hpp"
#include "tetcut/mesh_builder.hpp"

namespace tetcut::cli {

namespace {

std::optional<MeshFormat> parse_format(std::string_view s) {
  if (s == "msh22") return MeshFormat::kMsh22;
  if (s == "msh41") return MeshFormat::kMsh41;
  if (s == "vtu") return MeshFormat::kVtu;
  if (s == "vtk") return MeshFormat::kVtk;
  if (s == "medit") return MeshFormat::kMedit;
  if (s == "tetgen") return MeshFormat::kTetgen;
  return std::nullopt;
}

std::optional<Compression> parse_compression(std::string_view s) {
  if (s == "zlib") return Compression::kZlib;
  if (s == "lzma") return Compression::kLzma;
  return std::nullopt;
}

}  // namespace

int cmd_convert(Args args, std::ostream& out, std::ostream& err) {
  std::optional<std::string> in_arg, out_arg;
  std::optional<MeshFormat> format;
  std::optional<Compression> compression;
  bool binary = false, reorient = false;
  CommandParser parser(
      "convert", "tetcut convert IN OUT [--format F] [--binary] [--compress zlib|lzma] [--reorient]",
      "Converts a mesh between the supported formats, chosen by file extension, and prints the\n"
      "canonical hash of the mesh (identical for IN and OUT when the round trip is faithful).\n"
      "IN may be any format tetcut reads (ASCII, binary or compressed; see docs/usage.md).\n"
      "The output is written to a temporary file and renamed: a failure leaves no partial file.\n",
      "exit: 0, 2 unreadable input, unwritable output, a mesh --reorient cannot build, or bad usage");
  CLI::App& app = parser.app();
  opt::text(app, "IN", in_arg, "the mesh to read", "")->required();
  opt::text(app, "OUT", out_arg, "the file to write", "")->required();
  opt::parsed(app, "--format", format,
              "the output format, for when the extension is not enough: msh22 (the default for .msh) or msh41; "
              "also vtu, vtk, medit, tetgen",
              "F", parse_format, "must be msh22, msh41, vtu, vtk, medit or tetgen");
  opt::flag(app, "--binary", binary,
            "binary output: Gmsh binary MSH, legacy VTK BINARY, VTU appended raw data (medit and TetGen are "
            "text only)");
  opt::parsed(app, "--compress", compression, "VTU only, binary: zlib (vtkZLibDataCompressor) or lzma (xz)",
              "zlib|lzma", parse_compression, "must be zlib or lzma");
  opt::flag(app, "--reorient", reorient,
            "turn every negatively oriented tet positive (two vertices swapped), as the mesh builder does on "
            "request; for meshes from tools whose convention is the opposite of tetcut's");
  if (const auto code = parser.parse(args, out, err)) return *code;
  WriteOptions options;
  options.binary = binary;
  if (compression) options.compression = *compression;
  const std::string& in = *in_arg;
  const std::string& out_path = *out_arg;
  std::optional<RawMesh> mesh = load_mesh(in, err, !reorient);
  if (!mesh) return kExitBadInput;
  std::uint32_t reoriented = 0;
  if (reorient) {
    // The builder's own reorientation, so that what it accepts is what the engine loads.
    const BuildResult built = build_mesh(*mesh, BuildOptions{.reorient_inverted = true, .require_manifold = false});
    if (!built.ok()) {
      err << "tetcut: " << in << ": cannot reorient: " << built.problems.front().message << '\n';
      return kExitBadInput;
    }
    reoriented = built.reoriented;
    std::vector<std::uint32_t> labels = std::move(mesh->labels);
    mesh = built.mesh->to_raw();  // the same tets in the same order: the labels still match
    mesh->labels = std::move(labels);
  }
  const WriteResult written =
      format ? write_mesh_as(out_path, *mesh, *format, options) : write_mesh(out_path, *mesh, options);
  if (!written.ok) {
    err << "tetcut: " << (written.error.empty() ? out_path + ": cannot write" : written.error)
        << '\n';
    return kExitBadInput;
  }
  if (reorient) out << "reoriented " << reoriented << " of " << mesh->tets.size() << " tets\n";
  out << out_path << ": " << mesh->positions.size() << " vertices, " << mesh->tets.size()
      << " tets, hash " << hash_to_hex(canonical_hash(*mesh)) << '\n';
  return kExitOk;
}

}  // namespace tetcut::cli
