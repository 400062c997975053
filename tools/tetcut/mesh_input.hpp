// Reading the mesh a command was given, with the command line's way of reporting bad input.
#pragma once

#include <iosfwd>
#include <optional>
#include <span>
#include <string>

#include "json_output.hpp"
#include "tetcut/mesh.hpp"
#include "tetcut/raw_mesh.hpp"

namespace tetcut::cli {

// Reads `path` (format by content, else by extension). On failure prints "tetcut: FILE:LINE:
// reason" (one line) to `err` and returns nothing; the reader's notices (ignored elements, ...)
// go to `err` as "tetcut: FILE: note: ...". A file without tets is a failure that says what it
// held ("27 hexahedra, no tetrahedra"): every command needs tets. A mesh whose tets are all
// negatively oriented (another tool's convention) gets a note naming the command that
// reorients it, unless `orientation_note` is false (that command itself).
std::optional<RawMesh> load_mesh(const std::string& path, std::ostream& err, bool orientation_note = true);

// Writes `mesh` to `mesh_path` and, when `report_path` is set, `report`, each through a temporary
// file and a rename. On failure prints one line "tetcut: ..." to `err` and returns false.
// `tet_labels` by TetId, when the mesh has labels (empty: none).
bool save_mesh_and_report(const std::string& mesh_path, const TetMesh& mesh, const std::optional<std::string>& report_path,
                          const Json& report, std::ostream& err, std::span<const std::uint32_t> tet_labels = {});

}  // namespace tetcut::cli
