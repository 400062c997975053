#include "mesh_input.hpp"

#include <cstdint>
#include <filesystem>
#include <ostream>
#include <system_error>
#include <string_view>

#include "tetcut/io.hpp"
#include "tetcut/predicates.hpp"

namespace tetcut::cli {

namespace {

// Messages stay on one line whatever a reason or a file name holds.
std::string one_line(std::string_view s) {
  std::string out(s);
  for (char& c : out) {
    if (c == '\n' || c == '\r') c = ' ';
  }
  return out;
}

// True when every tet is negatively oriented. Stops at the first tet that is not, so a mesh in
// tetcut's convention costs one orientation test.
bool all_tets_inverted(const RawMesh& mesh) {
  for (const auto& t : mesh.tets) {
    for (std::uint32_t v : t) {
      if (v >= mesh.positions.size()) return false;  // the checker names it
    }
    const auto& p = mesh.positions;
    if (orientation(p[t[0]], p[t[1]], p[t[2]], p[t[3]]) >= 0) return false;
  }
  return !mesh.tets.empty();
}

}  // namespace

std::optional<RawMesh> load_mesh(const std::string& path, std::ostream& err, bool orientation_note) {
  ReadResult result = read_mesh(path);
  for (const std::string& notice : result.notices) {
    err << "tetcut: " << one_line(path) << ": note: " << one_line(notice) << '\n';
  }
  if (result.error || !result.mesh) {
    if (result.error) {
      const ParseError& e = *result.error;
      // Formatted here rather than with ParseError::message() so that the CLI's promise,
      // "FILE:LINE: reason", does not depend on how each reader fills the fields.
      // An empty file has one place where it went wrong, its first line; some readers say 0
      // ("not tied to a line") there, and the user's editor wants a line number.
      std::uint64_t line = e.line;
      std::error_code ec;
      if (line == 0 && std::filesystem::is_regular_file(path, ec) &&
          std::filesystem::file_size(path, ec) == 0 && !ec) {
        line = 1;
      }
      err << "tetcut: " << one_line(e.file.empty() ? path : e.file);
      if (line > 0) err << ':' << line;
      err << ": " << one_line(e.reason.empty() ? "unreadable mesh" : e.reason) << '\n';
    } else {
      err << "tetcut: " << one_line(path) << ": unreadable mesh\n";
    }
    return std::nullopt;
  }
  if (result.mesh->tets.empty()) {
    err << "tetcut: " << one_line(path) << ": " << one_line(no_tetrahedra_reason(result)) << '\n';
    return std::nullopt;
  }
  if (orientation_note && all_tets_inverted(*result.mesh)) {
    err << "tetcut: " << one_line(path) << ": note: all " << result.mesh->tets.size()
        << " tets are negatively oriented (the opposite of tetcut's convention); "
           "`tetcut convert " << one_line(path) << " OUT --reorient` writes them positively oriented\n";
  }
  return std::move(*result.mesh);
}

bool save_mesh_and_report(const std::string& mesh_path, const TetMesh& mesh, const std::optional<std::string>& report_path,
                          const Json& report, std::ostream& err, std::span<const std::uint32_t> tet_labels) {
  const WriteResult written = tet_labels.empty() ? write_mesh(mesh_path, mesh) : write_mesh(mesh_path, mesh, tet_labels);
  if (!written.ok) {
    err << "tetcut: " << written.error << "\n";
    return false;
  }
  return !report_path || write_json_file(*report_path, report, err);
}

}  // namespace tetcut::cli
