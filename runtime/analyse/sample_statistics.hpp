/// @file The statistics of a sample of numbers: mean, standard deviation, the standard
/// error of the mean, and quantiles. The sums run in the order of the sample, so the same
/// sample gives the same bits however it was computed.
#pragma once

#include <vector>

namespace eomgen::runtime {

struct SampleStatistics {
  long count = 0;          // the finite values; NaN values are left out
  double mean = 0, standard_deviation = 0, standard_error = 0;  // NaN below two values
  std::vector<double> quantiles;  // at the probabilities asked, NaN without values
};

/// Quantiles by linear interpolation between order statistics (Hyndman and Fan's type 7,
/// the default of R and NumPy); the standard deviation with the n − 1 denominator.
SampleStatistics sample_statistics(const std::vector<double>& values, const std::vector<double>& probabilities);

}  // namespace eomgen::runtime
