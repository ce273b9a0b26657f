#include "symbolic/constant_value.hpp"

#include <cmath>

#include <ginac/ginac.h>

#include "symbolic/decimal_numbers.hpp"

namespace eomgen {

std::optional<double> constant_value(const std::string& text) {
  try {
    GiNaC::symtab names{{"Pi", GiNaC::Pi}};
    GiNaC::parser reader(names, true);  // strict: any other name is a mistake
    GiNaC::ex value = reader(decimals_as_fractions(text)).evalf();
    if (!GiNaC::is_a<GiNaC::numeric>(value) || !GiNaC::ex_to<GiNaC::numeric>(value).is_real()) return std::nullopt;
    double v = GiNaC::ex_to<GiNaC::numeric>(value).to_double();
    if (!std::isfinite(v)) return std::nullopt;
    return v;
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

}  // namespace eomgen
