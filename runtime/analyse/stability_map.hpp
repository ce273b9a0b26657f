/// @file Stability maps (Hiller §7.4, stability regions): the stability degree,
/// the largest real part of the eigenvalues that counts for the verdict, over a
/// grid of two parameters, with the equilibrium re-found at every point.
#pragma once

#include <algorithm>
#include <atomic>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "simulation.hpp"

namespace eomgen::runtime {

struct SweepAxis {
  int parameter;  // index in parameter_names
  double low, high;
  int count;
  /// points a constant ratio apart (0 < low), for a range over decades: a damping from 1e-9 to
  /// 1e3 in 49 even steps has no point below 20
  bool logarithmic = false;
  double value(int k) const {
    if (count == 1 || k == 0) return low;
    if (k == count - 1) return high;
    double f = double(k) / (count - 1);
    return logarithmic ? low * std::pow(high / low, f) : low + (high - low) * f;
  }
};

/// The part of a sweep one process computes: rows of a map, points of a 1-D sweep.
struct PointRange {
  long begin = 0, end = -1;  // [begin, end); end −1: to the last
  long last(long count) const { return end < 0 ? count : std::min(end, count); }
};

struct StabilityMap {
  SweepAxis x, y;
  std::vector<double> degree;               // y.count rows of x.count, NaN where not computed or no equilibrium
  std::vector<std::vector<double>> states;  // the equilibrium at each point (empty where none)
  long computed = 0;
  bool interrupted = false;
  double seconds = 0;
};

/// Sweeps on `threads` threads (0: all cores). `start` is the equilibrium at the base
/// parameters; `fixed` keeps it (an --at equilibrium that does not move) instead of
/// re-finding it. `progress(done, total)` is called from the calling thread with this
/// process's points; setting `stop` ends the sweep early, keeping what was computed.
/// Only the rows in `rows` are computed (the others stay NaN): a share of a distributed
/// sweep. A row's result does not depend on which process or thread computes it.
StabilityMap sweep(const Problem& base, const std::vector<double>& start, bool fixed, SweepAxis x, SweepAxis y,
                   unsigned threads, const std::function<void(long, long)>& progress, const std::atomic<bool>& stop,
                   PointRange rows = {});

}  // namespace eomgen::runtime
