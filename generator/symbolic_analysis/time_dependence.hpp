/// @file Explicit time dependence of derived equations (rheonomic systems, driven
/// supports): whether t appears in M, f or the kinematic equations, and whether it
/// appears only through sin, cos or tan of ω·t + c with commensurate frequencies, in
/// which case the equations are periodic and Floquet theory applies.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "derive/equations.hpp"

namespace eomgen {

struct TimeDependence {
  bool depends_on_time = false;
  std::optional<double> period;  // the least common period, when periodic
  std::string frequencies;       // "w = 100 rad/s" as found
  std::string not_periodic;      // why no period was found
};

/// With `parameters` in parameter_names order giving the frequencies their values.
TimeDependence time_dependence(const Equations& e, const std::vector<double>& parameters);

}  // namespace eomgen
