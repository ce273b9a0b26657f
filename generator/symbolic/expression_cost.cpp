#include "symbolic/expression_cost.hpp"

#include <cstdlib>

namespace eomgen {

namespace {

// a function call's or a non-whole power's cost in operations (as emit/operation_count.cpp)
constexpr long elementary_function = 10;

long operands(const GiNaC::ex& e) {
  long n = 0;
  for (std::size_t i = 0; i < e.nops(); ++i) n += arithmetic_operations(e.op(i));
  return n;
}

}  // namespace

long arithmetic_operations(const GiNaC::ex& e) {
  if (GiNaC::is_a<GiNaC::numeric>(e) || GiNaC::is_a<GiNaC::symbol>(e) || GiNaC::is_a<GiNaC::constant>(e)) return 0;
  if (GiNaC::is_a<GiNaC::add>(e) || GiNaC::is_a<GiNaC::mul>(e)) {
    // a coefficient of −1 is a subtraction in the sum it stands in, not a product
    long factors = long(e.nops());
    if (GiNaC::is_a<GiNaC::mul>(e) && GiNaC::ex_to<GiNaC::mul>(e).op(e.nops() - 1).is_equal(-1)) --factors;
    return factors - 1 + operands(e);
  }
  if (GiNaC::is_a<GiNaC::power>(e)) {
    const GiNaC::ex& exponent = e.op(1);
    long base = arithmetic_operations(e.op(0));
    if (!exponent.info(GiNaC::info_flags::integer)) return base + elementary_function;
    long n = std::labs(GiNaC::ex_to<GiNaC::numeric>(exponent).to_long());
    return base + (n > 0 ? n - 1 : 0) + (exponent.info(GiNaC::info_flags::negative) ? 1 : 0);
  }
  if (GiNaC::is_a<GiNaC::function>(e)) return elementary_function + operands(e);
  return operands(e);
}

long arithmetic_operations(const std::vector<GiNaC::ex>& expressions) {
  long n = 0;
  for (const GiNaC::ex& e : expressions) n += arithmetic_operations(e);
  return n;
}

}  // namespace eomgen
