#include "base64.hpp"

namespace tetcut::io_detail {

namespace {

int sextet(char c) {
  if (c >= 'A' && c <= 'Z') return c - 'A';
  if (c >= 'a' && c <= 'z') return c - 'a' + 26;
  if (c >= '0' && c <= '9') return c - '0' + 52;
  if (c == '+') return 62;
  if (c == '/') return 63;
  return -1;
}

// Emits the bytes of a partial or full quantum of `n` sextets.
bool flush(std::uint32_t bits, int n, std::vector<std::uint8_t>& out) {
  if (n == 1) return false;
  if (n == 0) return true;
  bits <<= 6 * (4 - n);
  out.push_back(static_cast<std::uint8_t>(bits >> 16));
  if (n >= 3) out.push_back(static_cast<std::uint8_t>(bits >> 8));
  if (n == 4) out.push_back(static_cast<std::uint8_t>(bits));
  return true;
}

}  // namespace

bool decode_base64(std::string_view text, std::size_t pos, std::size_t limit,
                   std::vector<std::uint8_t>& out) {
  const std::size_t target = out.size() + limit < out.size() ? static_cast<std::size_t>(-1) : out.size() + limit;
  std::uint32_t bits = 0;
  int n = 0;
  for (; pos < text.size() && out.size() < target; ++pos) {
    const char c = text[pos];
    if (c == ' ' || c == '\n' || c == '\r' || c == '\t') continue;
    if (c == '<') break;
    if (c == '=') {
      if (!flush(bits, n, out)) return false;
      bits = 0;
      n = 0;
      continue;
    }
    const int s = sextet(c);
    if (s < 0) return false;
    bits = (bits << 6) | static_cast<std::uint32_t>(s);
    if (++n == 4) {
      flush(bits, 4, out);
      bits = 0;
      n = 0;
    }
  }
  if (out.size() < target && !flush(bits, n, out)) return false;
  if (out.size() > target) out.resize(target);
  return true;
}

}  // namespace tetcut::io_detail
