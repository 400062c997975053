// Base64 decoding as VTK XML files need it (inline binary and appended base64 data).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

namespace tetcut::io_detail {

// Decodes text[pos..) into `out` (appended), skipping whitespace, until `limit` bytes have been
// produced (the excess of the last quantum is dropped) or the text ends or a '<' is met. Padding
// closes a quantum and decoding goes on, because VTK may encode a header and its data as two
// separate base64 streams. False on a character outside the base64 alphabet or a lone sextet.
bool decode_base64(std::string_view text, std::size_t pos, std::size_t limit,
                   std::vector<std::uint8_t>& out);

}  // namespace tetcut::io_detail
