/// @file Small model files that more than one test writes: each a system whose motion is
/// known in closed form.
#pragma once

#include <string>

#include <fmt/format.h>

namespace eomgen::test {

/// A particle of mass m moving along x from x0 at speed v0: `parameters` are the lines of
/// [parameters] (m among them), `energy` the lines of [energy].
inline std::string particle_on_a_line_model(const std::string& name, const std::string& parameters,
                                            const std::string& energy, double x0 = 0, double v0 = 0) {
  return fmt::format(R"toml([model]
name = "{}"
[parameters]
{}[coordinates]
x = {{ initial = {:.17g}, rate = {:.17g} }}
[[particles]]
name = "mass"
mass = "m"
position = ["x", "0", "0"]
[energy]
{})toml",
                     name, parameters, x0, v0, energy);
}

/// m x'' = −k x: a mass on a spring along x, released from x0 at speed v0; x(t) = x0 cos(ω t) +
/// v0/ω sin(ω t), ω² = k/m.
inline std::string spring_mass_model(const std::string& name, double m, double k, double x0, double v0 = 0) {
  return particle_on_a_line_model(name, fmt::format("m = {:.17g}\nk = {:.17g}\n", m, k), "potential = \"k*x^2/2\"\n", x0, v0);
}

/// models/car_braking.toml's parameters on the time scale T (s), as `--set` flags: its axles'
/// stiffnesses and g over T², their dampings over T, so that every rate is its own over T.
struct BrakingCar {
  double m = 1500, Iyy = 2400, h = 0.55, kf = 40000, kr = 44000, cf = 4000, cr = 4400, g = 9.81;
  std::string on_time_scale(double T) const {
    return fmt::format("--set kf={:.17g} --set kr={:.17g} --set cf={:.17g} --set cr={:.17g} --set g={:.17g}", kf / (T * T),
                       kr / (T * T), cf / T, cr / T, g / (T * T));
  }
};

/// m x'' = F: a free mass pushed by the input force F (m = 2).
inline const char* const pushed_mass_model = R"toml(
[model]
name = "pushed_mass"
title = "a free mass pushed by an input force"
[parameters]
m = 2.0
[inputs]
F = 0.0
[coordinates]
x = 0.0
[[particles]]
name = "body"
mass = "m"
position = ["x", "0", "0"]
[[forces]]
at = ["x", "0", "0"]
force = ["F", "0", "0"]
)toml";

}  // namespace eomgen::test
