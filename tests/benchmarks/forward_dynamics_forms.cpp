// The two forms of a joint tree's rhs in one process: M = L D Lᵀ (the composite-rigid-body M and the
// Newton–Euler f) and the articulated-body algorithm, from two headers of one model (`eomgen generate
// --forward-dynamics mass_matrix` and `articulated`) included in namespaces of their own, timed in
// interleaved repetitions over the same random states; prints the two medians and the largest
// difference between their q'' as one JSON line.
// Built by forward_dynamics_forms.py: c++ -O2 -DMODEL=NAME -DFACTORED=DIR1/NAME.hpp -DARTICULATED=DIR2/NAME.hpp
#include <array>
#include <cmath>
#include <complex>
#include <cstddef>
#include <cstdio>
#include <limits>
#include <random>
#include <vector>

#include "batch_timing.hpp"

#define FORMS_STRING2(x) #x
#define FORMS_STRING(x) FORMS_STRING2(x)

namespace factored {
#include FORMS_STRING(FACTORED)
}
namespace articulated {
#include FORMS_STRING(ARTICULATED)
}
namespace by_ldlt = factored::eomgen::models::MODEL;
namespace by_articulated = articulated::eomgen::models::MODEL;
constexpr int N = int(by_ldlt::num_states);

int main() {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> uniform(-1, 1);
  constexpr int states = 64;
  std::vector<std::array<double, N>> x(states);
  for (auto& s : x)
    for (double& v : s) v = uniform(random);
  std::array<double, by_ldlt::num_inputs + 1> u{};
  const auto p = by_ldlt::default_parameters;
  std::array<double, N> a{}, b{};
  double difference = 0, sink = 0;
  for (const auto& s : x) {
    by_ldlt::rhs(0.0, s.data(), u.data(), p.data(), a.data());
    by_articulated::rhs(0.0, s.data(), u.data(), p.data(), b.data());
    double size = 1;
    for (int i = 0; i < N; ++i) size = std::max(size, std::abs(a[i]));
    for (int i = 0; i < N; ++i) difference = std::max(difference, std::abs(a[i] - b[i]) / size);
  }
  std::vector<double> ldlt_ns, articulated_ns;
  int k = 0;
  for (int r = 0; r < 31; ++r) {
    ldlt_ns.push_back(time_batch([&] { by_ldlt::rhs(0.0, x[k++ % states].data(), u.data(), p.data(), a.data()); sink += a[N - 1]; }, 20000));
    articulated_ns.push_back(time_batch([&] { by_articulated::rhs(0.0, x[k++ % states].data(), u.data(), p.data(), b.data()); sink += b[N - 1]; }, 20000));
  }
  std::printf("{\"ldlt_ns\": %.1f, \"articulated_ns\": %.1f, \"difference\": %.3g, \"sink\": %g}\n", median(ldlt_ns),
              median(articulated_ns), difference, sink * 0);
}
