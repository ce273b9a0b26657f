#include "analyse/exact_jordan.hpp"

#include <cstdlib>
#include <optional>

#include <fmt/format.h>

#include "symbolic/canonical_print.hpp"

namespace eomgen {

using GiNaC::ex;

namespace {

// the decimal a double was written as, exactly: 0.1 → 1/10 (shortest round-trip digits)
std::optional<GiNaC::numeric> exact_decimal(double v) {
  std::string s = fmt::format("{}", v);
  if (s.find_first_of("eEn") != std::string::npos) return std::nullopt;  // exponents, inf, nan
  bool negative = s[0] == '-';
  if (negative) s = s.substr(1);
  std::size_t dot = s.find('.');
  std::string digits = dot == std::string::npos ? s : s.substr(0, dot) + s.substr(dot + 1);
  std::size_t decimals = dot == std::string::npos ? 0 : s.size() - dot - 1;
  if (digits.size() > 17) return std::nullopt;
  GiNaC::numeric value(digits.c_str());
  value = value / GiNaC::pow(GiNaC::numeric(10), GiNaC::numeric(static_cast<long>(decimals)));
  return negative ? -value : value;
}

// the matrix with every entry at the point, or the name of the first entry that is not rational
std::optional<GiNaC::matrix> rational_at(const GiNaC::matrix& X, const GiNaC::exmap& point, const char* name,
                                         std::string& refusal) {
  GiNaC::matrix out(X.rows(), X.cols());
  for (unsigned i = 0; i < X.rows(); ++i)
    for (unsigned j = 0; j < X.cols(); ++j) {
      ex v = X(i, j).subs(point).normal();
      if (!GiNaC::is_a<GiNaC::numeric>(v) || !GiNaC::ex_to<GiNaC::numeric>(v).is_rational()) {
        refusal = fmt::format("{}[{}][{}] = {} is not rational at this state", name, i, j, canonical_text(v));
        return std::nullopt;
      }
      out(i, j) = v;
    }
  return out;
}

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

std::vector<std::pair<ex, int>> factors_of(const ex& factored) {
  std::vector<std::pair<ex, int>> out;
  auto add = [&](const ex& e) {
    if (GiNaC::is_a<GiNaC::numeric>(e)) return;
    if (GiNaC::is_a<GiNaC::power>(e)) out.push_back({e.op(0), GiNaC::ex_to<GiNaC::numeric>(e.op(1)).to_int()});
    else out.push_back({e, 1});
  };
  if (GiNaC::is_a<GiNaC::mul>(factored))
    for (std::size_t i = 0; i < factored.nops(); ++i) add(factored.op(i));
  else
    add(factored);
  return out;
}

}  // namespace

ExactJordan exact_jordan_structure(const Equations& e, const std::vector<double>& parameters,
                                   const std::vector<double>& inputs, const std::vector<double>& state) {
  ExactJordan out;
  const Symbols& s = e.symbols;
  std::size_t n = s.num_coordinates();
  if (e.uses_pseudo_velocities() || e.has_multipliers || e.method == "routh" || n > 6) {
    out.refusal = "exact arithmetic is used for Lagrange II models of up to six coordinates";
    return out;
  }
  GiNaC::exmap point;
  point[s.time] = 0;
  auto exact = [&](const GiNaC::realsymbol& x, double v, const std::string& name) {
    auto r = exact_decimal(v);
    if (!r) out.refusal = fmt::format("{} = {} has no exact decimal value", name, v);
    else point[x] = *r;
  };
  for (std::size_t i = 0; i < s.parameters.size(); ++i) exact(s.parameters[i], parameters[i], s.parameter_names[i]);
  for (std::size_t i = 0; i < s.inputs.size(); ++i) exact(s.inputs[i], inputs[i], s.input_names[i]);
  for (std::size_t i = 0; i < n; ++i) {
    exact(s.coordinates[i], state[i], s.coordinate_names[i]);
    exact(s.velocities[i], state[n + i], s.velocities[i].get_name());
  }
  if (!out.refusal.empty()) return out;
  Equations linear = e;
  if (!linear.has_linearization) add_linearization(linear);
  auto M = rational_at(e.mass_matrix, point, "M", out.refusal);
  auto P = M ? rational_at(linear.linear_damping_gyroscopic, point, "P", out.refusal) : std::nullopt;
  auto Q = P ? rational_at(linear.linear_stiffness_circulatory, point, "Q", out.refusal) : std::nullopt;
  if (!Q) return out;
  GiNaC::matrix Minv = M->inverse(), lowerQ = Minv.mul(*Q).mul_scalar(-1), lowerP = Minv.mul(*P).mul_scalar(-1);
  GiNaC::matrix A(2 * n, 2 * n);
  for (unsigned i = 0; i < n; ++i) {
    A(i, n + i) = 1;
    for (unsigned j = 0; j < n; ++j) A(n + i, j) = lowerQ(i, j), A(n + i, n + j) = lowerP(i, j);
  }
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
