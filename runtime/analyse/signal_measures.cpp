#include "analyse/signal_measures.hpp"

#include <algorithm>
#include <cmath>

namespace eomgen::runtime {

namespace {

const char* kind_name(MeasureKind kind) {
  switch (kind) {
    case MeasureKind::final_value: return "final";
    case MeasureKind::maximum: return "max";
    case MeasureKind::minimum: return "min";
    case MeasureKind::mean: return "mean";
    case MeasureKind::period: return "period";
  }
  return "";
}

// The time in [t[k], t[k+1]] where the interpolating polynomial through the samples
// k−1 … k+2 (fewer at the ends) equals `level`; v[k] < level <= v[k+1].
double crossing_time(const std::vector<double>& t, const std::vector<double>& v, std::size_t k, double level) {
  std::size_t first = k > 0 ? k - 1 : k, last = std::min(k + 2, t.size() - 1);
  auto p = [&](double x) {
    double sum = 0;  // Lagrange's form: four points at most
    for (std::size_t i = first; i <= last; ++i) {
      double w = v[i];
      for (std::size_t j = first; j <= last; ++j)
        if (j != i) w *= (x - t[j]) / (t[i] - t[j]);
      sum += w;
    }
    return sum - level;
  };
  double lo = t[k], hi = t[k + 1];
  if (p(hi) < 0) return lo + (hi - lo) * (level - v[k]) / (v[k + 1] - v[k]);  // the cubic overshoots: linear
  // to the doubles between lo and hi, whatever the time scale (a floor of 1e-15 s left runs of
  // picoseconds a single step of bisection)
  for (int i = 0; i < 200; ++i) {
    double mid = 0.5 * (lo + hi);
    if (!(mid > lo && mid < hi)) break;
    (p(mid) < 0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

double period(const std::vector<double>& t, const std::vector<double>& v) {
  auto [low, high] = std::minmax_element(v.begin(), v.end());
  double level = 0.5 * (*low + *high);
  std::vector<double> crossings;
  for (std::size_t k = 0; k + 1 < v.size(); ++k)
    if (v[k] < level && v[k + 1] >= level) crossings.push_back(crossing_time(t, v, k, level));
  if (crossings.size() < 2) return NAN;
  return (crossings.back() - crossings.front()) / double(crossings.size() - 1);
}

}  // namespace

std::string Measure::text() const { return std::string(kind_name(kind)) + "(" + signal + ")"; }

bool measure_kind(const std::string& name, MeasureKind& kind) {
  for (MeasureKind k : {MeasureKind::final_value, MeasureKind::maximum, MeasureKind::minimum, MeasureKind::mean,
                        MeasureKind::period})
    if (name == kind_name(k)) {
      kind = k;
      return true;
    }
  return false;
}

double measure_signal(MeasureKind kind, const std::vector<double>& times, const std::vector<double>& values) {
  if (values.empty() || values.size() != times.size()) return NAN;
  switch (kind) {
    case MeasureKind::final_value: return values.back();
    case MeasureKind::maximum: return *std::max_element(values.begin(), values.end());
    case MeasureKind::minimum: return *std::min_element(values.begin(), values.end());
    case MeasureKind::mean: {
      if (values.size() == 1) return values[0];
      double integral = 0;
      for (std::size_t k = 0; k + 1 < values.size(); ++k) integral += 0.5 * (values[k] + values[k + 1]) * (times[k + 1] - times[k]);
      return integral / (times.back() - times.front());
    }
    case MeasureKind::period: return period(times, values);
  }
  return NAN;
}

}  // namespace eomgen::runtime
