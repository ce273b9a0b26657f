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

/// Whether the samples a measure left out (`left_out`, among the finished ones) differ from the
/// kept ones in a drawn variable (`drawn[sample][variable]`): Welch's t of that variable between
/// the two groups beyond 4 means the loss depends on the varied values and the statistics over
/// the rest are biased. The variable with the largest |t| above 4 and that t, or −1.
struct SelectionDependence {
  int variable = -1;
  double t = 0;
};
SelectionDependence selection_dependence(const std::vector<std::vector<double>>& drawn, const std::vector<bool>& left_out);

}  // namespace eomgen::runtime
