/// @file The quantities of a recursion written out as intermediates: each value that is not
/// already a number or a symbol gets a symbol of its own, defined by the value, so that the
/// generated code computes it once and the next step of the recursion stays a short expression.
#pragma once

#include <string>
#include <vector>

#include <fmt/format.h>

#include "model/model.hpp"

namespace eomgen {

class RecursionQuantities {
 public:
  explicit RecursionQuantities(std::vector<Intermediate>& written) : written_(written) {}

  GiNaC::ex operator()(const GiNaC::ex& value, const std::string& cpp_name) {
    if (GiNaC::is_a<GiNaC::numeric>(value) || GiNaC::is_a<GiNaC::symbol>(value)) return value;
    GiNaC::symbol s(cpp_name);
    written_.push_back({s, value, cpp_name});
    return s;
  }

  /// components named prefix0, prefix1, prefix2
  Vector3 operator()(const Vector3& v, const std::string& prefix) {
    return {(*this)(v[0], prefix + "0"), (*this)(v[1], prefix + "1"), (*this)(v[2], prefix + "2")};
  }

  /// entries named prefix<row><column>; a symmetric matrix names its upper triangle only
  GiNaC::matrix operator()(const GiNaC::matrix& m, const std::string& prefix, bool symmetric) {
    GiNaC::matrix r(m.rows(), m.cols());
    for (unsigned a = 0; a < m.rows(); ++a)
      for (unsigned b = 0; b < m.cols(); ++b)
        r(a, b) = symmetric && b < a ? r(b, a) : (*this)(m(a, b), fmt::format("{}{}{}", prefix, a, b));
    return r;
  }

 private:
  std::vector<Intermediate>& written_;
};

}  // namespace eomgen
