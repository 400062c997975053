// Colours as the pictures take them ("#rrggbb") and as shading computes them (0..255 channels).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace tetcut::render {

struct Rgb {
  std::uint8_t r = 0, g = 0, b = 0;
  bool operator==(const Rgb&) const = default;
};

// "#rrggbb" (hex digits in either case), or nullopt for anything else.
std::optional<Rgb> parse_colour(std::string_view text);

// "#rrggbb" in lower case.
std::string to_hex(Rgb colour);

// Each channel multiplied by `factor` (>= 0), rounded to nearest and clamped to 255.
Rgb scaled(Rgb colour, double factor);

}  // namespace tetcut::render
