#include "analyse/stability_map.hpp"

#include <chrono>
#include <cmath>
#include <mutex>
#include <thread>

#include "analyse/equilibrium.hpp"
#include "analyse/linear_stability.hpp"

namespace eomgen::runtime {

namespace {

// one row of the map, continuing the equilibrium from point to point
void sweep_row(const Problem& base, const std::vector<double>& start, bool fixed, const SweepAxis& x, const SweepAxis& y,
               int row, StabilityMap& map, const std::atomic<bool>& stop) {
  Problem p = base;
  p.parameters[y.parameter] = y.value(row);
  std::vector<double> guess = start;
  for (int k = 0; k < x.count && !stop; ++k) {
    p.parameters[x.parameter] = x.value(k);
    Equilibrium eq = fixed ? check_equilibrium(p, start) : find_equilibrium(p, guess);
    std::size_t at = static_cast<std::size_t>(row) * x.count + k;
    if (eq.converged) {
      map.degree[at] = stability_degree(p, eq.state);
      map.states[at] = eq.state;
      guess = eq.state;
    } else {
      guess = start;
    }
  }
}

}  // namespace

StabilityMap sweep(const Problem& base, const std::vector<double>& start, bool fixed, SweepAxis x, SweepAxis y,
                   unsigned threads, const std::function<void(long, long)>& progress, const std::atomic<bool>& stop,
                   PointRange rows) {
  auto started = std::chrono::steady_clock::now();
  StabilityMap map{x, y, std::vector<double>(static_cast<std::size_t>(x.count) * y.count, NAN),
                   std::vector<std::vector<double>>(static_cast<std::size_t>(x.count) * y.count), 0, false, 0};
  if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
  const int first = static_cast<int>(rows.begin), end = static_cast<int>(rows.last(y.count)), share = std::max(0, end - first);
  std::atomic<int> next_row{first};
  std::atomic<long> rows_done{0};
  std::vector<std::thread> workers;
  for (unsigned w = 0; w < threads; ++w)
    workers.emplace_back([&] {
      for (int row; (row = next_row++) < end && !stop;) {
        sweep_row(base, start, fixed, x, y, row, map, stop);
        ++rows_done;
      }
    });
  long total = static_cast<long>(x.count) * share;
  while (rows_done < share && !stop) {
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
    if (progress) progress(rows_done * x.count, total);
  }
  for (auto& t : workers) t.join();
  for (double d : map.degree) map.computed += !std::isnan(d);
  map.interrupted = stop && rows_done < share;
  map.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  if (progress) progress(rows_done * x.count, total);
  return map;
}

}  // namespace eomgen::runtime
