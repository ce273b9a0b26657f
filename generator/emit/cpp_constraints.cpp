#include "emit/cpp_constraints.hpp"

#include <fmt/format.h>

#include "emit/cpp_body_writer.hpp"
#include "emit/formats.hpp"
#include "emit/tangent_sweep.hpp"
#include "kinematics/mechanics.hpp"

namespace eomgen {

using GiNaC::ex;

namespace {

// Baumgarte's gains in the generated code: C q'' + γ + 2α(C q' + b) + β² g = 0 drives a
// constraint error e by e'' + 2α e' + β² e = 0 (critically damped for α = β)
const GiNaC::realsymbol& gain_alpha() {
  static const GiNaC::realsymbol alpha("baumgarte_alpha");
  return alpha;
}
const GiNaC::realsymbol& gain_beta() {
  static const GiNaC::realsymbol beta("baumgarte_beta");
  return beta;
}

// the default gains, 1/s: a constraint error decays with time constant 0.1 s
constexpr double default_gain = 10;


// γ_stab = γ + 2α (C q' + b) + β² g, the right side of C q'' = −γ_stab
std::vector<ex> stabilized_bias(const Equations& e) {
  const ConstraintSet& c = e.constraints;
  const Symbols& s = e.symbols;
  std::vector<ex> out;
  for (unsigned i = 0; i < c.size(); ++i) {
    ex velocity = c.bias[i];
    for (unsigned j = 0; j < s.num_coordinates(); ++j) velocity += c.jacobian(i, j) * s.velocities[j];
    out.push_back(c.acceleration_bias[i] + 2 * gain_alpha() * velocity + gain_beta() * gain_beta() * c.position[i]);
  }
  return out;
}

std::vector<ex> jacobian_entries(const ConstraintSet& c) {
  std::vector<ex> out;
  for (unsigned i = 0; i < c.size(); ++i)
    for (unsigned j = 0; j < c.jacobian.cols(); ++j) out.push_back(c.jacobian(i, j));
  return out;
}

BodyWriter constrained_writer(const Equations& e) {
  BodyWriter w(e);
  w.name(gain_alpha(), "alpha");
  w.name(gain_beta(), "beta");
  return w;
}

// M, f, C and −γ_stab into local arrays; factor; q'' into ddq and λ into lambda. Returns
// the batch: its outputs are the upper triangle of M, f, C (row-major) and −γ_stab, in that order.
CseBatch solve_constrained(BodyWriter& w, const Equations& e) {
  std::size_t n = e.num_velocities(), m = e.constraints.size(), upper = n * (n + 1) / 2;
  std::vector<ex> exprs = upper_triangle(e.mass_matrix, n);
  exprs.insert(exprs.end(), e.forcing.begin(), e.forcing.end());
  for (const ex& c : jacobian_entries(e.constraints)) exprs.push_back(c);
  for (const ex& g : stabilized_bias(e)) exprs.push_back(-g);
  CseBatch batch = w.reduced_batch(exprs);
  std::vector<std::string> code;
  for (const ex& r : batch.outputs) code.push_back(w.print(r));
  w.line(fmt::format("T M[{}];", n * n));
  write_symmetric(w, std::vector<std::string>(code.begin(), code.begin() + static_cast<long>(upper)), n, "M");
  w.line(fmt::format("T ddq[{}];", n));
  for (std::size_t i = 0; i < n; ++i) w.line(fmt::format("ddq[{}] = {};", i, code[upper + i]));
  w.line(fmt::format("T C[{}];", m * n));
  for (std::size_t i = 0; i < m * n; ++i) w.line(fmt::format("C[{}] = {};", i, code[upper + n + i]));
  w.line(fmt::format("T right[{}];", m));
  for (std::size_t i = 0; i < m; ++i) w.line(fmt::format("right[{}] = {};", i, code[upper + n + m * n + i]));
  w.line("detail::ConstrainedSolver<T> solver;");
  w.line("solver.factor(M, C);");
  w.line("solver.solve(ddq, right, lambda);");
  return batch;
}

const char* stabilized_signature =
    "void rhs_stabilized(T t, const T* x, const detail::input_t<T>* u, const T* p, detail::input_t<T> alpha, "
    "detail::input_t<T> beta, T* xdot)";
const char* stabilized_jacobian_signature =
    "void jacobian_state_stabilized(T t, const T* x, const detail::input_t<T>* u, const T* p, detail::input_t<T> alpha, "
    "detail::input_t<T> beta, T* J)";
const char* sensitivities_signature =
    "void constrained_sensitivities(T t, const T* x, const input_t<T>* u, const T* p, input_t<T> alpha, "
    "input_t<T> beta, T* J, T* B)";

}  // namespace

std::string constraint_declarations(const Equations& e) {
  const ConstraintSet& c = e.constraints;
  std::string holonomic;
  for (bool h : c.holonomic) holonomic += std::string(holonomic.empty() ? "" : ", ") + (h ? "true" : "false");
  return fmt::format(
      "/// Constraints C(q,t) q' + b(q,t) = 0, the holonomic ones g(q,t) = 0 differentiated once.\n"
      "inline constexpr std::size_t num_constraints = {0};\n"
      "/// Lagrange I: one multiplier per constraint, M q'' = f + C^T lambda; none otherwise.\n"
      "inline constexpr std::size_t num_multipliers = {1};\n"
      "inline constexpr std::array<const char*, num_constraints> constraint_names{{{{{2}}}}};\n"
      "inline constexpr std::array<bool, num_constraints> constraint_is_holonomic{{{{{3}}}}};\n"
      "inline constexpr std::array<const char*, num_multipliers> multiplier_names{{{{{4}}}}};\n"
      "/// Baumgarte's stabilization of Lagrange I: C q'' + gamma = -2 alpha (C q' + b) - beta^2 g,\n"
      "/// so that a constraint error e obeys e'' + 2 alpha e' + beta^2 e = 0; rhs uses these gains [1/s].\n"
      "inline constexpr double baumgarte_alpha = {5};\n"
      "inline constexpr double baumgarte_beta = {5};\n\n",
      c.size(), e.has_multipliers ? c.size() : 0, quoted_list(c.names), holonomic,
      e.has_multipliers ? quoted_list(c.names, "lambda_") : "", format_number(default_gain));
}

std::string constrained_solver(const Equations& e) {
  if (!e.has_multipliers) return {};
  std::size_t n = e.num_velocities(), m = e.constraints.size();
  return fmt::format(
      "namespace detail {{\n\n"
      "/// The augmented system of Lagrange I, M a - C^T lambda = r1, C a = r2, solved through the\n"
      "/// Schur complement S = C M^-1 C^T (symmetric positive definite when C has full rank):\n"
      "/// lambda = S^-1 (r2 - C M^-1 r1), a = M^-1 (r1 + C^T lambda). Factor once, solve many times.\n"
      "/// Only =, +, -, *, / are applied to T, as in the rest of the header.\n"
      "template <class T>\n"
      "struct ConstrainedSolver {{\n"
      "  static constexpr std::size_t n = {0}, m = {1};\n"
      "  T L[n * n], D[n], C[m * n], Y[n * m], LS[m * m], DS[m];\n\n"
      "  void factor(const T* M, const T* constraint_jacobian) {{\n"
      "    ldlt_factor(M, L, D);\n"
      "    for (std::size_t i = 0; i < m * n; ++i) C[i] = constraint_jacobian[i];\n"
      "    for (std::size_t j = 0; j < m; ++j) {{  // Y = M^-1 C^T, column by column\n"
      "      T column[n];\n"
      "      for (std::size_t r = 0; r < n; ++r) column[r] = C[j * n + r];\n"
      "      ldlt_solve(L, D, column);\n"
      "      for (std::size_t r = 0; r < n; ++r) Y[r * m + j] = column[r];\n"
      "    }}\n"
      "    for (std::size_t j = 0; j < m; ++j) {{  // S = C Y = L_S D_S L_S^T\n"
      "      for (std::size_t i = j; i < m; ++i) {{\n"
      "        T s = T(0);\n"
      "        for (std::size_t r = 0; r < n; ++r) s = s + C[i * n + r] * Y[r * m + j];\n"
      "        for (std::size_t k = 0; k < j; ++k) s = s - LS[i * m + k] * LS[j * m + k] * DS[k];\n"
      "        if (i == j) DS[j] = s;\n"
      "        else LS[i * m + j] = s / DS[j];\n"
      "      }}\n"
      "    }}\n"
      "  }}\n\n"
      "  /// r1 (n) is overwritten with a; lambda (m) receives the multipliers.\n"
      "  void solve(T* r1, const T* r2, T* lambda) const {{\n"
      "    ldlt_solve(L, D, r1);\n"
      "    for (std::size_t i = 0; i < m; ++i) {{\n"
      "      lambda[i] = r2[i];\n"
      "      for (std::size_t r = 0; r < n; ++r) lambda[i] = lambda[i] - C[i * n + r] * r1[r];\n"
      "      for (std::size_t k = 0; k < i; ++k) lambda[i] = lambda[i] - LS[i * m + k] * lambda[k];\n"
      "    }}\n"
      "    for (std::size_t i = 0; i < m; ++i) lambda[i] = lambda[i] / DS[i];\n"
      "    for (std::size_t i = m; i-- > 0;)\n"
      "      for (std::size_t k = i + 1; k < m; ++k) lambda[i] = lambda[i] - LS[k * m + i] * lambda[k];\n"
      "    for (std::size_t r = 0; r < n; ++r)\n"
      "      for (std::size_t i = 0; i < m; ++i) r1[r] = r1[r] + Y[r * m + i] * lambda[i];\n"
      "  }}\n"
      "}};\n\n"
      "}}  // namespace detail\n\n"
      "template <class T>\n{2};\ntemplate <class T>\n{3};\n\n"
      "namespace detail {{\n\ntemplate <class T>\n{4};\n\n}}  // namespace detail\n\n",
      n, m, stabilized_signature, stabilized_jacobian_signature, sensitivities_signature);
}

std::string constrained_rhs_function(const Equations& e) {
  std::size_t n = e.num_velocities();
  return function(fmt::format("/// Explicit first-order form x' = [q'; q''] with x = [q; q'], q'' from the augmented system\n"
                              "/// with the default Baumgarte gains (rhs_stabilized takes others).\n"
                              "/// x, xdot: num_states = {}; u: num_inputs (may be null if none); p: num_parameters.\n",
                              2 * n),
                  "void rhs(T t, const T* x, const detail::input_t<T>* u, const T* p, T* xdot)",
                  "  rhs_stabilized(t, x, u, p, T(baumgarte_alpha), T(baumgarte_beta), xdot);\n");
}

std::string constrained_jacobian_state_function(const Equations& e) {
  std::size_t n = e.num_velocities();
  return function(fmt::format("/// Jacobian of rhs, dx'/dx, with the default Baumgarte gains. J: {0}x{0}, row-major.\n", 2 * n),
                  "void jacobian_state(T t, const T* x, const detail::input_t<T>* u, const T* p, T* J)",
                  "  jacobian_state_stabilized(t, x, u, p, T(baumgarte_alpha), T(baumgarte_beta), J);\n");
}

// d(q'', λ)/dy from the differentiated augmented system (y a state or an input):
// M dq'' − Cᵀ dλ = ∂f/∂y + (∂C/∂y)ᵀ λ − (∂M/∂y) q'',  C dq'' = ∂(−γ_stab)/∂y − (∂C/∂y) q''.
// The partial derivatives come from the tangent sweep through the code of `reduced`
// (laid out as solve_constrained returns it); the result is column by column, n + m per column.
std::vector<ex> differentiated_system(const Equations& e, const std::vector<ex>& reduced, const TangentSweep& sweep,
                                      std::size_t num_directions, const BodyWriter& w,
                                      const std::vector<GiNaC::symbol>& lambda) {
  std::size_t n = e.num_velocities(), m = e.constraints.size(), upper = n * (n + 1) / 2;
  auto mass = [&](std::size_t i, std::size_t k) {
    std::size_t a = std::min(i, k), b = std::max(i, k);
    return reduced[a * n - a * (a - 1) / 2 + (b - a)];
  };
  std::vector<std::vector<ex>> dM(n * n), dC(m * n);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t k = i; k < n; ++k) dM[i * n + k] = dM[k * n + i] = sweep.derivatives(mass(i, k));
  for (std::size_t i = 0; i < m * n; ++i) dC[i] = sweep.derivatives(reduced[upper + n + i]);
  // each entry's terms are gathered and summed once (+= would rebuild the growing sum)
  std::vector<std::vector<ex>> rows;  // n + m rows of num_directions entries
  for (std::size_t i = 0; i < n; ++i) {
    std::vector<ex> df = sweep.derivatives(reduced[upper + i]);
    rows.emplace_back();
    for (std::size_t j = 0; j < num_directions; ++j) {
      GiNaC::exvector terms{df[j]};
      for (std::size_t k = 0; k < n; ++k) terms.push_back(-dM[i * n + k][j] * w.accelerations()[k]);
      for (std::size_t r = 0; r < m; ++r) terms.push_back(dC[r * n + i][j] * lambda[r]);
      rows.back().push_back(GiNaC::add(terms));
    }
  }
  for (std::size_t r = 0; r < m; ++r) {
    std::vector<ex> dgamma = sweep.derivatives(reduced[upper + n + m * n + r]);
    rows.emplace_back();
    for (std::size_t j = 0; j < num_directions; ++j) {
      GiNaC::exvector terms{dgamma[j]};
      for (std::size_t k = 0; k < n; ++k) terms.push_back(-dC[r * n + k][j] * w.accelerations()[k]);
      rows.back().push_back(GiNaC::add(terms));
    }
  }
  std::vector<ex> columns;
  for (std::size_t j = 0; j < num_directions; ++j)
    for (std::size_t i = 0; i < n + m; ++i) columns.push_back(rows[i][j]);
  return columns;
}

