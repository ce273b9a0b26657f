/// @file What `eomgen sweep` with one parameter prints and writes: the crossings of the
/// imaginary axis, the stable intervals, and the eigenvalues against the parameter.
#pragma once

#include <string>

#include "analyse/eigenvalue_sweep.hpp"
#include "distribute/ranks.hpp"

namespace eomgen::studies {

/// The parameter, then Re and Im of each eigenvalue by decreasing real part.
std::string eigenvalue_sweep_csv(const runtime::EigenvalueSweep& s, const std::string& parameter);

/// `ranks`: the processes that computed it, said in the summary.
void print_eigenvalue_sweep_text(const runtime::EigenvalueSweep& s, const std::string& model, const std::string& parameter,
                                 const distribute::Ranks& ranks);

void print_eigenvalue_sweep_json(const runtime::EigenvalueSweep& s, const std::string& model, const std::string& parameter,
                                 const distribute::Ranks& ranks);

}  // namespace eomgen::studies
