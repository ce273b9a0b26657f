/// @file What an expression costs to evaluate, counted on GiNaC's tree before any code is written:
/// one operation per +, −, × or ÷ (a sum of k terms k − 1, a product of k factors k − 1, x^n with a
/// whole n its |n| − 1 products and a division where n < 0), and ten per elementary function or
/// non-whole power, as emit/operation_count.hpp counts a generated function's text. For choosing
/// between two forms of a model's code while the equations are derived.
#pragma once

#include <vector>

#include <ginac/ginac.h>

namespace eomgen {

long arithmetic_operations(const GiNaC::ex& e);

/// the operations of every definition and expression given
long arithmetic_operations(const std::vector<GiNaC::ex>& expressions);

}  // namespace eomgen
