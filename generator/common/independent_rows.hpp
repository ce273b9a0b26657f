/// @file Rows of a Jacobian taken in order, each kept when it is independent of those kept
/// before it (Gram–Schmidt): what a constraint adds that the ones before it do not already say.
/// A row counts as dependent when what it has outside their span is below 1e-9 of its largest
/// entry, so that the verdict does not change with the constraint's units.
#pragma once

#include <vector>

namespace eomgen {

class IndependentRows {
 public:
  /// Whether `row` is independent of the rows kept so far; it is kept when it is.
  bool add(std::vector<double> row);

 private:
  std::vector<std::vector<double>> basis_;  // orthonormal
};

}  // namespace eomgen
