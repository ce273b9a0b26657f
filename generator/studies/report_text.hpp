/// @file Numbers, matrices, polynomials and complex values as the reports of the
/// analysis commands print them: text for people, JSON for programs.
#pragma once

#include <complex>
#include <string>
#include <vector>

#include <Eigen/Dense>

namespace eomgen::studies {

/// 17 significant digits; "null" for a value that is not finite.
std::string json_number(double v);
std::string json_matrix(const Eigen::MatrixXd& A);
std::string json_strings(const std::vector<std::string>& v);
std::string json_numbers(const std::vector<double>& v);
/// "a + bi" with 6 digits, parts within rounding of zero dropped.
std::string complex_text(std::complex<double> z);
/// "  NAME =" and the rows, 6 digits.
std::string matrix_text(const char* name, const Eigen::MatrixXd& A);
/// "1 λ^2 + 0.5 λ + 4", highest power first.
std::string polynomial_text(const std::vector<double>& coefficients);

}  // namespace eomgen::studies
