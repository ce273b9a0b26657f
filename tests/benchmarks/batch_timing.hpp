// Timing for the benchmark programs in this folder: ns per call over a batch of calls, and the
// median of repetitions (interleaved by the caller, so that the peers see the same machine), or
// their fastest, which other programs on a shared machine slow the least.
#pragma once

#include <algorithm>
#include <chrono>
#include <vector>

template <class F>
double time_batch(F&& call, int calls) {
  auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < calls; ++i) call();
  return std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start).count() / calls;
}

inline double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

inline double fastest(const std::vector<double>& v) { return *std::min_element(v.begin(), v.end()); }
