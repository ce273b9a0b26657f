#include "derive/state_values.hpp"

#include <cmath>
#include <limits>

#include "symbolic/evaluate.hpp"

namespace eomgen {

StateValues::StateValues(const Symbols& s, const std::vector<Intermediate>& intermediates, const std::vector<double>& coordinates,
                         const std::vector<double>& velocities, const std::vector<double>& inputs, double time) {
  for (std::size_t i = 0; i < s.coordinates.size() && i < coordinates.size(); ++i) known_[s.coordinates[i]] = coordinates[i];
  for (std::size_t i = 0; i < s.velocities.size() && i < velocities.size(); ++i) known_[s.velocities[i]] = velocities[i];
  for (std::size_t i = 0; i < s.parameters.size(); ++i) known_[s.parameters[i]] = s.parameter_defaults[i];
  for (std::size_t i = 0; i < s.inputs.size() && i < inputs.size(); ++i) known_[s.inputs[i]] = inputs[i];
  known_[s.time] = time;
  for (const Intermediate& i : intermediates) definitions_.emplace(i.symbol, i.definition);
}

StateValues StateValues::initial(const Symbols& s, const std::vector<Intermediate>& intermediates) {
  return StateValues(s, intermediates, s.initial_coordinates, s.initial_velocities, s.input_defaults, 0);
}

StateValues StateValues::spread(const Symbols& s, const std::vector<Intermediate>& intermediates, int seed) {
  auto spread = [&](std::size_t count, std::size_t from, double scale) {
    std::vector<double> x(count);
    for (std::size_t i = 0; i < count; ++i) x[i] = scale * std::sin(1.3 + 0.71 * double(i + from) + 2.9 * seed);
    return x;
  };
  return StateValues(s, intermediates, spread(s.coordinates.size(), 0, 1.1), spread(s.velocities.size(), 50, 1.7),
                     std::vector<double>(s.inputs.size(), 0.0), 0.37 + seed);
}

double StateValues::operator()(const GiNaC::ex& x) const {
  return evaluate(x, [&](const GiNaC::symbol& y) { return value_of(y); });
}

double StateValues::value_of(const GiNaC::symbol& y) const {
  if (auto found = known_.find(y); found != known_.end()) return found->second;
  auto definition = definitions_.find(y);
  if (definition == definitions_.end()) return std::numeric_limits<double>::quiet_NaN();
  double value = (*this)(definition->second);
  known_[y] = value;
  return value;
}

}  // namespace eomgen
