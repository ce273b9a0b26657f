#include "symbolic_analysis/partial_fractions.hpp"

namespace eomgen {

using GiNaC::ex;

namespace {

// a polynomial in s by its coefficients, lowest power first, each a rational function of the other symbols
using Coefficients = std::vector<ex>;

Coefficients coefficients_of(const ex& p, const GiNaC::symbol& s) {
  ex e = p.expand();
  Coefficients c;
  for (int k = 0; k <= e.degree(s); ++k) c.push_back(e.coeff(s, k).normal());
  while (!c.empty() && c.back().is_zero()) c.pop_back();
  return c;
}

ex polynomial_of(const Coefficients& c, const GiNaC::symbol& s) {
  ex out = 0;
  for (std::size_t k = 0; k < c.size(); ++k) out += c[k] * GiNaC::pow(s, static_cast<int>(k));
  return out;
}

Coefficients trimmed(Coefficients c) {
  for (ex& x : c) x = x.normal();
  while (!c.empty() && c.back().is_zero()) c.pop_back();
  return c;
}

Coefficients minus(const Coefficients& a, const Coefficients& b) {
  Coefficients out(std::max(a.size(), b.size()), ex(0));
  for (std::size_t k = 0; k < a.size(); ++k) out[k] += a[k];
  for (std::size_t k = 0; k < b.size(); ++k) out[k] -= b[k];
  return trimmed(out);
}

Coefficients times(const Coefficients& a, const Coefficients& b) {
  if (a.empty() || b.empty()) return {};
  Coefficients out(a.size() + b.size() - 1, ex(0));
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j) out[i + j] += a[i] * b[j];
  return trimmed(out);
}

// long division a = q b + r, deg r < deg b (b ≠ 0)
void divide(const Coefficients& a, const Coefficients& b, Coefficients& q, Coefficients& r) {
  r = a;
  q.assign(a.size() >= b.size() ? a.size() - b.size() + 1 : 0, ex(0));
  while (r.size() >= b.size()) {
    std::size_t shift = r.size() - b.size();
    ex c = (r.back() / b.back()).normal();
    q[shift] = c;
    Coefficients step(shift, ex(0));
    for (const ex& x : b) step.push_back(c * x);
    Coefficients next = minus(r, step);
    if (next.size() >= r.size()) next.resize(r.size() - 1);  // the leading term cancels by construction
    r = trimmed(next);
  }
  q = trimmed(q);
}

// x with x·a ≡ 1 (mod m), a and m coprime (extended Euclid)
Coefficients inverse_modulo(const Coefficients& a, const Coefficients& m) {
  Coefficients r0 = m, r1 = a, s0 = {}, s1 = {ex(1)};
  while (r1.size() > 1) {
    Coefficients q, r;
    divide(r0, r1, q, r);
    Coefficients s = minus(s0, times(q, s1));
    r0 = r1, r1 = r, s0 = s1, s1 = s;
  }
  // r1 is a nonzero constant c: s1·a ≡ c
  for (ex& x : s1) x = (x / r1[0]).normal();
  Coefficients q, r;
  divide(s1, m, q, r);
  return r;
}

Coefficients power_of(const Coefficients& f, int k) {
  Coefficients out = {ex(1)};
  for (int i = 0; i < k; ++i) out = times(out, f);
  return out;
}

}  // namespace

std::vector<std::pair<ex, int>> factors_of(const ex& factored) {
  std::vector<std::pair<ex, int>> out;
  auto add = [&](const ex& e) {
    if (GiNaC::is_a<GiNaC::numeric>(e)) return;
    if (GiNaC::is_a<GiNaC::power>(e) && GiNaC::is_a<GiNaC::numeric>(e.op(1)))
      out.push_back({e.op(0), GiNaC::ex_to<GiNaC::numeric>(e.op(1)).to_int()});
    else
      out.push_back({e, 1});
  };
  if (GiNaC::is_a<GiNaC::mul>(factored))
    for (std::size_t i = 0; i < factored.nops(); ++i) add(factored.op(i));
  else
    add(factored);
  return out;
}

PartialFractions partial_fractions(const ex& rational_function, const GiNaC::symbol& s) {
  ex normal = rational_function.normal();
  Coefficients N = coefficients_of(normal.numer(), s), D = coefficients_of(normal.denom(), s);
  PartialFractions out;
  Coefficients polynomial, remainder;
  divide(N, D, polynomial, remainder);
  out.polynomial = polynomial_of(polynomial, s);
  if (remainder.empty()) return out;
  for (const auto& [base, power] : factors_of(GiNaC::factor(normal.denom()))) {
    if (!base.has(s)) continue;  // a factor of the parameters alone is part of D's leading coefficient
    Coefficients f = coefficients_of(base, s);
    for (ex& x : f) x = (x / f.back()).normal();
    Coefficients fm = power_of(f, power), cofactor, rest;
    divide(D, fm, cofactor, rest);
    // N/D = Σ A_i / f_i^m_i with A_i ≡ N · (D / f_i^m_i)⁻¹ (mod f_i^m_i)
    Coefficients q, A;
    divide(times(remainder, inverse_modulo(cofactor, fm)), fm, q, A);
    // the f-adic digits of A: A = Σ_k r_k f^k, so A / f^m = Σ_k r_k / f^(m−k)
    for (int k = 0; k < power && !A.empty(); ++k) {
      Coefficients next, digit;
      divide(A, f, next, digit);
      if (!digit.empty()) out.terms.push_back({polynomial_of(f, s), power - k, polynomial_of(digit, s)});
      A = next;
    }
  }
  return out;
}

}  // namespace eomgen
