// Decoding the DataArrays of a VTK XML file into numbers: ascii text, inline binary (base64) or
// appended data (raw or base64), each binary block either one header value (its byte count) and
// the values, or, in a compressed file, the compression header
//   [number of blocks] [block size] [size of the last block, 0 if full] [compressed size of each]
// followed by the compressed blocks (zlib or xz). Header values are UInt32 or UInt64 as the
// file's header_type says, and every value is in the file's byte order.
// Internal to the engine (not installed).
#pragma once

#include <cstdint>
#include <limits>
#include <span>
#include <string_view>
#include <vector>

#include "vtk_xml.hpp"

namespace tetcut::io_detail {

class VtkArrayDecoder {
 public:
  static constexpr std::uint64_t kAny = std::numeric_limits<std::uint64_t>::max();

  VtkArrayDecoder(std::string_view text, const VtkXmlFile& file, ErrorSink& sink)
      : text_(text), file_(file), sink_(sink) {}

  // Exactly `expected` finite values (any number when kAny); `role` names them in errors
  // ("coordinate", "connectivity", ...).
  bool reals(const VtkDataArray& a, std::uint64_t expected, std::string_view role, std::vector<double>& out);
  // Exactly `expected` integer values of an integer-typed array.
  bool integers(const VtkDataArray& a, std::uint64_t expected, std::string_view role, std::vector<std::int64_t>& out);

 private:
  // The array's values as bytes (after base64, header and decompression) in bytes_.
  bool value_bytes(const VtkDataArray& a);
  // The first `n` bytes of the array's encoded block (header included) in view_; false if the
  // block holds fewer.
  bool block_prefix(const VtkDataArray& a, std::uint64_t n);
  bool uncompressed_values(const VtkDataArray& a);
  bool compressed_values(const VtkDataArray& a);
  [[nodiscard]] std::uint64_t header_value(std::size_t index) const;
  template <class T, class FromToken, class FromBytes>
  bool decode(const VtkDataArray& a, std::uint64_t expected, std::string_view role, std::vector<T>& out,
              FromToken from_token, FromBytes from_bytes);

  std::string_view text_;
  const VtkXmlFile& file_;
  ErrorSink& sink_;
  std::vector<unsigned char> decoded_;  // base64 decoded block
  std::string_view view_;               // the encoded block's bytes so far (into text_ or decoded_)
  std::uint64_t available_ = 0;         // how many bytes the block can hold at most
  std::vector<unsigned char> values_;  // decompressed values
  // value_bytes()'s answer: into text_, decoded_ or values_, valid until the next call.
  std::span<const unsigned char> bytes_;
};

}  // namespace tetcut::io_detail