// solves the differentiated system column by column: the first `states` columns are those of
// dx'/dx (into J, when not null), the rest those of dx'/du (into B, when not null)
void write_sensitivities(BodyWriter& w, const std::vector<std::string>& code, std::size_t n, std::size_t m,
                         std::size_t states, std::size_t inputs) {
  w.line(fmt::format("if (J)\n    for (std::size_t i = 0; i < {0}; ++i)\n"
                     "      for (std::size_t j = 0; j < {1}; ++j) J[i * {1} + j] = T(j == {0} + i ? 1 : 0);", n, states));
  if (inputs > 0) w.line(fmt::format("if (B)\n    for (std::size_t i = 0; i < {}; ++i) B[i] = T(0);", n * inputs));
  w.line(fmt::format("T column[{}];", n));
  w.line(fmt::format("T column_right[{}];", m));
  w.line(fmt::format("T column_lambda[{}];", m));
  for (std::size_t j = 0; j < states + inputs; ++j) {
    for (std::size_t i = 0; i < n; ++i) w.line(fmt::format("column[{}] = {};", i, code[j * (n + m) + i]));
    for (std::size_t i = 0; i < m; ++i) w.line(fmt::format("column_right[{}] = {};", i, code[j * (n + m) + n + i]));
    w.line("solver.solve(column, column_right, column_lambda);");
    if (j < states)
      w.line(fmt::format("if (J)\n    for (std::size_t i = 0; i < {0}; ++i) J[({0} + i) * {1} + {2}] = column[i];", n, states, j));
    else
      w.line(fmt::format("if (B)\n    for (std::size_t i = 0; i < {0}; ++i) B[({0} + i) * {1} + {2}] = column[i];", n, inputs,
                         j - states));
  }
}

