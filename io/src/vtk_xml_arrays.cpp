#include "vtk_xml_arrays.hpp"

#include <cmath>
#include <string>

#include "base64.hpp"

namespace tetcut::io_detail {

namespace {

bool is_float_type(std::string_view type) { return type == "Float32" || type == "Float64"; }

// Value i of `type` in `bytes` as a double (integers converted).
double real_value(std::string_view type, const unsigned char* p, ByteOrder order) {
  if (type == "Float64") return load_f64(p, order);
  if (type == "Float32") return load_f32(p, order);
  const std::size_t size = vtk_type_size(type);
  if (type[0] == 'U') return static_cast<double>(load_uint(p, size, order));
  return static_cast<double>(load_int(p, size, order));
}

// Value of an integer `type`; false when it does not fit an int64 (a UInt64 past 2^63).
bool integer_value(std::string_view type, const unsigned char* p, ByteOrder order, std::int64_t& v) {
  const std::size_t size = vtk_type_size(type);
  if (type[0] == 'U') {
    const std::uint64_t u = load_uint(p, size, order);
    if (u > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max())) return false;
    v = static_cast<std::int64_t>(u);
    return true;
  }
  v = load_int(p, size, order);
  return true;
}

}  // namespace

std::uint64_t VtkArrayDecoder::header_value(std::size_t index) const {
  return load_uint(reinterpret_cast<const unsigned char*>(view_.data()) + index * file_.header_size,
                   file_.header_size, file_.order);
}

bool VtkArrayDecoder::block_prefix(const VtkDataArray& a, std::uint64_t n) {
  if (n > available_) return false;
  if (a.format == "appended" && file_.appended_base64) {
    // Decoded from the start each time, only as far as needed: a header may have been encoded
    // as its own base64 stream, which decode_base64 reads through.
    decoded_.clear();
    const std::size_t start = file_.appended_begin + static_cast<std::size_t>(a.offset);
    if (!decode_base64(text_, start, static_cast<std::size_t>(n), decoded_)) {
      return sink_.fail(a.line, "invalid base64 appended data");
    }
    view_ = std::string_view(reinterpret_cast<const char*>(decoded_.data()), decoded_.size());
  }
  return view_.size() >= n;
}

bool VtkArrayDecoder::value_bytes(const VtkDataArray& a) {
  values_.clear();
  decoded_.clear();
  bytes_ = {};
  if (a.format == "binary") {
    if (!decode_base64(text_.substr(0, a.content_end), a.content_begin, static_cast<std::size_t>(-1), decoded_)) {
      return sink_.fail(a.content_line, "invalid base64 data in DataArray");
    }
    view_ = std::string_view(reinterpret_cast<const char*>(decoded_.data()), decoded_.size());
    available_ = view_.size();
  } else {
    if (!file_.have_appended) return sink_.fail(a.line, "DataArray refers to appended data but the file has no <AppendedData>");
    if (a.offset > text_.size() - file_.appended_begin) {
      return sink_.fail(a.line, "appended offset " + std::to_string(a.offset) + " exceeds file size");
    }
    const std::size_t start = file_.appended_begin + static_cast<std::size_t>(a.offset);
    view_ = file_.appended_base64 ? std::string_view() : text_.substr(start);
    available_ = file_.appended_base64 ? (text_.size() - start) / 4 * 3 + 2 : text_.size() - start;
  }
  if (!(file_.compressor ? compressed_values(a) : uncompressed_values(a))) return false;
  const std::size_t size = vtk_type_size(a.type);
  if (bytes_.size() % size != 0) {
    return sink_.fail(a.line, "binary DataArray size " + std::to_string(bytes_.size()) + " is not a multiple of its " +
                                  std::string(a.type) + " values");
  }
  return true;
}

bool VtkArrayDecoder::uncompressed_values(const VtkDataArray& a) {
  const std::size_t hs = file_.header_size;
  if (!block_prefix(a, hs)) {
    return sink_.failed() ? false : sink_.fail(a.line, "binary DataArray shorter than its header");
  }
  const std::uint64_t n = header_value(0);
  if (a.format == "binary" && n != view_.size() - hs) {
    return sink_.fail(a.line, "binary DataArray declares " + std::to_string(n) + " bytes but holds " +
                                  std::to_string(view_.size() - hs));
  }
  if (n > available_ - hs || !block_prefix(a, hs + n)) {
    return sink_.failed() ? false : sink_.fail(a.line, "byte count " + std::to_string(n) + " exceeds file size");
  }
  // Read where they are (the file's text or the base64 decoded block), not copied: a copy of the
  // connectivity was a sixth of a session's peak memory (bench/session_memory.cpp).
  bytes_ = std::span<const unsigned char>(reinterpret_cast<const unsigned char*>(view_.data()) + hs, static_cast<std::size_t>(n));
  return true;
}

