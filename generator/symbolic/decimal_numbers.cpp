#include "symbolic/decimal_numbers.hpp"

#include <cctype>
#include <sstream>

namespace eomgen {

namespace {

using GiNaC::numeric;

// the exponent k of p in n, and n / p^k
int strip_factor(numeric& n, int p) {
  int k = 0;
  while (GiNaC::irem(n, numeric(p)).is_zero()) {
    n = GiNaC::iquo(n, numeric(p));
    ++k;
  }
  return k;
}

bool is_word_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }
bool is_digit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }

}  // namespace

std::string number_text(const numeric& value) {
  std::ostringstream s;
  s << value;
  return s.str();
}

std::optional<std::string> exact_decimal_text(const numeric& value) {
  if (!value.is_rational() || value.is_integer()) return std::nullopt;
  numeric rest = value.denom();
  int twos = strip_factor(rest, 2), fives = strip_factor(rest, 5);
  // short fractions read best as fractions (m*l^2/200, 7/5): the decimal is for the long ones
  static const numeric long_denominator = 1000000;
  if (rest != 1 || fives == 0 || value.denom() <= long_denominator) return std::nullopt;
  int places = std::max(twos, fives);
  numeric scaled = GiNaC::abs(value) * GiNaC::pow(numeric(10), numeric(places));
  std::string digits = number_text(scaled), sign = value.is_negative() ? "-" : "";
  int length = static_cast<int>(digits.size()), leading_exponent = length - 1 - places;
  if (leading_exponent < -4) {
    std::string mantissa = digits.substr(0, 1) + (length > 1 ? "." + digits.substr(1) : "");
    return sign + mantissa + "e" + std::to_string(leading_exponent);
  }
  if (places >= length) return sign + "0." + std::string(static_cast<std::size_t>(places - length), '0') + digits;
  std::size_t point = static_cast<std::size_t>(length - places);
  return sign + digits.substr(0, point) + "." + digits.substr(point);
}

std::string decimals_as_fractions(const std::string& text) {
  std::string out;
  std::size_t i = 0;
  while (i < text.size()) {
    char c = text[i];
    bool starts_number = is_digit(c) || (c == '.' && i + 1 < text.size() && is_digit(text[i + 1]));
    if (!starts_number) {
      std::size_t end = i + 1;
      if (is_word_char(c))
        while (end < text.size() && is_word_char(text[end])) ++end;
      out += text.substr(i, end - i);
      i = end;
      continue;
    }
    std::string whole, fraction;
    while (i < text.size() && is_digit(text[i])) whole += text[i++];
    bool decimal = false;
    if (i < text.size() && text[i] == '.') {
      decimal = true;
      ++i;
      while (i < text.size() && is_digit(text[i])) fraction += text[i++];
    }
    long exponent = 0;
    if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
      std::size_t j = i + 1;
      bool negative = j < text.size() && text[j] == '-';
      if (j < text.size() && (text[j] == '-' || text[j] == '+')) ++j;
      if (j < text.size() && is_digit(text[j])) {
        decimal = true;
        std::string e;
        while (j < text.size() && is_digit(text[j])) e += text[j++];
        exponent = std::stol(e) * (negative ? -1 : 1);
        i = j;
      }
    }
    if (!decimal) {
      out += whole;
      continue;
    }
    numeric value(("0" + whole + fraction).c_str());
    value *= GiNaC::pow(numeric(10), numeric(exponent - static_cast<long>(fraction.size())));
    out += "(" + number_text(value) + ")";
  }
  return out;
}

}  // namespace eomgen