std::vector<GiNaC::symbol> multiplier_symbols(BodyWriter& w, std::size_t m) {
  std::vector<GiNaC::symbol> lambda;
  for (std::size_t i = 0; i < m; ++i) {
    lambda.emplace_back(fmt::format("lambda{}", i));
    w.name(lambda.back(), fmt::format("lambda[{}]", i));
  }
  return lambda;
}

// detail::constrained_sensitivities: solve_constrained, then the derivatives of q'' and λ along
// the states and the inputs, from one tangent sweep
std::string sensitivities_function(const Equations& e) {
  const Symbols& s = e.symbols;
  std::size_t n = e.num_velocities(), m = e.constraints.size(), inputs = s.inputs.size();
  BodyWriter w = constrained_writer(e);
  std::vector<ex> directions(s.coordinates.begin(), s.coordinates.end());
  directions.insert(directions.end(), s.velocities.begin(), s.velocities.end());
  directions.insert(directions.end(), s.inputs.begin(), s.inputs.end());
  w.line(fmt::format("T lambda[{}];", m));
  CseBatch terms = solve_constrained(w, e);
  TangentSweep sweep(w, directions);
  sweep.follow(terms);
  auto code = w.batch(differentiated_system(e, terms.outputs, sweep, directions.size(), w, multiplier_symbols(w, m)));
  write_sensitivities(w, code, n, m, 2 * n, inputs);
  return "namespace detail {\n\n" +
         function(fmt::format("/// dx'/dx into J ({0}x{0}) and dx'/du into B ({0}x{1}), row-major, each when not null, with\n"
                              "/// Baumgarte gains alpha, beta: the derivatives of q'' and lambda solve the differentiated\n"
                              "/// augmented system, whose partial derivatives come from a tangent sweep (forward mode)\n"
                              "/// through the code of M, f, C and gamma.\n", 2 * n, inputs),
                  sensitivities_signature, w.finish(all_unused + std::string(" (void)alpha; (void)beta; (void)B;"))) +
         "}  // namespace detail\n\n";
}

