#include "symbolic_analysis/time_dependence.hpp"

#include <cmath>
#include <algorithm>
#include <numeric>

#include <fmt/format.h>

#include "symbolic/canonical_print.hpp"

namespace eomgen {

namespace {

using GiNaC::ex;

struct Search {
  const GiNaC::realsymbol& t;
  GiNaC::exmap values;
  std::vector<double> frequencies;
  std::vector<std::string> arguments;
  std::string not_periodic;
};

bool is_periodic_function(const ex& e) {
  return GiNaC::is_the_function<GiNaC::sin_SERIAL>(e) || GiNaC::is_the_function<GiNaC::cos_SERIAL>(e) || GiNaC::is_the_function<GiNaC::tan_SERIAL>(e);
}

// every occurrence of t must sit in sin/cos/tan(ω t + c) with a constant ω
void collect(const ex& e, Search& s) {
  if (!e.has(s.t) || !s.not_periodic.empty()) return;
  if (is_periodic_function(e)) {
    ex argument = e.op(0).expand();
    ex omega = argument.coeff(s.t, 1);
    if (argument.degree(s.t) == 1 && !omega.has(s.t) && !(argument - omega * s.t).expand().has(s.t)) {
      ex value = omega.subs(s.values).evalf();
      if (GiNaC::is_a<GiNaC::numeric>(value) && GiNaC::ex_to<GiNaC::numeric>(value).is_real()) {
        double w = std::abs(GiNaC::ex_to<GiNaC::numeric>(value).to_double());
        if (w > 0) {
          s.frequencies.push_back(GiNaC::is_the_function<GiNaC::tan_SERIAL>(e) ? 2 * w : w);  // tan has half the period
          std::string name = GiNaC::is_a<GiNaC::numeric>(omega) ? "" : canonical_text(omega) + " = ";
          s.arguments.push_back(name + fmt::format("{:.6g} rad/s", w));
          return;
        }
      }
    }
    s.not_periodic = "t appears in " + canonical_text(e) + ", whose argument is not w*t + c with a constant w";
    return;
  }
  if (e == s.t) {
    s.not_periodic = "t appears outside sin, cos and tan";
    return;
  }
  for (std::size_t i = 0; i < e.nops(); ++i) collect(e.op(i), s);
}

// the fundamental frequency of frequencies that are rational multiples of each other
std::optional<double> common_frequency(const std::vector<double>& w) {
  double smallest = *std::min_element(w.begin(), w.end());
  long denominator = 1;
  for (double x : w) {
    double ratio = x / smallest;
    long q = 1;
    for (; q <= 12; ++q)
      if (std::abs(ratio * q - std::round(ratio * q)) <= 1e-9 * ratio * q) break;
    if (q > 12) return std::nullopt;
    denominator = std::lcm(denominator, q);
  }
  return smallest / static_cast<double>(denominator);
}

}  // namespace

TimeDependence time_dependence(const Equations& e, const std::vector<double>& parameters) {
  Search s{e.symbols.time, {}, {}, {}, {}};
  for (std::size_t i = 0; i < e.symbols.parameters.size() && i < parameters.size(); ++i)
    s.values[e.symbols.parameters[i]] = parameters[i];
  std::vector<ex> all(e.forcing.begin(), e.forcing.end());
  for (unsigned i = 0; i < e.mass_matrix.rows(); ++i)
    for (unsigned j = 0; j < e.mass_matrix.cols(); ++j) all.push_back(e.mass_matrix(i, j));
  all.insert(all.end(), e.coordinate_rates.begin(), e.coordinate_rates.end());
  if (const MomentumSolve* momentum = e.momentum()) {
    all.insert(all.end(), momentum->bias.begin(), momentum->bias.end());
    for (unsigned i = 0; i < momentum->mass_matrix.rows(); ++i)
      for (unsigned j = 0; j < momentum->mass_matrix.cols(); ++j) all.push_back(momentum->mass_matrix(i, j));
  }
  TimeDependence out;
  for (const ex& x : all) {
    out.depends_on_time = out.depends_on_time || x.has(e.symbols.time);
    collect(x, s);
  }
  if (!out.depends_on_time) return out;
  if (!s.not_periodic.empty()) {
    out.not_periodic = s.not_periodic;
    return out;
  }
  std::sort(s.arguments.begin(), s.arguments.end());
  s.arguments.erase(std::unique(s.arguments.begin(), s.arguments.end()), s.arguments.end());
  for (const std::string& a : s.arguments) out.frequencies += (out.frequencies.empty() ? "" : ", ") + a;
  auto base = common_frequency(s.frequencies);
  if (!base) out.not_periodic = "the frequencies " + out.frequencies + " are not commensurate (the motion is quasi-periodic)";
  else out.period = 2 * M_PI / *base;
  return out;
}

}  // namespace eomgen
