/// @file Stability along one parameter (Hiller §7.4): the eigenvalues of the
/// linearization against the parameter, the values where an eigenvalue crosses the
/// imaginary axis, and the intervals of asymptotic stability. For the benchmark
/// bicycle these are the weave speed (a complex pair crosses: oscillatory) and the
/// capsize speed (a real eigenvalue crosses zero).
#pragma once

#include <atomic>
#include <complex>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "analyse/stability_map.hpp"
#include "simulation.hpp"

namespace eomgen::runtime {

struct AxisCrossing {
  double parameter = 0;                 // where Re λ = 0, bisected to EigenvalueSweep::resolution
  std::complex<double> eigenvalue;      // the crossing eigenvalue there (Im ≥ 0)
  bool oscillatory = false;             // a complex pair (Hopf), else a real eigenvalue through 0
  bool destabilizing = false;           // Re λ goes from < 0 to > 0 as the parameter grows
};

struct StableInterval {
  double low = 0, high = 0;  // ends: the crossings, or the ends of the sweep
  bool open_low = false, open_high = false;  // the interval runs on past the sweep's end
};

struct EigenvalueSweep {
  SweepAxis axis;
  /// per point: the eigenvalues that count (cyclic zeros left out), by decreasing real
  /// part; empty where no equilibrium or steady motion was found
  std::vector<std::vector<std::complex<double>>> eigenvalues;
  std::vector<std::string> verdicts;  // per point, empty where none was found
  std::vector<double> tolerances;     // per point: within it a real part counts as zero (NaN where none)
  std::vector<AxisCrossing> crossings;
  /// each crossing is bisected to within this, in the parameter; on a logarithmic axis, relative
  /// to the parameter's value
  double resolution = 0;
  std::vector<StableInterval> stable;
  std::vector<StableInterval> marginal;  // runs of points that are only marginally stable (ends at grid points)
  bool interrupted = false;
  double seconds = 0;
};

/// The state about which to linearize at the given parameter values (the model's initial
/// state for them: a steady motion that follows the parameters), or nothing.
using StartState = std::function<std::optional<std::vector<double>>(const std::vector<double>& parameters)>;

/// Sweeps `axis` on `threads` threads (0: all cores). At each point the equilibrium (or
/// steady motion) is found from `start`, or only checked when `fixed`. Crossings are
/// bisected to `resolution` times the axis' width (high − low), or to the doubles there (on a
/// logarithmic axis, to that fraction of the step they lie in, times the number of steps).
/// With `points` less than the whole axis (a
/// share of a distributed sweep) only those points are computed, and the crossings are
/// left to `locate_axis_crossings` once every share is in.
EigenvalueSweep sweep_eigenvalues(const Problem& base, const StartState& start, bool fixed, SweepAxis axis,
                                  double resolution, unsigned threads, const std::function<void(long, long)>& progress,
                                  const std::atomic<bool>& stop, PointRange points = {});

/// The crossings of the imaginary axis between neighbouring points of a complete sweep,
/// and the stable intervals between them.
void locate_axis_crossings(EigenvalueSweep& s, const Problem& base, const StartState& start, bool fixed, double resolution);

}  // namespace eomgen::runtime
