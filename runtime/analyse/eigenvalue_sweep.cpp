#include "analyse/eigenvalue_sweep.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <thread>

#include "analyse/equilibrium.hpp"
#include "analyse/linear_stability.hpp"

namespace eomgen::runtime {

namespace {

struct PointResult {
  bool found = false;
  CountedSpectrum spectrum;
};

Problem at_value(const Problem& base, int parameter, double value) {
  Problem p = base;
  p.parameters[std::size_t(parameter)] = value;
  return p;
}

PointResult analyse_point(const Problem& p, const std::optional<std::vector<double>>& x0, bool fixed) {
  if (!x0) return {};
  Equilibrium eq = fixed ? check_equilibrium(p, *x0) : find_equilibrium(p, *x0);
  if (!eq.converged) return {};
  return {true, counted_spectrum(p, eq.state)};
}

int unstable_count(const CountedSpectrum& s) {
  int n = 0;
  for (auto l : s.eigenvalues) n += l.real() > s.tolerance;
  return n;
}

// Eigenvalues to the right of the axis beyond their own rounding (ε·|A|·κ: large for a cluster at
// zero, a nearly defective pair) and beyond 1e-4 of the verdicts' tolerance: a crossing is then
// found to the rounding of the eigenvalue that crosses
bool right_of_axis(const CountedSpectrum& s, std::size_t i) {
  double rounding = i < s.errors.size() ? s.errors[i] : 0.0;
  return s.eigenvalues[i].real() > std::max(1e-4 * s.tolerance, rounding);
}

int right_of_axis(const CountedSpectrum& s) {
  int n = 0;
  for (std::size_t i = 0; i < s.eigenvalues.size(); ++i) n += right_of_axis(s, i);
  return n;
}

// The crossing between a and b: bisected on the number of eigenvalues to the right of the axis,
// which does not depend on telling one eigenvalue from another (following the nearest one jumped
// to a neighbouring mode of nearly the same frequency), to `resolution` or to the doubles there.
// The crossing eigenvalue is then the one nearest the axis on the unstable side of the bracket.
std::optional<AxisCrossing> bisect(const Problem& base, const StartState& start, bool fixed, int parameter, double a,
                                   const CountedSpectrum& sa, double b, const CountedSpectrum& sb, double resolution) {
  bool rising = unstable_count(sb) > unstable_count(sa);
  auto analysed_at = [&](double value) {
    Problem p = at_value(base, parameter, value);
    return analyse_point(p, start(p.parameters), fixed);
  };
  double lo = a, hi = b;
  // the sweep keeps its points' eigenvalues, not their rounding: the ends once more, with it
  PointResult first = analysed_at(a), last = analysed_at(b);
  if (!first.found || !last.found) return std::nullopt;
  CountedSpectrum at_lo = first.spectrum, at_hi = last.spectrum;
  int count_lo = right_of_axis(at_lo), count_hi = right_of_axis(at_hi);
  if (count_lo == count_hi) return std::nullopt;  // the change is within the verdicts' tolerance only
  while (hi - lo > resolution) {
    double mid = 0.5 * (lo + hi);
    if (!(mid > lo && mid < hi)) break;  // the doubles between lo and hi are exhausted
    PointResult r = analysed_at(mid);
    if (!r.found) return std::nullopt;
    int count = right_of_axis(r.spectrum);
    if (std::abs(count - count_lo) <= std::abs(count - count_hi)) lo = mid, at_lo = r.spectrum;
    else hi = mid, at_hi = r.spectrum;
  }
  const CountedSpectrum& unstable_end = rising ? at_hi : at_lo;
  std::complex<double> l = NAN;
  for (std::size_t i = 0; i < unstable_end.eigenvalues.size(); ++i)
    if (auto e = unstable_end.eigenvalues[i];
        right_of_axis(unstable_end, i) && e.imag() >= 0 && (std::isnan(l.real()) || e.real() < l.real()))
      l = e;
  if (std::isnan(l.real())) return std::nullopt;
  AxisCrossing c;
  c.parameter = 0.5 * (lo + hi);
  c.eigenvalue = {0.0, l.imag()};
  // a real double root splits into ±√(rounding): a pair is oscillatory beyond √(tolerance · |λ|max),
  // which scales with the eigenvalues as they do (√tolerance alone does not)
  double radius = 0;
  for (auto e : unstable_end.eigenvalues) radius = std::max(radius, std::abs(e));
  c.oscillatory = std::abs(l.imag()) > std::sqrt(std::max(unstable_end.tolerance * radius, 1e-300));
  c.destabilizing = rising;
  return c;
}

// asymptotically stable runs of points, their ends moved to the crossings beside them
// The runs of points with verdict `kind`, each end moved to the crossing that bounds it: past
// the last point of the run up to the next point that is neither of this kind nor marginal (a
// point at a crossing is marginal within rounding: 14 with the crossing at 14.0000000004 ended
// "stable for Ω < 12" at the grid before it)
std::vector<StableInterval> intervals_of(const EigenvalueSweep& s, const std::string& kind) {
  std::vector<StableInterval> out;
  int n = s.axis.count;
  auto bounding = [&](int from, int step) {  // the first point, going `step`, that is unstable or has none
    int k = from;
    while (k >= 0 && k < n && (s.verdicts[std::size_t(k)] == kind || s.verdicts[std::size_t(k)] == "marginally_stable")) k += step;
    return k;
  };
  for (int k = 0; k < n;) {
    if (s.verdicts[std::size_t(k)] != kind) {
      ++k;
      continue;
    }
    int first = k;
    while (k < n && s.verdicts[std::size_t(k)] == kind) ++k;
    StableInterval interval{s.axis.value(first), s.axis.value(k - 1), first == 0, k == n};
    if (kind == "asymptotically_stable") {
      double below = first > 0 ? s.axis.value(std::max(bounding(first - 1, -1), 0)) : s.axis.low;
      double above = k < n ? s.axis.value(std::min(bounding(k, 1), n - 1)) : s.axis.high;
      for (const AxisCrossing& c : s.crossings) {
        if (first > 0 && c.parameter >= below && c.parameter <= s.axis.value(first)) interval.low = c.parameter;
        if (k < n && c.parameter >= s.axis.value(k - 1) && c.parameter <= above && interval.high == s.axis.value(k - 1))
          interval.high = c.parameter;
      }
    }
    out.push_back(interval);
  }
  return out;
}

}  // namespace

EigenvalueSweep sweep_eigenvalues(const Problem& base, const StartState& start, bool fixed, SweepAxis axis,
                                  double resolution, unsigned threads, const std::function<void(long, long)>& progress,
                                  const std::atomic<bool>& stop, PointRange range) {
  auto started = std::chrono::steady_clock::now();
  EigenvalueSweep s;
  s.axis = axis;
  const int first = static_cast<int>(range.begin), end = static_cast<int>(range.last(axis.count));
  const long share = std::max(0, end - first);
  std::vector<PointResult> points(std::size_t(axis.count));
  // the start states first, on this thread: `start` may evaluate symbolic expressions,
  // and GiNaC is not thread-safe
  std::vector<Problem> problems(std::size_t(axis.count));
  std::vector<std::optional<std::vector<double>>> starts(std::size_t(axis.count));
  for (int k = first; k < end; ++k) {
    problems[std::size_t(k)] = at_value(base, axis.parameter, axis.value(k));
    starts[std::size_t(k)] = start(problems[std::size_t(k)].parameters);
  }
  if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
  std::atomic<int> next{first};
  std::atomic<long> done{0};
  std::vector<std::thread> workers;
  for (unsigned w = 0; w < threads; ++w)
    workers.emplace_back([&] {
      for (int k; (k = next++) < end && !stop; ++done)
        points[std::size_t(k)] = analyse_point(problems[std::size_t(k)], starts[std::size_t(k)], fixed);
    });
  while (done < share && !stop) {
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
    if (progress) progress(done, share);
  }
  for (auto& t : workers) t.join();
  s.interrupted = stop && done < share;
  for (const PointResult& r : points) {
    s.eigenvalues.push_back(r.found ? r.spectrum.eigenvalues : std::vector<std::complex<double>>{});
    s.verdicts.push_back(r.found ? r.spectrum.verdict : "");
    s.tolerances.push_back(r.found ? r.spectrum.tolerance : NAN);
  }
  if (first == 0 && end == axis.count && !s.interrupted) locate_axis_crossings(s, base, start, fixed, resolution);
  if (progress) progress(done, share);
  s.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return s;
}

void locate_axis_crossings(EigenvalueSweep& s, const Problem& base, const StartState& start, bool fixed, double resolution) {
  auto spectrum_at = [&](std::size_t k) {
    return CountedSpectrum{s.eigenvalues[k], s.verdicts[k], 0.0, s.tolerances[k], {}};
  };
  s.crossings.clear();
  // relative to the sweep's width: an absolute width would be coarser than a sweep over 1e-12
  // and, beside parameters of 1e12, finer than the doubles there. On a logarithmic axis, to the
  // same fraction of each step, so relative to the parameter's value
  s.resolution = resolution * (s.axis.high - s.axis.low);
  if (s.axis.logarithmic) s.resolution = resolution * (s.axis.count - 1) * (s.axis.value(1) / s.axis.low - 1);
  for (std::size_t k = 0; k + 1 < std::size_t(s.axis.count); ++k) {
    double step = s.axis.value(int(k) + 1) - s.axis.value(int(k));
    if (s.verdicts[k].empty() || s.verdicts[k + 1].empty()) continue;
    CountedSpectrum a = spectrum_at(k), b = spectrum_at(k + 1);
    // two eigenvalues crossing in opposite directions between grid points cancel in the
    // count: the grid must be fine enough to see them apart
    if (unstable_count(a) == unstable_count(b)) continue;
    if (auto c = bisect(base, start, fixed, s.axis.parameter, s.axis.value(int(k)), a, s.axis.value(int(k) + 1), b,
                        s.axis.logarithmic ? resolution * (s.axis.count - 1) * step : s.resolution))
      s.crossings.push_back(*c);
  }
  s.stable = intervals_of(s, "asymptotically_stable");
  s.marginal = intervals_of(s, "marginally_stable");
}

}  // namespace eomgen::runtime
