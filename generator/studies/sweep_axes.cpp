/// @file The swept parameters of `eomgen sweep` (NAME=LOW:HIGH:COUNT[:log]) and the symbolic
/// stability margin drawn over its map.
#include <cmath>
#include <iostream>
#include <stdexcept>

#include <fmt/format.h>

#include "analyse/stability_map.hpp"
#include "studies/loaded_problem.hpp"
#include "studies/sweep_axes.hpp"
#include "symbolic/evaluate.hpp"
#include "symbolic_analysis/stability_conditions.hpp"

namespace eomgen::studies {

// "name=LO:HI:N" or "name=LO:HI:N:log"
std::optional<runtime::SweepAxis> parse_axis(const eomgen_model_abi& m, const std::string& full, std::string& name) {
  const std::string log_suffix = ":log";
  bool logarithmic = full.size() > log_suffix.size() && full.compare(full.size() - log_suffix.size(), log_suffix.size(), log_suffix) == 0;
  std::string text = logarithmic ? full.substr(0, full.size() - log_suffix.size()) : full;
  std::size_t eq = text.find('='), c1 = text.find(':', eq), c2 = text.find(':', c1 + 1);
  if (eq == std::string::npos || c1 == std::string::npos || c2 == std::string::npos) {
    std::cerr << fmt::format("eomgen: error: --param '{}': expected NAME=LOW:HIGH:COUNT or NAME=LOW:HIGH:COUNT:log, e.g. "
                             "--param b=0.1:2:200 or --param d=1e-9:1e3:121:log\n", full);
    return std::nullopt;
  }
  name = text.substr(0, eq);
  int index = index_of(m.parameter_names, m.num_parameters, name);
  if (index < 0) {
    std::cerr << fmt::format("eomgen: error: --param {}: not a parameter; {}\n", name,
                             suggest(name, std::vector<std::string>(m.parameter_names, m.parameter_names + m.num_parameters), "parameters"));
    return std::nullopt;
  }
  try {
    // every character of each field read: std::stoi("2e9") is 2, which ran two points silently
    auto whole = [](const std::string& field, auto read) {
      std::size_t used = 0;
      auto value = read(field, &used);
      if (used != field.size()) throw std::invalid_argument(field);
      return value;
    };
    auto real = [](const std::string& f, std::size_t* used) { return std::stod(f, used); };
    auto integer = [](const std::string& f, std::size_t* used) { return std::stol(f, used); };
    long count = whole(text.substr(c2 + 1), integer);
    if (count < 2 || count > 100000) throw std::invalid_argument("count");
    runtime::SweepAxis axis{index, whole(text.substr(eq + 1, c1 - eq - 1), real), whole(text.substr(c1 + 1, c2 - c1 - 1), real),
                            static_cast<int>(count), logarithmic};
    if (!(axis.high > axis.low) || (logarithmic && !(axis.low > 0))) throw std::invalid_argument("range");
    return axis;
  } catch (const std::exception&) {
    std::cerr << fmt::format("eomgen: error: --param '{}': need LOW < HIGH (numbers{}) and a whole COUNT with 2 <= COUNT <= "
                             "100000\n", full, logarithmic ? ", 0 < LOW for :log" : "");
    return std::nullopt;
  }
}

// > 0 where every symbolic condition holds: the smallest condition, scaled by its size
std::vector<double> symbolic_margin(const LoadedProblem& loaded, const runtime::StabilityMap& map,
                                    const std::string& x_name, const std::string& y_name, const std::vector<double>& state) {
  StabilityConditions c = stability_conditions(loaded.equations, {x_name, y_name}, loaded.problem.parameters,
                                               loaded.problem.inputs, state);
  const Symbols& s = loaded.equations.symbols;
  std::vector<double> margin(map.degree.size(), NAN);
  for (int j = 0; j < map.y.count; ++j)
    for (int i = 0; i < map.x.count; ++i) {
      std::size_t at = static_cast<std::size_t>(j) * map.x.count + i;
      const std::vector<double>& x = map.states[at].empty() ? state : map.states[at];
      auto value_of = [&](const GiNaC::symbol& y) -> double {
        if (y.get_name() == x_name) return map.x.value(i);
        if (y.get_name() == y_name) return map.y.value(j);
        for (std::size_t k = 0; k < s.coordinates.size(); ++k) {
          if (GiNaC::ex(y).is_equal(s.coordinates[k])) return x[k];
          if (GiNaC::ex(y).is_equal(s.velocities[k])) return x[s.coordinates.size() + k];
        }
        throw std::runtime_error("unexpected symbol " + y.get_name());
      };
      // a condition that vanishes identically holds nowhere strictly: at best marginal
      double smallest = c.vanishing.empty() ? INFINITY : 0.0;
      for (const GiNaC::ex& condition : c.conditions) smallest = std::min(smallest, evaluate(condition, value_of));
      margin[at] = smallest;
    }
  return margin;
}

}  // namespace eomgen::studies
