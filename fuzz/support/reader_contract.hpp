// What every file reader promises, whatever bytes it is given (io.hpp), checked by the format
// fuzz targets:
//   - it returns, without crashing, either a mesh or an error, never both nor neither;
//   - a mesh it returns has every index in range and every coordinate finite
//     ("reader-contract" when not);
//   - for formats we also write: reading back what we wrote gives the same mesh, bit for bit
//     (writers use shortest round-trip number formatting) ("round-trip" when not).
#pragma once

#include <string_view>

#include "tetcut/io.hpp"

namespace tetcut::fuzz {

using TetReader = ReadResult (*)(std::string_view text, std::string_view name);
using TetFormatter = std::string (*)(const RawMesh& mesh);

// `reader` names the reader in failure messages. Returns the mesh read, if any.
const RawMesh* check_read_result(std::string_view reader, const ReadResult& result);
void check_surface_result(std::string_view reader, const SurfaceReadResult& result);

// Writes `mesh` with `format`, reads it back with `read` and aborts unless the result is equal.
void check_round_trip(std::string_view writer, const RawMesh& mesh, TetFormatter format, TetReader read);

// The common body of a single-text tet format target: read, check, and round-trip through
// `format`/`reread` when given (a read-only format round-trips through another format), and
// through `binary_format`/`reread` too when the format also has a binary writer.
void fuzz_tet_reader(std::string_view reader_name, TetReader read, std::string_view text,
                     TetFormatter format, TetReader reread, TetFormatter binary_format = nullptr);

}  // namespace tetcut::fuzz
