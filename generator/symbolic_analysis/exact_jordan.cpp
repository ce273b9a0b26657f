#include "symbolic_analysis/exact_jordan.hpp"

#include <cmath>

#include "symbolic_analysis/exact_linear_system.hpp"
#include "symbolic_analysis/partial_fractions.hpp"

namespace eomgen {

using GiNaC::ex;

namespace {

GiNaC::matrix power_of(const GiNaC::matrix& A, int k) {
  GiNaC::matrix P = GiNaC::ex_to<GiNaC::matrix>(GiNaC::unit_matrix(A.rows()));
  for (int i = 0; i < k; ++i) P = P.mul(A);
  return P;
}

// f(A) by Horner's rule, f a polynomial in lambda with rational coefficients
GiNaC::matrix polynomial_of(const GiNaC::matrix& A, const ex& f, const GiNaC::symbol& lambda) {
  int degree = f.degree(lambda);
  unsigned n = A.rows();
  GiNaC::matrix result(n, n);
  for (int k = degree; k >= 0; --k) {
    result = result.mul(A);
    ex c = f.coeff(lambda, k);
    for (unsigned i = 0; i < n; ++i) result(i, i) += c;
  }
  return result;
}

}  // namespace

ExactJordan exact_jordan_structure(const Equations& e, const std::vector<double>& parameters,
                                   const std::vector<double>& inputs, const std::vector<double>& state) {
  ExactJordan out;
  ExactLinearSystem system = exact_linear_system(e, parameters, inputs, state, false);
  out.refusal = system.refusal;
  if (!out.refusal.empty()) return out;
  const GiNaC::matrix& A = system.A;
  std::size_t n = A.rows() / 2;
  ex characteristic = A.charpoly(out.lambda).expand();
  for (const auto& [f, multiplicity] : factors_of(GiNaC::factor(characteristic))) {
    ExactFactor factor;
    factor.degree = f.degree(out.lambda);
    factor.polynomial = (f / f.lcoeff(out.lambda)).expand();
    factor.multiplicity = multiplicity;
    GiNaC::matrix fA = polynomial_of(A, factor.polynomial, out.lambda);
    // nullity_k / degree = Σ_blocks min(size, k); blocks of size ≥ k = (nullity_k − nullity_{k−1}) / degree
    std::vector<int> at_least{0};
    int previous = 0;
    for (int k = 1; k <= multiplicity; ++k) {
      int nullity = static_cast<int>(2 * n) - static_cast<int>(power_of(fA, k).rank());
      at_least.push_back((nullity - previous) / factor.degree);
      previous = nullity;
    }
    at_least.push_back(0);
    for (int k = multiplicity; k >= 1; --k)
      for (int b = 0; b < at_least[k] - at_least[k + 1]; ++b) factor.jordan_blocks.push_back(k);
    out.factors.push_back(factor);
  }
  return out;
}

const ExactFactor* factor_of(const ExactJordan& exact, std::complex<double> z) {
  const ExactFactor* best = nullptr;
  double smallest = 1e-6;
  for (const ExactFactor& f : exact.factors) {
    std::complex<double> sum = 0;
    double size = 0;
    for (int k = 0; k <= f.degree; ++k) {
      double c = GiNaC::ex_to<GiNaC::numeric>(f.polynomial.coeff(exact.lambda, k)).to_double();
      sum += c * std::pow(z, k), size += std::abs(c * std::pow(z, k));
    }
    if (double r = std::abs(sum) / std::max(size, 1e-300); r <= smallest) smallest = r, best = &f;
  }
  return best;
}

}  // namespace eomgen
