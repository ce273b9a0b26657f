#include "symbolic_analysis/term_pruning.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "symbolic/canonical_print.hpp"

namespace eomgen {

using GiNaC::ex;

namespace {

constexpr std::size_t max_terms = 400;   // per entry: beyond this, the entry is left whole
constexpr std::size_t max_samples = 40;  // rows of the trajectory at which terms are measured

std::vector<ex> terms_of(const ex& e) {
  ex x = e.expand();
  std::vector<ex> out;
  if (GiNaC::is_a<GiNaC::add>(x))
    for (std::size_t i = 0; i < x.nops(); ++i) out.push_back(x.op(i));
  else if (!x.is_zero())
    out.push_back(x);
  return out;
}

class TermMeter {
 public:
  TermMeter(const Equations& e, const std::vector<double>& parameters, const std::vector<double>& inputs,
            const std::vector<double>& times, const std::vector<std::vector<double>>& states) {
    const Symbols& s = e.symbols;
    std::size_t n = s.num_coordinates(), stride = std::max<std::size_t>(1, states.size() / max_samples);
    for (std::size_t k = 0; k < states.size(); k += stride) {
      GiNaC::exmap at{{s.time, times[k]}};
      for (std::size_t i = 0; i < s.parameters.size(); ++i) at[s.parameters[i]] = parameters[i];
      for (std::size_t i = 0; i < s.inputs.size(); ++i) at[s.inputs[i]] = inputs[i];
      for (std::size_t i = 0; i < n; ++i) at[s.coordinates[i]] = states[k][i], at[s.velocities[i]] = states[k][n + i];
      points_.push_back(at);
    }
  }

  // the largest |x| at the samples; infinite when x does not evaluate to a real number
  double largest(const ex& x) const {
    double out = 0;
    for (const GiNaC::exmap& at : points_) {
      ex v = GiNaC::evalf(x.subs(at));
      if (!GiNaC::is_a<GiNaC::numeric>(v) || !GiNaC::ex_to<GiNaC::numeric>(v).is_real()) return INFINITY;
      out = std::max(out, std::abs(GiNaC::ex_to<GiNaC::numeric>(v).to_double()));
    }
    return out;
  }

 private:
  std::vector<GiNaC::exmap> points_;
};

// the entry without its terms that stay below share · scale
ex pruned(const ex& entry, double scale, double share, const TermMeter& meter, const std::string& name,
          std::vector<std::string>& dropped) {
  std::vector<ex> terms = terms_of(entry);
  if (terms.size() > max_terms || (terms.size() < 2 && scale > 0)) return entry;
  ex out = 0;
  for (const ex& term : terms) {
    if (meter.largest(term) <= share * scale) dropped.push_back(fmt::format("{}: {}", name, canonical_text(term)));
    else out += term;
  }
  return out;
}

}  // namespace

Pruning prune_terms(const Equations& e, const std::vector<double>& parameters, const std::vector<double>& inputs,
                    const std::vector<double>& times, const std::vector<std::vector<double>>& states, double share) {
  Pruning out;
  out.equations = e;
  out.equations.solve_by_mass_matrix();
  if (e.method != "lagrange2" || e.has_multipliers || e.uses_pseudo_velocities()) {
    out.refusal = "terms are pruned in unconstrained Lagrange II models";
    return out;
  }
  TermMeter meter(e, parameters, inputs, times, states);
  std::size_t n = e.symbols.num_coordinates();
  double diagonal = 0;
  for (unsigned i = 0; i < n; ++i) diagonal = std::max(diagonal, meter.largest(e.mass_matrix(i, i)));
  Equations& p = out.equations;
  for (unsigned i = 0; i < n; ++i)
    for (unsigned j = i; j < n; ++j) {
      p.mass_matrix(i, j) = pruned(e.mass_matrix(i, j), diagonal, share, meter, fmt::format("M[{}][{}]", i, j), out.dropped);
      p.mass_matrix(j, i) = p.mass_matrix(i, j);
    }
  for (std::size_t i = 0; i < n; ++i)
    p.forcing[i] = pruned(e.forcing[i], meter.largest(e.forcing[i]), share, meter, fmt::format("f[{}]", i), out.dropped);
  if (out.dropped.empty()) out.refusal = "every term of M and f matters along the reference";
  p.model_name = e.model_name + "_pruned";
  p.title = e.title + " (pruned for a scene)";
  p.first_integrals.clear();
  p.has_linearization = false;
  return out;
}

}  // namespace eomgen
