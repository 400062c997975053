// Reading the mesh a command was given, with the command line's way of reporting bad input.
#pragma once

#include <iosfwd>
#include <optional>
#include <string>

#include "tetcut/raw_mesh.hpp"

namespace tetcut::cli {

// Reads `path` by its extension. On failure prints "tetcut: FILE:LINE: reason" (one line) to
// `err` and returns nothing; the reader's notices (ignored elements, ...) go to `err` as
// "tetcut: FILE: note: ...".
std::optional<RawMesh> load_mesh(const std::string& path, std::ostream& err);

}  // namespace tetcut::cli
