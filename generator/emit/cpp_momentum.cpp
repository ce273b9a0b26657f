#include "emit/cpp_momentum.hpp"

#include <fmt/format.h>

#include "emit/cpp_body_writer.hpp"
#include "symbolic/gradient.hpp"

namespace eomgen {

using GiNaC::ex;

// Hamilton's equations in mass-matrix form, x = [q; p], v = der(q) with M v = p − b:
// ∂v/∂p = M⁻¹, ∂v/∂q = −M⁻¹ G with G = ∂(M v)/∂q|_v + ∂b/∂q, and p' = f(q, v) by the chain rule
std::string momentum_jacobian_state_function(const Equations& e) {
  const Symbols& s = e.symbols;
  std::size_t n = s.num_coordinates(), N = 2 * n;
  BodyWriter w(e);
  w.solve_velocities();
  std::vector<ex> coordinates(s.coordinates.begin(), s.coordinates.end());
  std::vector<ex> velocities(e.coordinate_velocities.begin(), e.coordinate_velocities.end());
  std::vector<ex> entries;
  const MomentumSolve& momentum = *e.momentum();
  for (unsigned i = 0; i < n; ++i) {
    std::vector<ex> row = gradient(momentum.bias[i], coordinates);
    for (unsigned c = 0; c < n; ++c) {
      std::vector<ex> dM = gradient(momentum.mass_matrix(i, c), coordinates);
      for (unsigned j = 0; j < n; ++j) row[j] += dM[j] * velocities[c];
    }
    entries.insert(entries.end(), row.begin(), row.end());
  }
  for (unsigned i = 0; i < n; ++i) {
    std::vector<ex> dq = gradient(e.forcing[i], coordinates);
    entries.insert(entries.end(), dq.begin(), dq.end());
  }
  for (unsigned i = 0; i < n; ++i) {
    std::vector<ex> dv = gradient(e.forcing[i], velocities);
    entries.insert(entries.end(), dv.begin(), dv.end());
  }
  auto code = w.batch(entries);
  const char* arrays[3] = {"G", "Fq", "Fv"};
  for (int a = 0; a < 3; ++a) {
    w.line(fmt::format("T {}[{}];", arrays[a], n * n));
    for (std::size_t i = 0; i < n * n; ++i) w.line(fmt::format("{}[{}] = {};", arrays[a], i, code[a * n * n + i]));
  }
  w.line(fmt::format("T column[{}];", n));
  w.line(fmt::format("for (std::size_t j = 0; j < {}; ++j) {{", n));
  w.line(fmt::format("  for (std::size_t i = 0; i < {0}; ++i) column[i] = -G[i * {0} + j];", n));
  w.line("  detail::ldlt_solve(Lv, Dv, column);");
  w.line(fmt::format("  for (std::size_t i = 0; i < {}; ++i) J[i * {} + j] = column[i];", n, N));
  w.line(fmt::format("  for (std::size_t i = 0; i < {}; ++i) column[i] = T(i == j ? 1 : 0);", n));
  w.line("  detail::ldlt_solve(Lv, Dv, column);");
  w.line(fmt::format("  for (std::size_t i = 0; i < {}; ++i) J[i * {} + {} + j] = column[i];", n, N, n));
  w.line("}");
  w.line(fmt::format("for (std::size_t i = 0; i < {}; ++i) {{", n));
  w.line(fmt::format("  for (std::size_t j = 0; j < {}; ++j) {{", N));
  w.line(fmt::format("    T sum = j < {0} ? Fq[i * {0} + j] : T(0);", n));
  w.line(fmt::format("    for (std::size_t k = 0; k < {0}; ++k) sum = sum + Fv[i * {0} + k] * J[k * {1} + j];", n, N));
  w.line(fmt::format("    J[({} + i) * {} + j] = sum;", n, N));
  w.line("  }");
  w.line("}");
  return function(fmt::format("/// Jacobian of the right-hand side, dx'/dx, analytic: der(q) solves M der(q) = p - b, so\n"
                              "/// d der(q)/dp = M^-1, d der(q)/dq = -M^-1 (d(M der(q))/dq + db/dq), and der(p) = f(q, der(q))\n"
                              "/// by the chain rule. J: {0}x{0}, row-major.\n", N),
                  "void jacobian_state(T t, const T* x, const detail::input_t<T>* u, const T* p, T* J)", w.finish(all_unused));
}

// P = −∂p'/∂p, Q = −∂p'/∂q and B = ∂p'/∂u of Hamilton's equations in mass-matrix form, from the Jacobians
std::string momentum_linearization_function(const Equations& e) {
  std::size_t n = e.symbols.num_coordinates(), N = 2 * n, m = e.symbols.inputs.size();
  std::string body = fmt::format("  T J[{0}];\n  jacobian_state(t, x, u, p, J);\n"
                                 "  for (std::size_t i = 0; i < {1}; ++i)\n    for (std::size_t j = 0; j < {1}; ++j) {{\n"
                                 "      P[i * {1} + j] = -J[({1} + i) * {2} + {1} + j];\n"
                                 "      Q[i * {1} + j] = -J[({1} + i) * {2} + j];\n    }}\n",
                                 N * N, n, N);
  if (m > 0)
    body += fmt::format("  T Bx[{0}];\n  jacobian_input(t, x, u, p, Bx);\n  for (std::size_t i = 0; i < {1}; ++i)\n"
                        "    for (std::size_t j = 0; j < {2}; ++j) B[i * {2} + j] = Bx[({1} + i) * {2} + j];\n",
                        N * m, n, m);
  else
    body += "  (void)B;\n";
  return function("/// Linearization of the momentum equations, read off the Jacobians: P = -d der(p)/dp,\n"
                  "/// Q = -d der(p)/dq, B = d der(p)/du (M = I).\n",
                  "void linearization(T t, const T* x, const detail::input_t<T>* u, const T* p, T* P, T* Q, T* B)", body);
}

}  // namespace eomgen
