// `tetcut convert IN OUT`: between the supported formats, chosen by extension (design: formats).
// Prints the canonical hash so that a user can see a round trip kept the mesh (the hash does not
// depend on numbering, which formats are free to change).
#include <ostream>
#include <optional>
#include <string>
#include <string_view>

#include "args.hpp"
#include "command.hpp"
#include "mesh_input.hpp"
#include "tetcut/canonical_hash.hpp"
#include "tetcut/io.hpp"

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
  static constexpr OptionSpec kOptions[] = {{"--format", true}};
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
  const std::string& in = positionals[0];
  const std::string& out_path = positionals[1];
  const std::optional<RawMesh> mesh = load_mesh(in, err);
  if (!mesh) return kExitBadInput;
  const WriteResult written =
      format ? write_mesh_as(out_path, *mesh, *format) : write_mesh(out_path, *mesh);
  if (!written.ok) {
    err << "tetcut: " << (written.error.empty() ? out_path + ": cannot write" : written.error)
        << '\n';
    return kExitBadInput;
  }
  out << out_path << ": " << mesh->positions.size() << " vertices, " << mesh->tets.size()
      << " tets, hash " << hash_to_hex(canonical_hash(*mesh)) << '\n';
  return kExitOk;
}

}  // namespace tetcut::cli
