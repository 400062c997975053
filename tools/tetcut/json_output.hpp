// The command line's JSON output, through nlohmann-json (Debian's nlohmann-json3-dev).
//
// Keys come out in the order the code sets them (ordered_json), so output is deterministic and a
// diff of two reports is meaningful. Doubles are written in the shortest form that reads back to
// the same bits (nlohmann's Grisu2-based dtoa; tests/cli/json_output_test.cpp holds it to that);
// NaN and infinities, which JSON cannot express, become null, as they always have. Bytes that are
// not valid UTF-8 (a file name can hold anything) become U+FFFD, so the output is always valid
// JSON. Layout: two-space indent, one value a line.
#pragma once

#include <iosfwd>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

namespace tetcut::cli {

using Json = nlohmann::ordered_json;

// `value` as the text a command prints or writes, ending with a newline.
std::string json_text(const Json& value);

// `v` when there is something to report, null otherwise (a quality with no tets is not 0).
inline Json number_or_null(double v, bool present) { return present ? Json(v) : Json(nullptr); }

// Writes `value` to `path` through a temporary file and a rename; on failure prints one line
// "tetcut: ..." to `err` and returns false.
bool write_json_file(const std::string& path, const Json& value, std::ostream& err);

}  // namespace tetcut::cli
