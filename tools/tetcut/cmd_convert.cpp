// `tetcut convert IN OUT`: between the supported formats, chosen by extension (design: formats),
// ASCII or binary (--binary, --compress for VTU), optionally reorienting inverted tets.
// Prints the canonical hash so that a user can see a round trip kept the mesh (the hash does not
// depend on numbering, which formats are free to change).
#include <ostream>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "args.hpp"
#include "command.hpp"
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

}  // namespace

int cmd_convert(Args args, std::ostream& out, std::ostream& err) {
  static constexpr OptionSpec kOptions[] = {
      {"--format", true}, {"--binary", false}, {"--compress", true}, {"--reorient", false}};
  const ArgParseResult parsed = parse_args(args, kOptions);
  if (!parsed.ok()) return usage_error("convert", parsed.error, err);
  const auto& positionals = parsed.args.positionals;
  if (positionals.size() != 2) {
    return usage_error("convert",
                       positionals.size() < 2 ? "needs IN and OUT" : "too many arguments", err);
  }
  std::optional<MeshFormat> format;
  if (const auto text = parsed.args.value("--format")) {
    format = parse_format(*text);
    if (!format) {
      return usage_error(
          "convert", "--format must be msh22, msh41, vtu, vtk, medit or tetgen, not '" + *text + "'",
          err);
    }
  }
  WriteOptions options;
  options.binary = parsed.args.has("--binary");
  if (const auto text = parsed.args.value("--compress")) {
    if (*text == "zlib") options.compression = Compression::kZlib;
    else if (*text == "lzma") options.compression = Compression::kLzma;
    else return usage_error("convert", "--compress must be zlib or lzma, not '" + *text + "'", err);
  }
  const std::string& in = positionals[0];
  const std::string& out_path = positionals[1];
  const bool reorient = parsed.args.has("--reorient");
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
    mesh = built.mesh->to_raw();
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
