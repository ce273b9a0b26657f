/// @file Exact decimals in printed equations. A model file's decimals are read as exact
/// rationals (2.7425820240206541 is 27425820240206541/10^16), so products of them have
/// denominators of 40 digits and more. Printed as a fraction such a number says nothing
/// to a reader; printed as its exact decimal expansion (it terminates) it is the number
/// the model file wrote, still exact. Readers of the canonical text turn the decimals
/// back into rationals before GiNaC's parser, which would read them as floats.
#pragma once

#include <optional>
#include <string>

#include <ginac/ginac.h>

namespace eomgen {

/// A number in GiNaC's own text, every digit: 3127439543999999821863399999999997 or p/q.
std::string number_text(const GiNaC::numeric& value);

/// The exact decimal of a rational whose denominator is 2^a 5^b with b >= 1 and over a
/// million (a number that came from a long decimal: 27425820240206541/10^16 →
/// "2.7425820240206541"), in scientific notation below 1e-4 ("1.5e-20"); nothing for any
/// other number: 7/5, m*l^2/200 and 2^-30 read better as the fractions they are.
std::optional<std::string> exact_decimal_text(const GiNaC::numeric& value);

/// `text` with every decimal literal (a number with a point or an exponent) written as an
/// exact fraction in parentheses, for GiNaC's parser: "0.15*m" → "(15/100)*m".
std::string decimals_as_fractions(const std::string& text);

}  // namespace eomgen
