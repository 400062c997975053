#include "tetcut/render/colour.hpp"

#include <cmath>

namespace tetcut::render {
namespace {

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

std::uint8_t scale_channel(std::uint8_t channel, double factor) {
  const double v = std::round(channel * factor);
  if (!(v > 0.0)) return 0;  // also NaN
  return v >= 255.0 ? std::uint8_t{255} : static_cast<std::uint8_t>(v);
}

}  // namespace

std::optional<Rgb> parse_colour(std::string_view text) {
  if (text.size() != 7 || text[0] != '#') return std::nullopt;
  int channels[3];
  for (int i = 0; i < 3; ++i) {
    const int hi = hex_digit(text[1 + 2 * i]), lo = hex_digit(text[2 + 2 * i]);
    if (hi < 0 || lo < 0) return std::nullopt;
    channels[i] = hi * 16 + lo;
  }
  return Rgb{static_cast<std::uint8_t>(channels[0]), static_cast<std::uint8_t>(channels[1]),
             static_cast<std::uint8_t>(channels[2])};
}

std::string to_hex(Rgb colour) {
  static constexpr char kDigits[] = "0123456789abcdef";
  std::string out = "#";
  for (std::uint8_t c : {colour.r, colour.g, colour.b}) {
    out += kDigits[c >> 4];
    out += kDigits[c & 15];
  }
  return out;
}

Rgb scaled(Rgb colour, double factor) {
  return {scale_channel(colour.r, factor), scale_channel(colour.g, factor), scale_channel(colour.b, factor)};
}

}  // namespace tetcut::render
