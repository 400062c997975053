// Reading the mesh a command was given, with the command line's way of reporting bad input.
#pragma once

#include <functional>
#include <iosfwd>
#include <optional>
#include <string>

#include "json_writer.hpp"
#include "tetcut/mesh.hpp"
#include "tetcut/raw_mesh.hpp"

namespace tetcut::cli {

// Reads `path` by its extension. On failure prints "tetcut: FILE:LINE: reason" (one line) to
// `err` and returns nothing; the reader's notices (ignored elements, ...) go to `err` as
// "tetcut: FILE: note: ...".
std::optional<RawMesh> load_mesh(const std::string& path, std::ostream& err);

// Writes `mesh` to `mesh_path` and, when `report_path` is set, a JSON object whose members
// `fill` writes, each through a temporary file and a rename. On failure prints one line
// "tetcut: ..." to `err` and returns false.
bool save_mesh_and_report(const std::string& mesh_path, const TetMesh& mesh, const std::optional<std::string>& report_path,
                          const std::function<void(JsonWriter&)>& fill, std::ostream& err);

}  // namespace tetcut::cli
