#include "studies/ensemble_options.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <regex>

#include <fmt/format.h>

#include "studies/loaded_problem.hpp"
#include "common/diagnostic.hpp"

namespace eomgen::studies {

namespace {

std::string trim(const std::string& s) {
  std::size_t a = s.find_first_not_of(" \t"), b = s.find_last_not_of(" \t");
  return a == std::string::npos ? "" : s.substr(a, b - a + 1);
}

bool parse_number(const std::string& text, double& out) {
  try {
    std::size_t used = 0;
    out = std::stod(trim(text), &used);
    return used == trim(text).size() && std::isfinite(out);
  } catch (const std::exception&) {
    return false;
  }
}

std::optional<runtime::Distribution> parse_distribution(const std::string& text, const std::string& whole) {
  static const std::regex form(R"(\s*(normal|uniform|lognormal)\s*\(([^,()]*),([^,()]*)\)\s*)");
  std::smatch match;
  runtime::Distribution d;
  if (!std::regex_match(text, match, form) || !parse_number(match[2], d.a) || !parse_number(match[3], d.b)) {
    std::cerr << fmt::format("eomgen: error: --vary '{}': expected NAME=normal(MEAN,SD), NAME=uniform(LOW,HIGH) or "
                             "NAME=lognormal(MU,SIGMA) with numbers, e.g. --vary 'm=normal(1,0.05)'\n",
                             whole);
    return std::nullopt;
  }
  d.kind = match[1] == "normal"    ? runtime::Distribution::Kind::normal
           : match[1] == "uniform" ? runtime::Distribution::Kind::uniform
                                   : runtime::Distribution::Kind::lognormal;
  bool uniform = d.kind == runtime::Distribution::Kind::uniform;
  if (uniform ? !(d.b > d.a) : !(d.b >= 0)) {
    std::cerr << fmt::format("eomgen: error: --vary '{}': {}\n", whole,
                             uniform ? "uniform(LOW,HIGH) needs LOW < HIGH" : "the spread (the second number) must be >= 0");
    return std::nullopt;
  }
  return d;
}

}  // namespace

std::optional<runtime::Variation> parse_variation(const eomgen_model_abi& m, const std::string& text) {
  std::size_t eq = text.find('=');
  if (eq == std::string::npos) {
    std::cerr << fmt::format("eomgen: error: --vary '{}': expected NAME=DISTRIBUTION, e.g. --vary 'm=normal(1,0.05)'\n", text);
    return std::nullopt;
  }
  runtime::Variation v;
  v.name = trim(text.substr(0, eq));
  auto d = parse_distribution(text.substr(eq + 1), text);
  if (!d) return std::nullopt;
  v.distribution = *d;
  if (int i = index_of(m.parameter_names, m.num_parameters, v.name); i >= 0) {
    v.target = runtime::Variation::Target::parameter, v.index = i;
  } else if (int j = index_of(m.input_names, m.num_inputs, v.name); j >= 0) {
    v.target = runtime::Variation::Target::input, v.index = j;
  } else if (int k = state_index(m, v.name); k >= 0) {
    v.target = runtime::Variation::Target::state, v.index = k;
  } else {
    std::vector<std::string> names(m.parameter_names, m.parameter_names + m.num_parameters);
    names.insert(names.end(), m.input_names, m.input_names + m.num_inputs);
    names.insert(names.end(), m.state_names, m.state_names + m.num_states);
    std::cerr << fmt::format("eomgen: error: --vary {}: not a parameter, input or initial value of {}; {}\n", v.name, m.name,
                             suggest(v.name, names, "names"));
    return std::nullopt;
  }
  return v;
}

std::vector<std::string> recordable_signals(const eomgen_model_abi& m) {
  std::vector<std::string> names(m.state_names, m.state_names + m.num_states);
  names.insert(names.end(), m.output_names, m.output_names + m.num_outputs);
  names.push_back("energy");
  return names;
}

bool check_signal(const eomgen_model_abi& m, const std::string& name, const char* flag) {
  std::vector<std::string> names = recordable_signals(m);
  if (std::find(names.begin(), names.end(), name) != names.end()) return true;
  std::cerr << fmt::format("eomgen: error: {} {}: not a state, output or energy of {}; {}\n", flag, name, m.name,
                           suggest(name, names, "signals"));
  return false;
}

std::optional<runtime::Measure> parse_measure(const eomgen_model_abi& m, const std::string& text) {
  static const std::regex form(R"(\s*([a-z]+)\s*\(\s*(.+?)\s*\)\s*)");
  std::smatch match;
  runtime::Measure measure;
  if (!std::regex_match(text, match, form) || !runtime::measure_kind(match[1], measure.kind)) {
    std::cerr << fmt::format("eomgen: error: --measure '{}': expected final(SIGNAL), max(SIGNAL), min(SIGNAL), "
                             "mean(SIGNAL) or period(SIGNAL), e.g. --measure 'period(phi)'\n",
                             text);
    return std::nullopt;
  }
  measure.signal = match[2];
  if (!check_signal(m, measure.signal, "--measure")) return std::nullopt;
  return measure;
}

std::optional<std::vector<double>> parse_probabilities(const std::string& text) {
  std::vector<double> out;
  std::size_t start = 0;
  while (start <= text.size()) {
    std::size_t comma = std::min(text.find(',', start), text.size());
    double p = 0;
    if (!parse_number(text.substr(start, comma - start), p) || p < 0 || p > 1) {
      std::cerr << fmt::format("eomgen: error: --quantiles '{}': expected probabilities in [0, 1] separated by commas, "
                               "e.g. --quantiles 0.05,0.5,0.95\n",
                               text);
      return std::nullopt;
    }
    out.push_back(p);
    start = comma + 1;
  }
  return out;
}

}  // namespace eomgen::studies
