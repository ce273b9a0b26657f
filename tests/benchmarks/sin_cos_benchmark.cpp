// The generated headers' detail::sin_cos for double against the C library's std::sin and std::cos of
// the same angles, in one process with interleaved repetitions and medians, for as many angles as a
// function of a 1-, 2-, 8- and 30-link chain takes. Prints a Markdown table with the ratio.
// Built by tests/benchmarks/run: c++ -O2 -std=c++17 -I generated sin_cos_benchmark.cpp; --quick: few repetitions.
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <vector>

#include "batch_timing.hpp"
#include "double_pendulum.hpp"

namespace detail = eomgen::models::double_pendulum::detail;

volatile double sink;

template <std::size_t N>
void row(int repetitions, std::mt19937& random) {
  std::uniform_real_distribution<double> uniform(-3.5, 3.5);
  double angle[N], s[N], c[N];
  for (double& a : angle) a = uniform(random);
  std::vector<double> batched, library;
  const int calls = 20000;
  for (int r = 0; r < repetitions; ++r) {
    batched.push_back(time_batch([&] {
      detail::sin_cos(angle, s, c);
      sink = s[N - 1] + c[0];
      angle[0] = angle[0] + 1e-300;  // a new argument each call: nothing to hoist
    }, calls));
    library.push_back(time_batch([&] {
      for (std::size_t i = 0; i < N; ++i) {
        s[i] = std::sin(angle[i]);
        c[i] = std::cos(angle[i]);
      }
      sink = s[N - 1] + c[0];
      angle[0] = angle[0] + 1e-300;
    }, calls));
  }
  double b = median(batched), l = median(library);
  std::printf("| %zu | %.1f | %.1f | %.1fx |\n", N, b, l, l / b);
}

int main(int argc, char** argv) {
  int repetitions = argc > 1 && std::strcmp(argv[1], "--quick") == 0 ? 3 : 31;
  std::mt19937 random(1);
  std::printf("| angles | detail::sin_cos [ns] | std::sin + std::cos [ns] | ratio |\n|---|---|---|---|\n");
  row<1>(repetitions, random);
  row<2>(repetitions, random);
  row<8>(repetitions, random);
  row<30>(repetitions, random);
}
