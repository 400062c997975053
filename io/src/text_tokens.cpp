// The token-level pieces of text_reader.hpp: quoting a token for a message, trimming and
// splitting, ASCII case-insensitive comparison, and whole-token number parsing with
// std::from_chars (locale-independent). The line and token readers are in text_reader.cpp.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <system_error>

#include "text_reader.hpp"

namespace tetcut::io_detail {

std::string quote(std::string_view token) {
  constexpr std::size_t kMax = 40;
  std::string out = "'";
  for (std::size_t i = 0; i < token.size() && i < kMax; ++i) {
    const unsigned char c = static_cast<unsigned char>(token[i]);
    if (c >= 0x20 && c < 0x7F) {
      out += static_cast<char>(c);
    } else {
      constexpr char kHex[] = "0123456789abcdef";
      out += "\\x";
      out += kHex[c >> 4];
      out += kHex[c & 15];
    }
  }
  if (token.size() > kMax) out += "...";
  out += "'";
  return out;
}

std::string_view trim(std::string_view s) {
  std::size_t b = 0;
  std::size_t e = s.size();
  while (b < e && is_space(s[b])) ++b;
  while (e > b && is_space(s[e - 1])) --e;
  return s.substr(b, e - b);
}

void split_tokens(std::string_view line, std::vector<std::string_view>& out) {
  out.clear();
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && is_space(line[i])) ++i;
    const std::size_t start = i;
    while (i < line.size() && !is_space(line[i])) ++i;
    if (i > start) out.push_back(line.substr(start, i - start));
  }
}

bool iequals(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    char x = a[i];
    char y = b[i];
    if (x >= 'A' && x <= 'Z') x = static_cast<char>(x - 'A' + 'a');
    if (y >= 'A' && y <= 'Z') y = static_cast<char>(y - 'A' + 'a');
    if (x != y) return false;
  }
  return true;
}

namespace {
std::string_view strip_plus(std::string_view t) {
  // from_chars rejects a leading '+', which C's strtod and most writers accept.
  if (t.size() > 1 && t[0] == '+' && t[1] != '-' && t[1] != '+') t.remove_prefix(1);
  return t;
}
}  // namespace

bool parse_u64(std::string_view token, std::uint64_t& value) {
  token = strip_plus(token);
  if (token.empty()) return false;
  const auto r = std::from_chars(token.data(), token.data() + token.size(), value);
  return r.ec == std::errc() && r.ptr == token.data() + token.size();
}

bool parse_i64(std::string_view token, std::int64_t& value) {
  token = strip_plus(token);
  if (token.empty()) return false;
  const auto r = std::from_chars(token.data(), token.data() + token.size(), value);
  return r.ec == std::errc() && r.ptr == token.data() + token.size();
}

bool parse_double(std::string_view token, double& value) {
  token = strip_plus(token);
  if (token.empty()) return false;
  const auto r = std::from_chars(token.data(), token.data() + token.size(), value);
  if (r.ptr != token.data() + token.size()) return false;
  if (r.ec == std::errc::result_out_of_range) {
    // Overflow or underflow: from_chars leaves value unchanged. Treat as the limit, so that the
    // caller reports an infinite coordinate or accepts a denormal-range zero.
    const bool negative = token[0] == '-';
    const std::size_t e = token.find_first_of("eE");
    const bool tiny = e != std::string_view::npos && e + 1 < token.size() && token[e + 1] == '-';
    value = tiny ? (negative ? -0.0 : 0.0)
                 : (negative ? -std::numeric_limits<double>::infinity()
                             : std::numeric_limits<double>::infinity());
    return true;
  }
  return r.ec == std::errc();
}

}  // namespace tetcut::io_detail
