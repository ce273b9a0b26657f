#include "studies/report_text.hpp"

#include <cmath>
#include <sstream>

#include <fmt/format.h>

#include "studies/exit_status.hpp"
#include "emit/formats.hpp"

namespace eomgen::studies {

std::string json_number(double v) { return std::isfinite(v) ? fmt::format("{:.17g}", v + 0.0) : "null"; }

std::string json_matrix(const Eigen::MatrixXd& A) {
  std::string out = "[";
  for (Eigen::Index i = 0; i < A.rows(); ++i) {
    out += i ? ", [" : "[";
    for (Eigen::Index j = 0; j < A.cols(); ++j) out += (j ? ", " : "") + json_number(A(i, j));
    out += "]";
  }
  return out + "]";
}

std::string json_strings(const std::vector<std::string>& v) {
  std::string out;
  for (const std::string& s : v) out += (out.empty() ? "" : ", ") + json_quoted(s);
  return "[" + out + "]";
}

std::string json_numbers(const std::vector<double>& v) {
  std::string out;
  for (double x : v) out += (out.empty() ? "" : ", ") + json_number(x);
  return "[" + out + "]";
}

std::string complex_text(std::complex<double> z) {
  z += std::complex<double>(0.0, 0.0);  // no "-0"
  if (std::abs(z.real()) <= 1e-12 * std::abs(z)) z.real(0.0);  // on the axis within rounding
  if (std::abs(z.imag()) <= 1e-12 * std::abs(z)) z.imag(0.0);
  if (std::abs(z.imag()) < 1e-300) return fmt::format("{:.6g}", z.real());
  return fmt::format("{:.6g} {} {:.6g}i", z.real(), z.imag() < 0 ? "-" : "+", std::abs(z.imag()));
}

std::string matrix_text(const char* name, const Eigen::MatrixXd& A) {
  std::ostringstream s;
  s << "  " << name << " =\n";
  for (Eigen::Index i = 0; i < A.rows(); ++i) {
    s << "   ";
    for (Eigen::Index j = 0; j < A.cols(); ++j) s << fmt::format(" {:>12.6g}", A(i, j) + 0.0);
    s << "\n";
  }
  return s.str();
}

std::string polynomial_text(const std::vector<double>& c) {
  std::string out;
  int n = static_cast<int>(c.size()) - 1;
  for (int k = 0; k <= n; ++k) {
    int power = n - k;
    std::string term = fmt::format("{:.6g}", std::abs(c[k])) + (power > 1 ? fmt::format(" λ^{}", power) : power == 1 ? " λ" : "");
    out += out.empty() ? (c[k] < 0 ? "-" + term : term) : (c[k] < 0 ? " - " : " + ") + term;
  }
  return out;
}


}  // namespace eomgen::studies
