// Fixed-size binary values in a file's byte order, read and written the same way on any host:
// integers are assembled byte by byte with shifts (never by reinterpreting memory), and a
// floating-point value is the IEEE 754 bit pattern of such an integer, moved with memcpy. So a
// big-endian legacy VTK file or a little-endian Gmsh file decodes to the same bits everywhere.
// Internal to the engine (not installed).
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

namespace tetcut::io_detail {

enum class ByteOrder : std::uint8_t { kLittle, kBig };

// The unsigned value of the `size` (1..8) bytes at `p`.
[[nodiscard]] inline std::uint64_t load_uint(const unsigned char* p, std::size_t size, ByteOrder order) {
  std::uint64_t v = 0;
  for (std::size_t i = 0; i < size; ++i) {
    const std::size_t k = order == ByteOrder::kBig ? i : size - 1 - i;
    v = (v << 8) | p[k];
  }
  return v;
}

// The same bytes as a two's complement signed value.
[[nodiscard]] inline std::int64_t load_int(const unsigned char* p, std::size_t size, ByteOrder order) {
  const std::uint64_t u = load_uint(p, size, order);
  if (size == 8) {
    std::int64_t s = 0;
    std::memcpy(&s, &u, 8);
    return s;
  }
  const std::uint64_t sign = std::uint64_t{1} << (8 * size - 1);
  return (u & sign) != 0 ? static_cast<std::int64_t>(u) - static_cast<std::int64_t>(sign << 1)
                         : static_cast<std::int64_t>(u);
}

[[nodiscard]] inline double load_f64(const unsigned char* p, ByteOrder order) {
  const std::uint64_t bits = load_uint(p, 8, order);
  double d = 0;
  std::memcpy(&d, &bits, 8);
  return d;
}

[[nodiscard]] inline double load_f32(const unsigned char* p, ByteOrder order) {
  const auto bits = static_cast<std::uint32_t>(load_uint(p, 4, order));
  float f = 0;
  std::memcpy(&f, &bits, 4);
  return f;
}

inline void store_uint(std::string& out, std::uint64_t v, std::size_t size, ByteOrder order) {
  for (std::size_t i = 0; i < size; ++i) {
    const std::size_t shift = 8 * (order == ByteOrder::kBig ? size - 1 - i : i);
    out += static_cast<char>((v >> shift) & 0xFF);
  }
}

inline void store_f64(std::string& out, double d, ByteOrder order) {
  std::uint64_t bits = 0;
  std::memcpy(&bits, &d, 8);
  store_uint(out, bits, 8, order);
}

// A bounds-checked position in binary data: every read says whether the bytes were there.
class ByteCursor {
 public:
  ByteCursor(std::string_view bytes, ByteOrder order) : bytes_(bytes), order_(order) {}

  [[nodiscard]] std::size_t position() const { return pos_; }
  [[nodiscard]] std::size_t remaining() const { return bytes_.size() - pos_; }
  [[nodiscard]] bool has(std::size_t n) const { return n <= remaining(); }
  [[nodiscard]] ByteOrder order() const { return order_; }
  [[nodiscard]] const unsigned char* here() const {
    return reinterpret_cast<const unsigned char*>(bytes_.data()) + pos_;
  }

  bool skip(std::size_t n) {
    if (!has(n)) return false;
    pos_ += n;
    return true;
  }
  bool read_uint(std::size_t size, std::uint64_t& v) {
    if (!has(size)) return false;
    v = load_uint(here(), size, order_);
    pos_ += size;
    return true;
  }
  bool read_int(std::size_t size, std::int64_t& v) {
    if (!has(size)) return false;
    v = load_int(here(), size, order_);
    pos_ += size;
    return true;
  }
  bool read_f64(double& v) {
    if (!has(8)) return false;
    v = load_f64(here(), order_);
    pos_ += 8;
    return true;
  }

 private:
  std::string_view bytes_;
  ByteOrder order_;
  std::size_t pos_ = 0;
};

}  // namespace tetcut::io_detail
