#include "common/independent_rows.hpp"

#include <algorithm>
#include <cmath>

namespace eomgen {

bool IndependentRows::add(std::vector<double> row) {
  double size = 0, norm = 0;
  for (double v : row) size = std::max(size, std::abs(v));
  for (const std::vector<double>& b : basis_) {
    double along = 0;
    for (std::size_t j = 0; j < row.size(); ++j) along += row[j] * b[j];
    for (std::size_t j = 0; j < row.size(); ++j) row[j] -= along * b[j];
  }
  for (double v : row) norm += v * v;
  norm = std::sqrt(norm);
  if (!(size > 0 && norm > 1e-9 * size)) return false;
  for (double& v : row) v /= norm;
  basis_.push_back(std::move(row));
  return true;
}

}  // namespace eomgen
