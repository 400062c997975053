#include "compression.hpp"

#include <lzma.h>
#include <zlib.h>

#include <algorithm>
#include <limits>

namespace tetcut::io_detail {

namespace {

// Output is produced in chunks of this size, so memory follows what the stream really holds.
constexpr std::size_t kChunk = 64 * 1024;
// An xz header chooses the decoder's dictionary size. Preset 9 (the largest a VTK or Python
// writer uses) needs 65 MiB; a header asking for more is refused rather than allocated.
constexpr std::uint64_t kLzmaMemoryLimit = 80ull << 20;

// Appends the `produced` bytes of `chunk` to `out`, unless the block would then exceed `expected`.
bool append_output(const unsigned char* chunk, std::size_t produced, std::size_t start, std::uint64_t expected,
                   std::vector<unsigned char>& out, std::string& reason) {
  if (out.size() - start + produced > expected) {
    reason = "compressed block yields more than the " + std::to_string(expected) + " bytes its header declares";
    return false;
  }
  out.insert(out.end(), chunk, chunk + produced);
  return true;
}

std::string too_little(std::uint64_t got, std::uint64_t expected) {
  return "compressed block yields " + std::to_string(got) + " bytes, its header declares " + std::to_string(expected);
}

bool inflate_zlib(std::string_view in, std::uint64_t expected, std::vector<unsigned char>& out, std::string& reason) {
  z_stream zs{};
  if (inflateInit(&zs) != Z_OK) {
    reason = "zlib could not start";
    return false;
  }
  const std::size_t start = out.size();
  unsigned char chunk[kChunk];
  std::size_t in_pos = 0;
  int rc = Z_OK;
  while (rc != Z_STREAM_END) {
    // zlib counts in uInt: feed the input in pieces it can count.
    if (zs.avail_in == 0 && in_pos < in.size()) {
      const std::size_t n = std::min<std::size_t>(in.size() - in_pos, std::numeric_limits<uInt>::max());
      zs.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(in.data() + in_pos));
      zs.avail_in = static_cast<uInt>(n);
      in_pos += n;
    }
    zs.next_out = chunk;
    zs.avail_out = kChunk;
    rc = inflate(&zs, Z_NO_FLUSH);
    if (!append_output(chunk, kChunk - zs.avail_out, start, expected, out, reason)) {
      inflateEnd(&zs);
      return false;
    }
    // Output space was given, so "no progress possible" means the input ran out.
    if (rc == Z_BUF_ERROR) {
      inflateEnd(&zs);
      reason = "compressed block ends before its zlib stream does (truncated?)";
      return false;
    }
    if (rc != Z_OK && rc != Z_STREAM_END) {
      reason = std::string("bad zlib stream: ") + (zs.msg != nullptr ? zs.msg : "error " + std::to_string(rc));
      inflateEnd(&zs);
      return false;
    }
  }
  const std::size_t left = zs.avail_in + (in.size() - in_pos);
  inflateEnd(&zs);
  if (left != 0) {
    reason = "compressed block has " + std::to_string(left) + " bytes after the end of its zlib stream";
    return false;
  }
  if (out.size() - start != expected) {
    reason = too_little(out.size() - start, expected);
    return false;
  }
  return true;
}

std::string lzma_reason(lzma_ret rc) {
  switch (rc) {
    case LZMA_MEMLIMIT_ERROR: return "xz stream needs more memory than any VTK writer asks for";
    case LZMA_FORMAT_ERROR: return "bad xz stream: not in the xz format";
    case LZMA_OPTIONS_ERROR: return "bad xz stream: unsupported options";
    case LZMA_DATA_ERROR: return "bad xz stream: corrupt data";
    case LZMA_BUF_ERROR: return "compressed block ends before its xz stream does (truncated?)";
    default: return "bad xz stream: error " + std::to_string(static_cast<int>(rc));
  }
}

bool inflate_lzma(std::string_view in, std::uint64_t expected, std::vector<unsigned char>& out, std::string& reason) {
  lzma_stream xs = LZMA_STREAM_INIT;
  if (lzma_stream_decoder(&xs, kLzmaMemoryLimit, LZMA_CONCATENATED) != LZMA_OK) {
    reason = "liblzma could not start";
    return false;
  }
  const std::size_t start = out.size();
  unsigned char chunk[kChunk];
  xs.next_in = reinterpret_cast<const std::uint8_t*>(in.data());
  xs.avail_in = in.size();
  lzma_ret rc = LZMA_OK;
  while (rc == LZMA_OK) {
    xs.next_out = chunk;
    xs.avail_out = kChunk;
    // All the input is there: LZMA_FINISH says so, and makes a truncated stream an error.
    rc = lzma_code(&xs, LZMA_FINISH);
    if (!append_output(chunk, kChunk - xs.avail_out, start, expected, out, reason)) {
      lzma_end(&xs);
      return false;
    }
  }
  lzma_end(&xs);
  if (rc != LZMA_STREAM_END) {
    reason = lzma_reason(rc);
    return false;
  }
  if (out.size() - start != expected) {
    reason = too_little(out.size() - start, expected);
    return false;
  }
  return true;
}

}  // namespace

bool decompress_block(Compressor compressor, std::string_view in, std::uint64_t expected,
                      std::vector<unsigned char>& out, std::string& reason) {
  return compressor == Compressor::kZlib ? inflate_zlib(in, expected, out, reason)
                                         : inflate_lzma(in, expected, out, reason);
}

std::string compress_block(Compressor compressor, std::string_view data) {
  std::string out;
  if (compressor == Compressor::kZlib) {
    uLongf size = compressBound(static_cast<uLong>(data.size()));
    out.resize(size);
    compress2(reinterpret_cast<Bytef*>(out.data()), &size, reinterpret_cast<const Bytef*>(data.data()),
              static_cast<uLong>(data.size()), Z_DEFAULT_COMPRESSION);
    out.resize(size);
  } else {
    out.resize(lzma_stream_buffer_bound(data.size()));
    std::size_t size = 0;
    lzma_easy_buffer_encode(6, LZMA_CHECK_CRC64, nullptr, reinterpret_cast<const std::uint8_t*>(data.data()),
                            data.size(), reinterpret_cast<std::uint8_t*>(out.data()), &size, out.size());
    out.resize(size);
  }
  return out;
}

}  // namespace tetcut::io_detail
