#include "symbolic_analysis/closed_form_solution.hpp"

#include <algorithm>
#include <optional>

#include <fmt/format.h>

#include "symbolic_analysis/partial_fractions.hpp"
#include "symbolic/canonical_print.hpp"

namespace eomgen {

using GiNaC::ex;

namespace {

// adj(sI − A) = Σ_k M_k s^(n−k) and det(sI − A) by Faddeev–LeVerrier, exact
struct Resolvent {
  GiNaC::matrix adjugate;
  ex characteristic;
};

Resolvent resolvent_of(const GiNaC::matrix& A, const GiNaC::symbol& s) {
  unsigned n = A.rows();
  GiNaC::matrix Mk(n, n), adjugate(n, n);
  ex c = 1, characteristic = GiNaC::pow(s, static_cast<int>(n));
  for (unsigned k = 1; k <= n; ++k) {
    Mk = A.mul(Mk);
    for (unsigned i = 0; i < n; ++i) Mk(i, i) += c;
    for (unsigned i = 0; i < n; ++i)
      for (unsigned j = 0; j < n; ++j) Mk(i, j) = Mk(i, j).normal(), adjugate(i, j) += Mk(i, j) * GiNaC::pow(s, static_cast<int>(n - k));
    c = (-A.mul(Mk).trace() / static_cast<int>(k)).normal();
    characteristic += c * GiNaC::pow(s, static_cast<int>(n - k));
  }
  return {adjugate, characteristic};
}

// L⁻¹{1/Q^k} and L⁻¹{s/Q^k} for Q = s² + w2, by d/ds(s/Q^k) = (1 − 2k)/Q^k + 2k w2/Q^(k+1)
// and L⁻¹{F'} = −t f(t)
struct QuadraticTransforms {
  std::vector<ex> one, s;  // index k − 1
};

QuadraticTransforms quadratic_transforms(const ex& w2, bool oscillating, int up_to, const GiNaC::symbol& t) {
  QuadraticTransforms out;
  ex w = GiNaC::sqrt(oscillating ? w2 : -w2);
  out.one.push_back(oscillating ? GiNaC::sin(w * t) / w : GiNaC::sinh(w * t) / w);
  out.s.push_back(oscillating ? GiNaC::cos(w * t) : GiNaC::cosh(w * t));
  for (int k = 1; k < up_to; ++k) {
    out.one.push_back(((2 * k - 1) * out.one[k - 1] - t * out.s[k - 1]) / (2 * k * w2));
    out.s.push_back(t * out.one[k - 1] / (2 * k));
  }
  return out;
}

class InverseLaplace {
 public:
  InverseLaplace(const GiNaC::symbol& s, const GiNaC::symbol& t, const GiNaC::exmap& values) : s_(s), t_(t), values_(values) {}

  // the inverse transform of a proper rational function in s, or the reason there is none
  std::optional<ex> of(const ex& rational, std::string& refusal, std::vector<std::string>& conditions) const {
    PartialFractions parts = partial_fractions(rational, s_);
    ex out = 0;
    for (const PartialFraction& term : parts.terms) {
      int degree = term.factor.degree(s_);
      if (degree == 1) {
        ex a = -term.factor.coeff(s_, 0);
        out += term.numerator * GiNaC::pow(t_, term.power - 1) / GiNaC::factorial(term.power - 1) * GiNaC::exp(a * t_);
        continue;
      }
      if (degree > 2) {
        std::string factor = canonical_text(term.factor);
        refusal = fmt::format("the characteristic polynomial has {} of degree {} in s, whose roots have no closed form here",
                              factor.size() <= 80 ? "the factor " + factor : "a factor", degree);
        return std::nullopt;
      }
      // f = (s − α)² + w2, r = p s + q = p (s − α) + (q + p α)
      ex alpha = (-term.factor.coeff(s_, 1) / 2).normal(), w2 = (term.factor.coeff(s_, 0) - alpha * alpha).normal();
      w2 = GiNaC::factor(w2.numer()) / GiNaC::factor(w2.denom());  // sqrt(g*(m + mc)/(l*mc)), not of a sum of fractions
      ex sign = w2.subs(values_).normal();
      ex p = term.numerator.coeff(s_, 1), q = term.numerator.coeff(s_, 0);
      if (sign.is_zero()) {
        // a double root at the model's values (critical damping): f = (s − α)², so
        // L⁻¹{(p (s − α) + q + p α)/(s − α)^(2k)} = e^(αt) (p t^(2k−2)/(2k−2)! + (q + p α) t^(2k−1)/(2k−1)!),
        // the Jordan form's t e^(αt), valid where w2 = 0 (the sinh or sin form is 0/0 there)
        note(conditions, canonical_text(w2) + " = 0");
        int m = 2 * term.power;
        out += GiNaC::exp(alpha * t_) * (p * GiNaC::pow(t_, m - 2) / GiNaC::factorial(m - 2) +
                                         (q + p * alpha).normal() * GiNaC::pow(t_, m - 1) / GiNaC::factorial(m - 1));
        continue;
      }
      bool oscillating = sign.info(GiNaC::info_flags::positive);
      bool decided = w2.info(GiNaC::info_flags::positive) || (-w2).info(GiNaC::info_flags::positive);
      if (!decided) note(conditions, canonical_text(w2) + (oscillating ? " > 0" : " < 0"));
      QuadraticTransforms h = quadratic_transforms(w2, oscillating, term.power, t_);
      out += GiNaC::exp(alpha * t_) * (p * h.s[term.power - 1] + (q + p * alpha).normal() * h.one[term.power - 1]);
    }
    return tidy(out);
  }

