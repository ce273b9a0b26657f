/// @file The colour scale of a stability map: which colour each stability degree (the largest
/// real part of the eigenvalues) gets, symmetric about zero, in the map's own scale.
#pragma once

#include <string>
#include <vector>

namespace eomgen::runtime {

/// Linear in the degree where the map's degrees lie within two decades of the largest; otherwise
/// symmetric-logarithmic, c = sign(d) log10(1 + |d|/knee) with the knee at the tenth of the
/// smallest decile of the nonzero |d|, so that a map over a logarithmic axis of six decades shows
/// its small degrees as colours and not all as white. Nothing in it has units: the degrees times
/// any factor give the same picture.
struct DegreeColours {
  double knee = 0;     // 0: linear
  double largest = 1;  // the largest |d|, the end of the scale
  /// the value plotted for a degree (NaN stays NaN)
  double colour(double degree) const;
  /// the colour bar's range, ±colour(largest)
  double range() const { return colour(largest); }
  /// gnuplot's `set cbtics (...)` for a logarithmic scale: 0 and ±10^k in whole decades between
  /// the knee and the largest; empty for a linear one (gnuplot's own tics)
  std::string tics() const;
};

DegreeColours degree_colours(const std::vector<double>& degrees);

}  // namespace eomgen::runtime
