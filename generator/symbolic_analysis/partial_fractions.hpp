/// @file Partial fractions of a rational function N(s)/D(s) whose coefficients are
/// rational numbers or rational functions of other symbols (the parameters): over the
/// irreducible factors f of D, N/D = polynomial + Σ r_k(s) / f^k with deg r_k < deg f.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include <ginac/ginac.h>

namespace eomgen {

/// The factors of a product as (base, exponent), numbers left out: 3 (s+1)^2 s → (s+1, 2), (s, 1).
std::vector<std::pair<GiNaC::ex, int>> factors_of(const GiNaC::ex& factored);

struct PartialFraction {
  GiNaC::ex factor;     // f(s), monic and irreducible over the rationals (in the other symbols)
  int power = 1;        // k
  GiNaC::ex numerator;  // r(s), deg r < deg f
};

struct PartialFractions {
  GiNaC::ex polynomial;  // the part of N/D that is a polynomial in s
  std::vector<PartialFraction> terms;
};

/// N/D split over the factors of D (factored by GiNaC over the rationals).
PartialFractions partial_fractions(const GiNaC::ex& rational_function, const GiNaC::symbol& s);

}  // namespace eomgen
