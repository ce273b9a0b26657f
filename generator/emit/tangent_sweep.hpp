/// @file Forward-mode derivatives of generated code, written as code: the tangent sweep.
///
/// A symbolic gradient differentiates the whole expression of every output, so a Jacobian's
/// code grows with the size of the expressions times the number of variables (and repeats
/// what the values' common subexpressions had shared). The tangent sweep differentiates the
/// straight-line program instead: each temporary c = φ(a, b, …) gets, for every direction j it
/// depends on, a tangent c_dj = Σ ∂φ/∂a · a_dj, itself one line of code. The derivative of an
/// output is then a short sum over the tangents of its operands, and the code grows with the
/// program times the number of directions each temporary depends on (Griewank and Walther,
/// Evaluating Derivatives, ch. 3).
#pragma once

#include <map>
#include <vector>

#include <ginac/ginac.h>

#include "emit/cpp_body_writer.hpp"

namespace eomgen {

class TangentSweep {
 public:
  /// The directions are model symbols (coordinates, velocities, inputs): direction j is
  /// the unit change of directions[j]; every other symbol is held constant.
  TangentSweep(BodyWriter& writer, const std::vector<GiNaC::ex>& directions);

  /// Writes the tangents of the batch's temporaries (call once per batch, in order, before
  /// derivatives of the batch's outputs are taken).
  void follow(const CseBatch& batch);
  /// dE/d(direction j) for every direction, in model symbols, temporaries and tangents.
  std::vector<GiNaC::ex> derivatives(const GiNaC::ex& reduced) const;
  /// The tangents written so far, in order: each in temporaries and earlier tangents.
  const std::vector<Temporary>& tangents_written() const { return written_; }

 private:
  std::vector<GiNaC::ex> derivatives_of(const Temporary& t) const;

  BodyWriter& writer_;
  std::size_t num_directions_;
  // a direction symbol or a temporary → its nonzero tangents by direction
  std::map<GiNaC::ex, std::map<std::size_t, GiNaC::ex>, GiNaC::ex_is_less> tangents_;
  std::vector<Temporary> written_;
};

}  // namespace eomgen
