#include "emit/cpp_articulated.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "emit/cpp_body_writer.hpp"
#include "symbolic/gradient.hpp"

namespace eomgen {

using GiNaC::ex;

namespace {

// the columns of ∂f/∂(x, u): q, q', then the inputs
std::vector<ex> forcing_variables(const Symbols& s) {
  std::vector<ex> v(s.coordinates.begin(), s.coordinates.end());
  v.insert(v.end(), s.velocities.begin(), s.velocities.end());
  v.insert(v.end(), s.inputs.begin(), s.inputs.end());
  return v;
}

}  // namespace

std::string articulated_rhs_function(const Equations& e) {
  std::size_t n = e.symbols.num_coordinates();
  BodyWriter w(e);
  auto ddq = w.batch(e.articulated_accelerations);
  for (std::size_t i = 0; i < n; ++i) w.line(fmt::format("xdot[{}] = x[{}];", i, n + i));
  for (std::size_t i = 0; i < n; ++i) w.line(fmt::format("xdot[{}] = {};", n + i, ddq[i]));
  return function(fmt::format("/// Explicit first-order form x' = [q'; q''] with x = [q; q'], q'' = M^-1 f by the\n"
                              "/// articulated-body recursion of the particles' tree (O(n), without forming M).\n"
                              "/// x, xdot: num_states = {}; u: num_inputs (may be null if none); p: num_parameters.\n",
                              2 * n),
                  "void rhs(T t, const T* x, const detail::input_t<T>* u, const T* p, T* xdot)", w.finish(all_unused));
}

// rows [first, last) of ∂τ/∂(q, q', u), τ = M(q) q'' − f(q, q', u) with q'' held, written into F
std::string inverse_dynamics_gradient_rows(const Equations& e, unsigned first, unsigned last) {
  const Symbols& s = e.symbols;
  std::size_t n = s.num_coordinates();
  std::vector<ex> variables = forcing_variables(s), coordinates(s.coordinates.begin(), s.coordinates.end()), entries;
  BodyWriter w(e);
  for (unsigned i = first; i < last; ++i) {
    std::vector<GiNaC::exvector> terms(variables.size());
    std::vector<ex> df = gradient(e.forcing[i], variables);
    for (std::size_t j = 0; j < variables.size(); ++j) terms[j].push_back(-df[j]);
    for (unsigned c = 0; c < n; ++c) {
      if (e.mass_matrix(i, c).info(GiNaC::info_flags::numeric)) continue;
      std::vector<ex> dM = gradient(e.mass_matrix(i, c), coordinates);
      for (unsigned j = 0; j < n; ++j)
        if (!dM[j].is_zero()) terms[j].push_back(dM[j] * w.accelerations()[c]);
    }
    for (const GiNaC::exvector& t : terms) entries.push_back(GiNaC::add(t));
  }
  std::size_t offset = first * variables.size();
  w.assign(entries, [&](std::size_t k, const std::string& code) { return fmt::format("F[{}] = {};", offset + k, code); });
  return w.finish(all_unused + std::string(" (void)ddq;"));
}

// ∂τ/∂(q, q', u) row by row: the Jacobian is −M⁻¹ ∂τ/∂x at the rhs's q'', the linearization ∂τ/∂x
// at q'' = 0 (P = ∂τ/∂q', Q = ∂τ/∂q, B = −∂τ/∂u). A long chain's rows go in blocks of about
// entries_per_block entries, each a function of its own: g++ -O2 of the 30-link chain's rhs and
// jacobian_state took 8.3 s with its 1,800 entries in one function (register allocation grows
// faster than the function), 4.5 s in blocks of 300, 4.2 s in blocks of 120; each block computes
// its own sines and cosines again (jacobian_state 37 µs -> 44 µs, header 365 KB -> 404 KB)
std::string inverse_dynamics_gradient_function(const Equations& e) {
  constexpr std::size_t entries_per_block = 300;
  std::size_t n = e.symbols.num_coordinates(), W = forcing_variables(e.symbols).size();
  unsigned rows = unsigned(std::max<std::size_t>(1, entries_per_block / W));
  const char* arguments = "(T t, const T* x, const T* ddq, const input_t<T>* u, const T* p, T* F)";
  std::string doc = fmt::format("/// d tau/d(q, q', u) of the inverse dynamics tau = M(q) q'' - f(q, q', u), q'' held.\n"
                                "/// ddq: {0}; F: {0}x{1}, row-major.\n", n, W);
  std::string out = "namespace detail {\n\n";
  if (rows >= n) {
    out += function(doc, std::string("void inverse_dynamics_gradient") + arguments, inverse_dynamics_gradient_rows(e, 0, unsigned(n)));
    return out + "}  // namespace detail\n\n";
  }
  std::string calls = "  (void)t; (void)x; (void)ddq; (void)u; (void)p;\n";
  for (unsigned first = 0; first < n; first += rows) {
    unsigned last = std::min(unsigned(n), first + rows);
    std::string name = fmt::format("inverse_dynamics_gradient_rows_{}_{}", first, last);
    out += function(fmt::format("/// Rows {} to {} of inverse_dynamics_gradient.\n", first, last - 1), "void " + name + arguments,
                    inverse_dynamics_gradient_rows(e, first, last));
    calls += fmt::format("  {}(t, x, ddq, u, p, F);\n", name);
  }
  out += function(doc, std::string("void inverse_dynamics_gradient") + arguments, calls);
  return out + "}  // namespace detail\n\n";
}

// dq''/dx = −M⁻¹ ∂τ/∂x, with q'' from rhs and M from mass_matrix
std::string articulated_jacobian_state_function(const Equations& e) {
  const Symbols& s = e.symbols;
  std::size_t n = s.num_coordinates(), N = 2 * n, W = N + s.inputs.size();
  BodyWriter w(e);
  w.line(fmt::format("T xdot[{}];", N));
  w.line("rhs(t, x, u, p, xdot);");
  w.line(fmt::format("T M[{}];", n * n));
  w.line("mass_matrix(t, x, p, M);");
  w.line(fmt::format("T L[{}];", n * n));
  w.line(fmt::format("T D[{}];", n));
  w.line("detail::ldlt_factor(M, L, D);");
  w.line(fmt::format("T F[{}];", n * W));
  w.line(fmt::format("detail::inverse_dynamics_gradient(t, x, xdot + {}, u, p, F);", n));
  w.line(fmt::format("for (std::size_t i = 0; i < {}; ++i)", n));
  w.line(fmt::format("  for (std::size_t j = 0; j < {0}; ++j) J[i * {0} + j] = T(j == {1} + i ? 1 : 0);", N, n));
  w.line(fmt::format("T column[{}];", n));
  w.line(fmt::format("for (std::size_t j = 0; j < {}; ++j) {{", N));
  w.line(fmt::format("  for (std::size_t i = 0; i < {}; ++i) column[i] = -F[i * {} + j];", n, W));
  w.line("  detail::ldlt_solve(L, D, column);");
  w.line(fmt::format("  for (std::size_t i = 0; i < {0}; ++i) J[({0} + i) * {1} + j] = column[i];", n, N));
  w.line("}");
  return inverse_dynamics_gradient_function(e) +
         function(fmt::format("/// Jacobian of the right-hand side, dx'/dx, analytic: the lower block is -M^-1 d tau/dx\n"
                              "/// (tau = M q'' - f, q'' held), with q'' from rhs and M from mass_matrix. J: {0}x{0}, row-major.\n",
                              N),
                  "void jacobian_state(T t, const T* x, const detail::input_t<T>* u, const T* p, T* J)", w.finish(all_unused));
}

// a tree of particles is scleronomic and has no [energy] kinetic, so T = ½ q'ᵀ M q' exactly (Hiller §3.5)
std::string articulated_kinetic_energy_function(const Equations& e) {
  std::size_t n = e.symbols.num_coordinates();
  return function("/// Kinetic energy T = q'^T M q' / 2, with M from mass_matrix. x: num_states; p: num_parameters.\n",
                  "T kinetic_energy(T t, const T* x, const T* p)",
                  fmt::format("  T M[{0}];\n  mass_matrix(t, x, p, M);\n  T twice = T(0);\n"
                              "  for (std::size_t i = 0; i < {1}; ++i)\n    for (std::size_t j = 0; j < {1}; ++j)"
                              " twice = twice + x[{1} + i] * M[i * {1} + j] * x[{1} + j];\n  return twice / T(2);\n",
                              n * n, n));
}

// M q'' + P q' + Q q = B u about a state with q'' = 0 (Hiller §5.3), read off ∂τ/∂(q, q', u) there
std::string articulated_linearization_function(const Equations& e) {
  const Symbols& s = e.symbols;
  std::size_t n = s.num_coordinates(), m = s.inputs.size(), W = 2 * n + m;
  std::string body = fmt::format("  (void)B;\n  const T ddq[{3}] = {{}};\n  T F[{0}];\n"
                                 "  detail::inverse_dynamics_gradient(t, x, ddq, u, p, F);\n"
                                 "  for (std::size_t i = 0; i < {1}; ++i) {{\n"
                                 "    for (std::size_t j = 0; j < {1}; ++j) P[i * {1} + j] = F[i * {2} + {1} + j];\n"
                                 "    for (std::size_t j = 0; j < {1}; ++j) Q[i * {1} + j] = F[i * {2} + j];\n",
                                 n * W, n, W, n);
  if (m > 0) body += fmt::format("    for (std::size_t j = 0; j < {0}; ++j) B[i * {0} + j] = -F[i * {1} + {2} + j];\n", m, W, 2 * n);
  body += "  }\n";
  return function(fmt::format("/// Linearization M q'' + P q' + Q q = B u about the state x, valid where q'' = 0\n"
                              "/// (an equilibrium or a steady motion): P = -df/dq', Q = -df/dq, B = df/du, with M from\n"
                              "/// mass_matrix. P: {0}x{0}; Q: {0}x{0}; B: {0}x{1}; all row-major.\n", n, m),
                  "void linearization(T t, const T* x, const detail::input_t<T>* u, const T* p, T* P, T* Q, T* B)", body);
}

}  // namespace eomgen
