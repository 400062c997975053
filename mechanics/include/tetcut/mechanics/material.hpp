// A linear-elastic material, in SI units, and what the explicit integrator needs from it.
//
// The default is liver-like: Young's modulus 3 kPa, Poisson ratio 0.45 (nearly incompressible
// soft tissue), density 1,000 kg/m3 (the order of magnitude in the hepatectomy simulators the
// paper's model comes from, Cotin, Delingette and Ayache 2000).
#pragma once

#include <optional>
#include <string>

namespace tetcut::mechanics {

struct Material {
  double young = 3000.0;    // Pa
  double poisson = 0.45;    // in (-1, 0.5)
  double density = 1000.0;  // kg / m3
};

struct Lame {
  double lambda = 0.0, mu = 0.0;  // Pa
};

[[nodiscard]] Lame lame(const Material& material);
// sqrt((lambda + 2 mu) / rho): the fastest (pressure) wave, which bounds the explicit step.
[[nodiscard]] double pressure_wave_speed(const Material& material);
// A message naming the parameter when one is non-finite or out of range.
[[nodiscard]] std::optional<std::string> validate(const Material& material);

}  // namespace tetcut::mechanics
