/// @file Small model files that more than one test writes: each a system whose motion is
/// known in closed form.
#pragma once

namespace eomgen::test {

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
