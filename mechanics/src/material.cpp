#include "tetcut/mechanics/material.hpp"

#include <cmath>

namespace tetcut::mechanics {

Lame lame(const Material& m) {
  return {m.young * m.poisson / ((1.0 + m.poisson) * (1.0 - 2.0 * m.poisson)), m.young / (2.0 * (1.0 + m.poisson))};
}

double pressure_wave_speed(const Material& m) {
  const Lame l = lame(m);
  return std::sqrt((l.lambda + 2.0 * l.mu) / m.density);
}

std::optional<std::string> validate(const Material& m) {
  if (!std::isfinite(m.young) || m.young <= 0) return "Young's modulus must be positive and finite";
  if (!std::isfinite(m.poisson) || m.poisson <= -1.0 || m.poisson >= 0.5)
    return "Poisson ratio must lie in (-1, 0.5)";
  if (!std::isfinite(m.density) || m.density <= 0) return "density must be positive and finite";
  return std::nullopt;
}

}  // namespace tetcut::mechanics
