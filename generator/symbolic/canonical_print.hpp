/// @file Printing expressions in an order fixed by their names, not by
/// GiNaC's hash order (which depends on the order symbols were created), so
/// the same equations print as the same bytes in every run and process.
#pragma once

#include <functional>
#include <string>

#include <ginac/ginac.h>

namespace eomgen {

/// GiNaC syntax (`^` for powers, `der(q)` for velocities) that GiNaC's and
/// SymPy's parsers read back; terms and factors sorted by their text.
std::string canonical_text(const GiNaC::ex& e);

/// LaTeX; `symbol_name` gives the TeX of each symbol.
std::string latex_text(const GiNaC::ex& e, const std::function<std::string(const GiNaC::symbol&)>& symbol_name);

}  // namespace eomgen