 private:
  static void note(std::vector<std::string>& conditions, const std::string& c) {
    if (std::find(conditions.begin(), conditions.end(), c) == conditions.end()) conditions.push_back(c);
  }

  // each time function's coefficient in lowest terms: (4 - 3 cos(n t)), not a sum of fractions
  ex tidy(const ex& e) const {
    ex expanded = e.expand();
    GiNaC::exset functions;
    expanded.find(GiNaC::sin(GiNaC::wild()), functions);
    expanded.find(GiNaC::cos(GiNaC::wild()), functions);
    expanded.find(GiNaC::sinh(GiNaC::wild()), functions);
    expanded.find(GiNaC::cosh(GiNaC::wild()), functions);
    expanded.find(GiNaC::exp(GiNaC::wild()), functions);
    GiNaC::lst atoms{t_};
    for (const ex& f : functions) atoms.append(f);
    ex collected = GiNaC::collect(expanded, atoms, true);
    if (!GiNaC::is_a<GiNaC::add>(collected)) return collected;
    ex out = 0;
    for (std::size_t i = 0; i < collected.nops(); ++i) {
      ex term = collected.op(i), coefficient = 1, atom = 1;
      auto split = [&](const ex& factor) { (factor.has(t_) ? atom : coefficient) *= factor; };
      if (GiNaC::is_a<GiNaC::mul>(term))
        for (std::size_t k = 0; k < term.nops(); ++k) split(term.op(k));
      else
        split(term);
      out += coefficient.normal() * atom;
    }
    return out;
  }

  const GiNaC::symbol &s_, &t_;
  const GiNaC::exmap& values_;
};

}  // namespace

ClosedFormSolution closed_form_solution(const GiNaC::matrix& A, const GiNaC::matrix& B, const GiNaC::matrix& C,
                                        const GiNaC::matrix& D, const GiNaC::exmap& values) {
  ClosedFormSolution out;
  unsigned n = A.rows();
  Resolvent R = resolvent_of(A, out.s);
  InverseLaplace inverse(out.s, out.t, values);
  out.fundamental = GiNaC::matrix(n, n);
  for (unsigned i = 0; i < n; ++i)
    for (unsigned j = 0; j < n; ++j) {
      auto entry = inverse.of(R.adjugate(i, j) / R.characteristic, out.refusal, out.conditions);
      if (!entry) return out;
      out.fundamental(i, j) = *entry;
    }
  bool with_io = B.cols() > 0 && C.rows() > 0 && B.rows() == n && C.cols() == n;
  if (with_io) {
    GiNaC::matrix G = C.mul(R.adjugate).mul(B);
    out.transfer = GiNaC::matrix(C.rows(), B.cols());
    for (unsigned i = 0; i < C.rows(); ++i)
      for (unsigned j = 0; j < B.cols(); ++j) {
        ex g = (G(i, j) / R.characteristic + D(i, j)).normal();
        out.transfer(i, j) = GiNaC::factor(g.numer()) / GiNaC::factor(g.denom());
      }
  }
  return out;
}

}  // namespace eomgen
