/// @file All partial derivatives of an expression at once. GiNaC's diff walks
/// the whole expression for every variable; a sum is split into its terms here,
/// each term is differentiated only by the variables it contains, so the
/// gradient of an n-term sum in n variables costs about n term-derivatives, not n².
#pragma once

#include <vector>

#include <ginac/ginac.h>

namespace eomgen {

/// ∂e/∂v_k for every k; `variables` are symbols.
std::vector<GiNaC::ex> gradient(const GiNaC::ex& e, const std::vector<GiNaC::ex>& variables);

/// Every symbol in e (the variables e can depend on), added to `out`.
void collect_symbols(const GiNaC::ex& e, GiNaC::exset& out);

}  // namespace eomgen