bool VtkArrayDecoder::compressed_values(const VtkDataArray& a) {
  const std::size_t hs = file_.header_size;
  if (!block_prefix(a, 3 * hs)) {
    return sink_.failed() ? false : sink_.fail(a.line, "compressed DataArray shorter than its compression header");
  }
  const std::uint64_t blocks = header_value(0);
  const std::uint64_t block_size = header_value(1);
  const std::uint64_t last_size = header_value(2);
  if (blocks > (available_ - 3 * hs) / hs) {
    return sink_.fail(a.line, "compression header declares " + std::to_string(blocks) +
                                  " blocks, more than the file holds");
  }
  const std::uint64_t header_bytes = (3 + blocks) * hs;
  if (!block_prefix(a, header_bytes)) {
    return sink_.failed() ? false : sink_.fail(a.line, "compression header cut short");
  }
  std::uint64_t compressed_total = 0;
  for (std::uint64_t b = 0; b < blocks; ++b) {
    const std::uint64_t c = header_value(static_cast<std::size_t>(3 + b));
    if (c > available_ - header_bytes - compressed_total) {
      return sink_.fail(a.line, "compressed block sizes add up to more than the file holds (block " +
                                    std::to_string(b) + " of " + std::to_string(blocks) + ")");
    }
    compressed_total += c;
  }
  if (last_size > block_size) {
    return sink_.fail(a.line, "compression header: last block of " + std::to_string(last_size) +
                                  " bytes is larger than the block size " + std::to_string(block_size));
  }
  if (!block_prefix(a, header_bytes + compressed_total)) {
    return sink_.failed() ? false : sink_.fail(a.line, "compressed data cut short");
  }
  if (a.format == "binary" && header_bytes + compressed_total != view_.size()) {
    return sink_.fail(a.line, "compressed DataArray holds " + std::to_string(view_.size()) +
                                  " bytes, its compression header declares " +
                                  std::to_string(header_bytes + compressed_total));
  }
  // Block sizes come from the header; the output grows only as each stream yields data.
  std::uint64_t at = header_bytes;
  std::string reason;
  for (std::uint64_t b = 0; b < blocks; ++b) {
    const std::uint64_t c = header_value(static_cast<std::size_t>(3 + b));
    const std::uint64_t expected = b + 1 == blocks && last_size != 0 ? last_size : block_size;
    if (!decompress_block(*file_.compressor, view_.substr(static_cast<std::size_t>(at), static_cast<std::size_t>(c)),
                          expected, values_, reason)) {
      return sink_.fail(a.line, "block " + std::to_string(b + 1) + " of " + std::to_string(blocks) + ": " + reason);
    }
    at += c;
  }
  bytes_ = std::span<const unsigned char>(values_.data(), values_.size());
  return true;
}

// The shared walk of reals() and integers(): ascii tokens through `from_token(line, token, v)`,
// binary values through `from_bytes(index, bytes, v)`, each false (with an error) to stop.
template <class T, class FromToken, class FromBytes>
bool VtkArrayDecoder::decode(const VtkDataArray& a, std::uint64_t expected, std::string_view role,
                             std::vector<T>& out, FromToken from_token, FromBytes from_bytes) {
  out.clear();
  if (a.format == "ascii") {
    TokenReader tokens(text_.substr(a.content_begin, a.content_end - a.content_begin), '\0', a.content_line);
    std::string_view token;
    while (tokens.next(token)) {
      T v{};
      if (!from_token(tokens.line_number(), token, v)) return false;
      if (out.size() >= expected) {
        return sink_.fail(tokens.line_number(), "more " + std::string(role) + " values than the Piece declares");
      }
      out.push_back(v);
    }
  } else {
    if (!value_bytes(a)) return false;
    const std::size_t size = vtk_type_size(a.type);
    const std::size_t n = bytes_.size() / size;
    if (expected != kAny && n != expected) {
      return sink_.fail(a.line, "expected " + std::to_string(expected) + " " + std::string(role) + " values, got " +
                                    std::to_string(n));
    }
    out.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
      T v{};
      if (!from_bytes(i, bytes_.data() + i * size, v)) return false;
      out.push_back(v);
    }
  }
  if (expected != kAny && out.size() != expected) {
    return sink_.fail(a.line, "expected " + std::to_string(expected) + " " + std::string(role) + " values, got " +
                                  std::to_string(out.size()));
  }
  return true;
}

bool VtkArrayDecoder::reals(const VtkDataArray& a, std::uint64_t expected, std::string_view role,
                            std::vector<double>& out) {
  return decode(
      a, expected, role, out,
      [&](std::uint64_t line, std::string_view token, double& v) { return parse_coordinate(sink_, line, token, v); },
      [&](std::size_t i, const unsigned char* p, double& v) {
        v = real_value(a.type, p, file_.order);
        if (std::isnan(v)) return sink_.fail(a.line, "NaN coordinate (value " + std::to_string(i) + ")");
        if (std::isinf(v)) return sink_.fail(a.line, "infinite coordinate (value " + std::to_string(i) + ")");
        return true;
      });
}

bool VtkArrayDecoder::integers(const VtkDataArray& a, std::uint64_t expected, std::string_view role,
                               std::vector<std::int64_t>& out) {
  if (is_float_type(a.type)) {
    return sink_.fail(a.line, std::string(role) + " must have an integer type, got " + quote(a.type));
  }
  return decode(
      a, expected, role, out,
      [&](std::uint64_t line, std::string_view token, std::int64_t& v) {
        return parse_i64(token, v) ||
               sink_.fail(line, "expected an integer in " + std::string(role) + ", got " + quote(token));
      },
      [&](std::size_t, const unsigned char* p, std::int64_t& v) {
        return integer_value(a.type, p, file_.order, v) || sink_.fail(a.line, "value out of range in " + std::string(role));
      });
}

}  // namespace tetcut::io_detail