std::string constrained_jacobian_input_function(const Equations& e) {
  std::size_t n = e.num_velocities(), inputs = e.symbols.inputs.size();
  return function(fmt::format("/// Input Jacobian dx'/du with the default Baumgarte gains: zero upper block, dq''/du below.\n"
                              "/// B: {}x{}, row-major (nothing is written when the model has no inputs).\n", 2 * n, inputs),
                  "void jacobian_input(T t, const T* x, const detail::input_t<T>* u, const T* p, T* B)",
                  inputs == 0 ? std::string("  ") + all_unused + " (void)B;\n"
                              : "  detail::constrained_sensitivities(t, x, u, p, T(baumgarte_alpha), T(baumgarte_beta), "
                                "static_cast<T*>(nullptr), B);\n");
}

namespace {

std::string lagrange1_functions(const Equations& e) {
  std::size_t n = e.num_velocities(), m = e.constraints.size();
  std::string out;
  {
    // one copy of the augmented system's code, shared by rhs_stabilized and multipliers
    BodyWriter w = constrained_writer(e);
    solve_constrained(w, e);
    for (std::size_t i = 0; i < n; ++i) w.line(fmt::format("accelerations[{}] = ddq[{}];", i, i));
    out += "namespace detail {\n\n" +
           function(fmt::format("/// q'' and lambda of the augmented system with Baumgarte gains alpha, beta.\n"
                                "/// accelerations: {}; lambda: {}.\n", n, m),
                    "void constrained_solution(T t, const T* x, const input_t<T>* u, const T* p, input_t<T> alpha, "
                    "input_t<T> beta, T* accelerations, T* lambda)",
                    w.finish(all_unused + std::string(" (void)alpha; (void)beta;"))) +
           "}  // namespace detail\n\n";
  }
  out += function("/// rhs with Baumgarte gains alpha, beta [1/s]; alpha = beta = 0 is the plain index-1 form\n"
                  "/// C q'' + gamma = 0, whose constraint errors grow along a simulation.\n",
                  stabilized_signature,
                  fmt::format("  T lambda[{0}];\n  detail::constrained_solution(t, x, u, p, alpha, beta, xdot + {1}, lambda);\n"
                              "  for (std::size_t i = 0; i < {1}; ++i) xdot[i] = x[{1} + i];\n", m, n));
  out += function(fmt::format("/// The multipliers lambda of M q'' = f + C^T lambda on the constraint manifold (no\n"
                              "/// Baumgarte terms): C^T lambda are the constraint forces. lambda: {}.\n", m),
                  "void multipliers(T t, const T* x, const detail::input_t<T>* u, const T* p, T* lambda)",
                  fmt::format("  T accelerations[{}];\n  detail::constrained_solution(t, x, u, p, T(0), T(0), accelerations, lambda);\n", n));
  out += sensitivities_function(e);
  out += function(fmt::format("/// Jacobian of rhs_stabilized, dx'/dx (see detail::constrained_sensitivities).\n"
                              "/// J: {0}x{0}, row-major.\n", 2 * n),
                  stabilized_jacobian_signature,
                  "  detail::constrained_sensitivities(t, x, u, p, alpha, beta, J, static_cast<T*>(nullptr));\n");
  return out;
}

// rhs_stabilized and jacobian_state_stabilized of a model without multipliers: the gains do nothing
std::string plain_stabilized_functions() {
  return function("/// The same as rhs: Baumgarte's gains apply to Lagrange I models only.\n", stabilized_signature,
                  "  (void)alpha; (void)beta;\n  rhs(t, x, u, p, xdot);\n") +
         function("/// The same as jacobian_state: Baumgarte's gains apply to Lagrange I models only.\n",
                  stabilized_jacobian_signature, "  (void)alpha; (void)beta;\n  jacobian_state(t, x, u, p, J);\n") +
         function("/// Only Lagrange I models have multipliers: nothing is written.\n",
                  "void multipliers(T t, const T* x, const detail::input_t<T>* u, const T* p, T* lambda)",
                  "  (void)t; (void)x; (void)u; (void)p; (void)lambda;\n");
}

std::string residual_functions(const Equations& e) {
  const ConstraintSet& c = e.constraints;
  std::size_t nq = e.symbols.num_coordinates(), m = c.size();
  std::string out;
  {
    BodyWriter w(e);
    auto code = w.batch(jacobian_entries(c));
    for (std::size_t i = 0; i < code.size(); ++i) w.line(fmt::format("C[{}] = {};", i, code[i]));
    out += function(fmt::format("/// Constraint Jacobian C(q,t) of C q' + b = 0. C: {}x{}, row-major.\n", m, nq),
                    "void constraint_jacobian(T t, const T* x, const T* p, T* C)",
                    w.finish("(void)t; (void)x; (void)p; (void)C;"));
  }
  BodyWriter w(e);
  if (m > 0) {
    std::vector<ex> exprs = c.position;
    for (const ex& x : jacobian_entries(c)) exprs.push_back(x);
    exprs.insert(exprs.end(), c.bias.begin(), c.bias.end());
    auto code = w.batch(exprs);
    w.line(fmt::format("T qdot[{}];", nq));
    if (e.uses_pseudo_velocities()) {
      auto rates = w.batch(e.coordinate_rates);
      for (std::size_t j = 0; j < nq; ++j) w.line(fmt::format("qdot[{}] = {};", j, rates[j]));
    } else {
      for (std::size_t j = 0; j < nq; ++j) w.line(fmt::format("qdot[{}] = x[{}];", j, nq + j));
    }
    for (std::size_t i = 0; i < m; ++i) {
      w.line(fmt::format("position[{}] = {};", i, code[i]));
      std::string velocity = code[m + m * nq + i];
      for (std::size_t j = 0; j < nq; ++j) velocity += fmt::format(" + ({})*qdot[{}]", code[m + i * nq + j], j);
      w.line(fmt::format("velocity[{}] = {};", i, velocity));
    }
  }
  out += function(fmt::format("/// Constraint residuals: g(q,t) of the holonomic constraints (0 for the others) and\n"
                              "/// C q' + b of all, with q' from the state{}. position, velocity: {}.\n",
                              e.uses_pseudo_velocities() ? " (q' = W s + w)" : "", m),
                  "void constraint_residuals(T t, const T* x, const T* p, T* position, T* velocity)",
                  w.finish("(void)t; (void)x; (void)p; (void)position; (void)velocity;"));
  return out;
}

}  // namespace

std::string constraint_functions(const Equations& e) {
  return residual_functions(e) + (e.has_multipliers ? lagrange1_functions(e) : plain_stabilized_functions());
}

}  // namespace eomgen
