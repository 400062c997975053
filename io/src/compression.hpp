// The compressors of VTK XML files, through Debian's zlib and liblzma (never hand-written
// decoding): one block in, one block out. Internal to the engine (not installed).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace tetcut::io_detail {

enum class Compressor : std::uint8_t {
  kZlib,  // vtkZLibDataCompressor: a zlib stream per block
  kLzma,  // vtkLZMADataCompressor: an xz stream per block
};

// Decompresses the block `in` and appends its bytes to `out`, which must come to exactly
// `expected` bytes (the size the file's header declares). `out` grows only as the stream yields
// data, so a header that declares an absurd size allocates nothing for it. False, with `reason`
// ("bad zlib stream: ...", "block yields more than the 32768 bytes declared", ...), otherwise.
bool decompress_block(Compressor compressor, std::string_view in, std::uint64_t expected,
                      std::vector<unsigned char>& out, std::string& reason);

// The block `data`, compressed (zlib's default level; xz preset 6, as VTK and Python write).
std::string compress_block(Compressor compressor, std::string_view data);

}  // namespace tetcut::io_detail
