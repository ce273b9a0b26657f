/// @file The generated C++ header: DESIGN.md's contract, one self-contained
/// header per model that needs only the C++17 standard library.
#include <optional>

#include <fmt/format.h>

#include "common/version.hpp"
#include "derive/angle_coordinates.hpp"
#include "emit/cpp_articulated.hpp"
#include "emit/cpp_articulated_jacobian.hpp"
#include "emit/cpp_body_writer.hpp"
#include "emit/cpp_constant.hpp"
#include "emit/cpp_constraints.hpp"
#include "emit/cpp_drawing.hpp"
#include "emit/cpp_expression.hpp"
#include "emit/cpp_ldlt.hpp"
#include "emit/cpp_momentum.hpp"
#include "emit/cpp_piecewise.hpp"
#include "emit/cpp_trig.hpp"
#include "emit/cpp_header.hpp"
#include "emit/cpp_header_summary.hpp"
#include "emit/cpp_joint_tree.hpp"
#include "emit/cpp_tree_gradient_loops.hpp"
#include "emit/operation_count.hpp"
#include "emit/dynamics_form.hpp"
#include "emit/formats.hpp"
#include "model/symbols.hpp"
#include "symbolic/canonical_print.hpp"
#include "symbolic/cse.hpp"
#include "symbolic/gradient.hpp"
#include "symbolic/trig_expansion.hpp"

namespace eomgen {

using GiNaC::ex;

namespace {


std::string number_list(const std::vector<double>& values) {
  std::string s;
  for (double v : values) s += (s.empty() ? "" : ", ") + format_number(v);
  return s;
}


std::string mass_matrix_function(const Equations& e) {
  DynamicsForm form = dynamics_form(e);
  if (form == DynamicsForm::particle_tree) return articulated_mass_matrix_function(e);
  std::size_t n = e.forcing.size(), m = e.symbols.inputs.size();
  BodyWriter w(e);
  if (form == DynamicsForm::newton_euler) {
    // M does not depend on u: f is taken at u = 0 and dropped
    w.line(fmt::format("T f[{}];", n));
    if (m > 0) w.line(fmt::format("const detail::input_t<T> no_inputs[{}] = {{}};", m));
    w.line(fmt::format("detail::mass_matrix_and_forcing(t, x, {}, p, M, f);", m > 0 ? "no_inputs" : "nullptr"));
  } else {
    write_symmetric(w, w.batch(upper_triangle(e.mass_matrix, n)), n, "M");
  }
  return function(fmt::format("/// Mass matrix M(q,t) of M q'' = f, symmetric positive definite.\n"
                              "/// x: num_states; p: num_parameters; M: {}x{}, row-major.\n", n, n),
                  "void mass_matrix(T t, const T* x, const T* p, T* M)", w.finish("(void)t; (void)x; (void)p;"));
}

std::string forcing_function(const Equations& e) {
  BodyWriter w(e);
  DynamicsForm form = dynamics_form(e);
  const std::vector<ex>& f = form == DynamicsForm::particle_tree ? e.articulated()->inverse_dynamics.forcing : e.forcing;
  if (form == DynamicsForm::newton_euler) {
    w.line(fmt::format("T M[{}];", f.size() * f.size()));
    w.line("detail::mass_matrix_and_forcing(t, x, u, p, M, f);");
  } else {
    w.assign(f, [](std::size_t i, const std::string& code) { return fmt::format("f[{}] = {};", i, code); });
  }
  return function(fmt::format("/// Forcing f(q, q', u, t) of M q'' = f: applied, gravity, dissipative and velocity terms.\n"
                              "/// x: num_states; u: num_inputs (may be null if none); p: num_parameters; f: {}.\n", e.forcing.size()),
                  "void forcing(T t, const T* x, const detail::input_t<T>* u, const T* p, T* f)", w.finish(all_unused));
}

// q' = v, or the kinematic equations q' = W s + w of Appell's equations
void coordinate_rates(BodyWriter& w, const Equations& e, const std::string& target) {
  std::size_t n = e.symbols.num_coordinates();
  if (!e.uses_pseudo_velocities()) {
    for (std::size_t i = 0; i < n; ++i) w.line(fmt::format("{}[{}] = x[{}];", target, i, n + i));
    return;
  }
  auto rates = w.batch(e.coordinate_rates);
  for (std::size_t i = 0; i < n; ++i) w.line(fmt::format("{}[{}] = {};", target, i, rates[i]));
}

std::string rhs_function(const Equations& e) {
  if (e.has_multipliers) return constrained_rhs_function(e);
  DynamicsForm form = dynamics_form(e);
  if (form == DynamicsForm::particle_tree) return articulated_rhs_function(e);
  if (e.joint_tree_accelerations()) return joint_tree_rhs_function(e);
  std::size_t n = e.symbols.num_coordinates(), k = e.num_velocities();
  BodyWriter w(e);
  // a tree's M and f are long code, written once, in detail::factored_accelerations
  if (form == DynamicsForm::newton_euler) call_factored_accelerations(w, k);
  else accelerations(w, e);
  coordinate_rates(w, e, "xdot");
  for (std::size_t i = 0; i < k; ++i) w.line(fmt::format("xdot[{}] = ddq[{}];", n + i, i));
  return function(fmt::format("/// Explicit first-order form x' = [{}; M^-1 f] with x = [q; {}].\n"
                              "/// x, xdot: num_states = {}; u: num_inputs (may be null if none); p: num_parameters.\n",
                              e.uses_pseudo_velocities() ? "W s + w" : "q'", e.uses_pseudo_velocities() ? "s" : "q'", n + k),
                  "void rhs(T t, const T* x, const detail::input_t<T>* u, const T* p, T* xdot)", w.finish(all_unused));
}

// dq''/dx_j = M^-1 (df/dx_j - dM/dx_j q''), all columns solved at once with the factored M
std::string jacobian_state_function(const Equations& e, bool tree_pass) {
  if (e.has_multipliers) return constrained_jacobian_state_function(e);
  DynamicsForm form = dynamics_form(e);
  if (form == DynamicsForm::momentum) return momentum_jacobian_state_function(e);
  if (form == DynamicsForm::particle_tree) return articulated_jacobian_state_function(e);
  const Symbols& s = e.symbols;
  std::size_t nq = s.num_coordinates(), n = e.num_velocities(), N = nq + n;
  BodyWriter w(e);
  std::vector<ex> state(s.coordinates.begin(), s.coordinates.end()), coordinates = state;
  state.insert(state.end(), s.velocities.begin(), s.velocities.end());
  bool newton_euler = form == DynamicsForm::newton_euler;
  if (!newton_euler) accelerations(w, e);
  // a long tree's jacobian_state may form M and f in the pass its derivatives go on from
  if (newton_euler && !tree_pass) call_factored_accelerations(w, n);
  if (tree_pass) w.line(fmt::format("T L[{}];", n * n)), w.line(fmt::format("T D[{}];", n));
  // rows[i][j] = ∂f_i/∂x_j − Σ_c ∂M_ic/∂x_j q''_c = −∂τ_i/∂x_j  (M depends on q only)
  // (each entry's terms are gathered and summed once: += would rebuild the growing sum)
  std::vector<std::vector<ex>> rows;
  for (unsigned i = 0; i < n && !newton_euler; ++i) {
    std::vector<ex> df = gradient(e.forcing[i], state);
    std::vector<GiNaC::exvector> terms(N);
    for (std::size_t j = 0; j < N; ++j) terms[j].push_back(df[j]);
    for (unsigned c = 0; c < n; ++c) {
      if (e.mass_matrix(i, c).info(GiNaC::info_flags::numeric)) continue;
      std::vector<ex> dM = gradient(e.mass_matrix(i, c), coordinates);
      for (unsigned j = 0; j < nq; ++j)
        if (!dM[j].is_zero()) terms[j].push_back(-dM[j] * w.accelerations()[c]);
    }
    rows.emplace_back();
    for (const GiNaC::exvector& t : terms) rows.back().push_back(GiNaC::add(t));
  }
  std::vector<ex> columns;
  for (std::size_t j = 0; j < N && !newton_euler; ++j)
    for (unsigned i = 0; i < n; ++i) columns.push_back(rows[i][j]);
  std::vector<std::string> code = w.batch(columns);
  if (e.uses_pseudo_velocities()) {
    std::vector<ex> top;
    for (const ex& rate : e.coordinate_rates)
      for (const ex& d : gradient(rate, state)) top.push_back(d);
    auto top_code = w.batch(top);
    for (std::size_t i = 0; i < nq * N; ++i) w.line(fmt::format("J[{}] = {};", i, top_code[i]));
  } else {
    for (std::size_t i = 0; i < nq; ++i)
      for (std::size_t j = 0; j < N; ++j) w.line(fmt::format("J[{}] = T({});", i * N + j, j == nq + i ? 1 : 0));
  }
  // the lower block's rows, −∂τ/∂x, then M^-1 applied to all its columns at once, in place: the
  // solve's rows of odd length are vectorized too (each_column: m / 4 * 4 columns, then the rest),
  // so that solving them in a padded local array, as before, only added its copies (jacobian_state,
  // g++ -O2, one core, the fastest of 101 batches: tests/crosscheck's quadruped 5.45-5.53 µs
  // padded against 4.51-4.62 in place, example-robot-data's simple humanoid on a free joint
  // 13.2-13.4 against 12.75-12.9)
  w.line(fmt::format("T* rows = J + {};", nq * N));
  // a tree's rows are ∂τ/∂x, written in place by the gradient, and negated in the solve
  // the loops' pass, or the closed form's straight-line code with q'' to be solved for (no given_ddq)
  std::string pass_call = fmt::format("detail::tree_acceleration_gradient(t, x, u, p, {}L, D, rows);",
                                      e.gradient_loops() ? "" : "static_cast<const T*>(nullptr), ");
  if (tree_pass) {
    w.line(pass_call);
  } else if (newton_euler) {
    w.line("detail::inverse_dynamics_gradient(t, x, ddq, u, p, rows);");
  } else {
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < N; ++j) w.line(fmt::format("rows[{}] = {};", i * N + j, code[j * n + i]));
  }
  w.line(fmt::format("detail::ldlt_solve_rows<{}{}>(L, D, rows);", N, newton_euler ? ", true" : ""));
  return function(fmt::format("/// Jacobian of the right-hand side, dx'/dx, analytic: the lower block is\n"
                              "/// M^-1 (df/dx - (dM/dx) {}'). J: {}x{}, row-major.\n",
                              e.uses_pseudo_velocities() ? "s" : "q'", N, N),
                  "void jacobian_state(T t, const T* x, const detail::input_t<T>* u, const T* p, T* J)", w.finish(all_unused));
}

std::string jacobian_input_function(const Equations& e) {
  if (e.has_multipliers) return constrained_jacobian_input_function(e);
  DynamicsForm form = dynamics_form(e);
  if (form == DynamicsForm::particle_tree) return articulated_jacobian_input_function(e);
  const Symbols& s = e.symbols;
  std::size_t nq = s.num_coordinates(), n = e.forcing.size(), m = s.inputs.size();
  BodyWriter w(e);
  if (m > 0) {
    w.line(fmt::format("T M[{}];", n * n));
    // a tree's M is long code, written once, in mass_matrix
    if (form == DynamicsForm::newton_euler) w.line("mass_matrix(t, x, p, M);");
    else write_symmetric(w, w.batch(upper_triangle(e.mass_matrix, n)), n, "M");
    w.line(fmt::format("T L[{}];", n * n));
    w.line(fmt::format("T D[{}];", n));
    w.line("detail::ldlt_factor(M, L, D);");
    std::vector<ex> inputs(s.inputs.begin(), s.inputs.end());
    std::vector<std::vector<ex>> rows;
    for (std::size_t i = 0; i < n; ++i) rows.push_back(gradient(e.forcing[i], inputs));
    std::vector<ex> columns;
    for (std::size_t j = 0; j < m; ++j)
      for (std::size_t i = 0; i < n; ++i) columns.push_back(rows[i][j]);
    auto code = w.batch(columns);
    for (std::size_t i = 0; i < nq * m; ++i) w.line(fmt::format("B[{}] = T(0);", i));
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < m; ++j) w.line(fmt::format("B[{}] = {};", (nq + i) * m + j, code[j * n + i]));
    w.line(fmt::format("detail::ldlt_solve_rows<{}>(L, D, B + {});", m, nq * m));
  }
  return function(fmt::format("/// Input Jacobian dx'/du: zero upper block, M^-1 df/du below.\n"
                              "/// B: {}x{}, row-major (nothing is written when the model has no inputs).\n", nq + n, m),
                  "void jacobian_input(T t, const T* x, const detail::input_t<T>* u, const T* p, T* B)", w.finish(all_unused + std::string(" (void)B;")));
}

// M q'' + P q' + Q q = B u about a state with q'' = 0 (Hiller §5.3): P = -df/dq', Q = -df/dq, B = df/du
std::string linearization_function(const Equations& e) {
  DynamicsForm form = dynamics_form(e);
  if (form == DynamicsForm::momentum) return momentum_linearization_function(e);
  if (form == DynamicsForm::particle_tree) return articulated_linearization_function(e);
  bool newton_euler = form == DynamicsForm::newton_euler;
  const Symbols& s = e.symbols;
  std::size_t n = e.forcing.size(), nq = s.num_coordinates(), m = s.inputs.size();
  BodyWriter w(e);
  std::vector<ex> entries, velocities(s.velocities.begin(), s.velocities.end()),
      coordinates(s.coordinates.begin(), s.coordinates.end()), inputs(s.inputs.begin(), s.inputs.end());
  if (newton_euler) {
    // f = −τ at q'' = 0 (equations.hpp): P = ∂τ/∂q', Q = ∂τ/∂q, and B = ∂f/∂u below
    std::size_t W = nq + n;
    w.line(fmt::format("const T ddq[{}] = {{}};", n));
    w.line(fmt::format("T F[{}];", n * W));
    w.line("detail::inverse_dynamics_gradient(t, x, ddq, u, p, F);");
    w.line(fmt::format("for (std::size_t i = 0; i < {}; ++i) {{", n));
    w.line(fmt::format("  for (std::size_t j = 0; j < {}; ++j) P[i * {} + j] = F[i * {} + {} + j];", n, n, W, nq));
    w.line(fmt::format("  for (std::size_t j = 0; j < {}; ++j) Q[i * {} + j] = F[i * {} + j];", nq, nq, W));
    w.line("}");
    for (unsigned i = 0; i < n; ++i)
      for (const ex& d : gradient(e.forcing[i], inputs)) entries.push_back(d);
  }
  for (unsigned i = 0; i < n && !newton_euler; ++i) {
    for (const ex& d : gradient(e.forcing[i], velocities)) entries.push_back(-d);
    for (const ex& d : gradient(e.forcing[i], coordinates)) entries.push_back(-d);
    for (const ex& d : gradient(e.forcing[i], inputs)) entries.push_back(d);
  }
  auto code = w.batch(entries);
  std::size_t at = 0;
  for (std::size_t i = 0; i < n && newton_euler; ++i)
    for (std::size_t j = 0; j < m; ++j) w.line(fmt::format("B[{}] = {};", i * m + j, code[at++]));
  for (std::size_t i = 0; i < n && !newton_euler; ++i) {
    for (std::size_t j = 0; j < n; ++j) w.line(fmt::format("P[{}] = {};", i * n + j, code[at++]));
    for (std::size_t j = 0; j < nq; ++j) w.line(fmt::format("Q[{}] = {};", i * nq + j, code[at++]));
    for (std::size_t j = 0; j < m; ++j) w.line(fmt::format("B[{}] = {};", i * m + j, code[at++]));
  }
  return function(fmt::format("/// Linearization M q'' + P q' + Q q = B u about the state x, valid where q'' = 0\n"
                              "/// (an equilibrium or a steady motion): P = -df/dq', Q = -df/dq, B = df/du, with M from\n"
                              "/// mass_matrix{3}. P: {0}x{0}; Q: {0}x{2}; B: {0}x{1}; all row-major.\n", n, m, nq,
                              e.has_multipliers ? " (of the system without its constraints)"
                              : e.uses_pseudo_velocities() ? " (q' = s stands for the pseudo-velocities)" : ""),
                  "void linearization(T t, const T* x, const detail::input_t<T>* u, const T* p, T* P, T* Q, T* B)",
                  w.finish(all_unused + std::string(" (void)B;")));
}

// when T = ½ vᵀ M v (derive/quadratic_kinetic_energy.hpp): a tree's T in the recursion's
// quantities was as long as its M (99 KB of a 21-joint tree's header)
std::string kinetic_energy_from_mass_matrix_function(const Equations& e) {
  std::size_t nq = e.symbols.num_coordinates(), n = e.num_velocities();
  return function("/// Kinetic energy T = v^T M v / 2 of the state's velocities v, with M from mass_matrix.\n"
                  "/// x: num_states; p: num_parameters.\n",
                  "T kinetic_energy(T t, const T* x, const T* p)",
                  fmt::format("  T M[{0}];\n  mass_matrix(t, x, p, M);\n  T twice = T(0);\n"
                              "  for (std::size_t i = 0; i < {1}; ++i)\n    for (std::size_t j = 0; j < {1}; ++j)"
                              " twice = twice + x[{2} + i] * M[i * {1} + j] * x[{2} + j];\n  return twice / T(2);\n",
                              n * n, n, nq));
}

std::string scalar_function(const Equations& e, const char* name, const ex& value, const char* doc) {
  BodyWriter w(e);
  auto code = w.batch({value});
  w.line("return " + code[0] + ";");
  return function(doc, fmt::format("T {}(T t, const T* x, const T* p)", name), w.finish("(void)t; (void)x; (void)p;"));
}

std::string outputs_function(const Equations& e) {
  BodyWriter w(e);
  std::vector<ex> values;
  for (const NamedSymbolic& o : e.outputs) values.push_back(o.expression);
  auto code = w.batch(values);
  for (std::size_t i = 0; i < code.size(); ++i) w.line(fmt::format("y[{}] = {};", i, code[i]));
  return function(fmt::format("/// The model's [outputs], in output_names order. y: {}.\n", code.size()),
                  "void outputs(T t, const T* x, const detail::input_t<T>* u, const T* p, T* y)", w.finish(all_unused + std::string(" (void)y;")));
}

// each first integral in the state's variables (they hold at zero inputs, so take none)
std::string first_integrals_function(const Equations& e) {
  std::vector<std::string> names;
  for (const FirstIntegral& f : e.first_integrals) names.push_back(f.name);
  std::string out = fmt::format(
      "/// The first integrals (Hiller §3.6, §3.8.3): the generalized energy and the momenta of cyclic\n"
      "/// coordinates that stay constant along every motion at zero inputs, as `eomgen derive` explains.\n"
      "inline constexpr std::size_t num_first_integrals = {};\n"
      "inline constexpr std::array<const char*, num_first_integrals> first_integral_names{{{{{}}}}};\n\n",
      names.size(), quoted_list(names));
  BodyWriter w(e);
  // the energy T + V is the sum of the two functions above: not written out a second time
  std::vector<ex> values;
  std::vector<std::size_t> written;
  bool mass_matrix_formed = false;
  std::size_t n = e.num_velocities(), nq = e.symbols.coordinates.size();
  for (std::size_t i = 0; i < e.first_integrals.size(); ++i) {
    const FirstIntegral& f = e.first_integrals[i];
    if ((f.expression - e.kinetic_energy - e.potential_energy).is_zero()) {
      w.line(fmt::format("out[{}] = kinetic_energy(t, x, p) + potential_energy(t, x, p);", i));
    } else if (f.mass_matrix_row >= 0) {
      // the momentum as M's row times the velocities (derive/equations.hpp: FirstIntegral)
      if (!mass_matrix_formed) w.line(fmt::format("T M[{}];", n * n)), w.line("mass_matrix(t, x, p, M);");
      mass_matrix_formed = true;
      w.line(fmt::format("out[{}] = T(0);", i));
      w.line(fmt::format("for (std::size_t j = 0; j < {}; ++j) out[{}] += M[{} + j] * x[{} + j];", n, i,
                         std::size_t(f.mass_matrix_row) * n, nq));
    } else {
      values.push_back(f.expression), written.push_back(i);
    }
  }
  w.assign(values, [&](std::size_t k, const std::string& code) { return fmt::format("out[{}] = {};", written[k], code); });
  return out + function("/// The first integrals' values, in first_integral_names order. out: num_first_integrals.\n",
                        "void first_integrals(T t, const T* x, const T* p, T* out)",
                        w.finish("(void)t; (void)x; (void)p; (void)out;"));
}

// the detail namespace: the input type that keeps u out of deducing T, the batched sin and cos and
// the piecewise functions (cpp_piecewise.hpp) when a function uses them, and the LDLᵀ of M (which a model solved by the articulated-body recursion does
// not use: its functions take M⁻¹ from the tree)
std::string detail_functions(const Equations& e, std::size_t n, bool with_ldlt, bool with_sin_cos, bool with_constants,
                             bool with_clamp, bool with_magnitude, bool with_atan_ratio) {
  std::string out =
      "namespace detail {\n\n"
      "/// The input pointer does not take part in deducing T, so a model without\n"
      "/// inputs can be called with u = nullptr.\n"
      "template <class T>\nstruct input_type {\n  using type = T;\n};\n"
      "template <class T>\nusing input_t = typename input_type<T>::type;\n\n";
  if (with_constants) out += cpp_constant_function();
  if (with_clamp || with_magnitude || with_atan_ratio) out += piecewise_functions(with_clamp, with_magnitude, with_atan_ratio);
  if (with_sin_cos) out += sin_cos_function();
  if (with_ldlt) out += mass_matrix_factorization(e, n);
  return out + "}  // namespace detail\n\n";
}

std::string bool_list(const std::vector<bool>& flags) {
  std::string out;
  for (bool c : flags) out += std::string(out.empty() ? "" : ", ") + (c ? "true" : "false");
  return out;
}

// every function of the header but the detail namespace, in the header's order
std::string all_functions(const Equations& e) {
  std::string functions = constrained_solver(e);
  MassMatrixAndForcing mass_matrix_and_forcing = mass_matrix_and_forcing_code(e);
  bool tree_pass = jacobian_takes_tree_pass(e, mass_matrix_and_forcing.straight_line_operations);
  // the loops' templates and tables come first: mass_matrix_and_forcing may call them
  if (dynamics_form(e) == DynamicsForm::newton_euler) functions += tree_gradient_loops_function(e, mass_matrix_and_forcing.by_loops);
  std::string gradient = newton_euler_gradient_function(e);
  std::string acceleration_gradient = tree_pass ? tree_acceleration_gradient_function(e) : "";
  if (!tree_pass && dynamics_form(e) == DynamicsForm::newton_euler) {
    std::string fused = closed_form_acceleration_gradient_functions(e, mass_matrix_and_forcing.operations, gradient);
    if (!fused.empty()) gradient = std::move(fused), tree_pass = true;
  }
  functions += mass_matrix_and_forcing.function + mass_matrix_function(e) + forcing_function(e) + factored_accelerations_function(e) + rhs_function(e) +
               gradient + acceleration_gradient + jacobian_state_function(e, tree_pass) + jacobian_input_function(e) + linearization_function(e);
  functions += e.kinetic_energy_from_mass_matrix
                   ? kinetic_energy_from_mass_matrix_function(e)
                   : scalar_function(e, "kinetic_energy", e.kinetic_energy,
                                     "/// Kinetic energy T(q, q', t). x: num_states; p: num_parameters.\n");
  functions += scalar_function(e, "potential_energy", e.potential_energy,
                               "/// Potential energy V(q, t) of gravity and [energy] potential. x: num_states; p: num_parameters.\n");
  functions += outputs_function(e);
  functions += first_integrals_function(e);
  return functions + constraint_functions(e) + drawing_functions(e);
}

std::string source_name(const std::string& path) {
  std::string base = path.substr(path.find_last_of('/') + 1);
  return path.find("models/") != std::string::npos || path.rfind("models", 0) == 0 ? "models/" + base : base;
}

std::string quaternion_list(const Equations& e) {
  std::string out;
  for (const auto& q : e.quaternions)
    for (std::size_t c : q) out += (out.empty() ? "" : ", ") + std::to_string(c);
  return out;
}

}  // namespace

std::string emit_cpp_header(const Equations& given) {
  // a joint tree's rhs in the form eomgen chooses (the articulated-body algorithm or M = L D Lᵀ)
  std::optional<Equations> factored;
  if (given.joint_tree_accelerations() && !rhs_takes_articulated_bodies(given)) {
    factored = given;
    factored->newton_euler()->joint_tree_accelerations.reset();
  }
  const Equations& e = factored ? *factored : given;
  const Symbols& s = e.symbols;
  const DynamicsForm form = dynamics_form(e);
  std::size_t n = s.num_coordinates(), k = e.num_velocities();
  std::vector<std::string> velocities, states = s.coordinate_names, outputs;
  for (const auto& v : s.velocities) velocities.push_back(v.get_name());
  std::vector<std::string> definitions = velocities;
  for (std::size_t i = 0; i < e.pseudo_velocity_definitions.size(); ++i)
    definitions[i] = canonical_text(e.pseudo_velocity_definitions[i].expression);
  states.insert(states.end(), velocities.begin(), velocities.end());
  for (const NamedSymbolic& o : e.outputs) outputs.push_back(o.name);
  std::vector<double> state = s.initial_coordinates;
  state.insert(state.end(), s.initial_velocities.begin(), s.initial_velocities.end());

  std::string members, values;
  for (std::size_t i = 0; i < s.parameters.size(); ++i) {
    members += fmt::format("  Scalar {} = Scalar({});\n", parameter_member_name(s.parameter_names[i]),
                           format_number(s.parameter_defaults[i]));
    values += (values.empty() ? "" : ", ") + parameter_member_name(s.parameter_names[i]);
  }

  std::string functions = all_functions(e);
  bool uses_constants = functions.find("detail::constant<T>(") != std::string::npos;
  bool uses_clamp = functions.find("detail::clamp(") != std::string::npos || functions.find("detail::below(") != std::string::npos;
  bool uses_magnitude =
      functions.find("detail::magnitude(") != std::string::npos || functions.find("detail::sign(") != std::string::npos;
  bool uses_atan_ratio = functions.find("detail::atan_ratio(") != std::string::npos;
  std::string out = fmt::format(
      "// Generated by eomgen {0} from {1}. Do not edit: change the model file and regenerate.\n"
      "// {2}: {3} (method {4}, {5} degree{6} of freedom).\n"
      "// {12}\n"
      "#pragma once\n\n#include <array>\n#include <cmath>\n#include <cstddef>\n{14}\n"
      "namespace eomgen::models::{2} {{\n\n"
      "inline constexpr std::size_t num_coordinates = {7};\n"
      "inline constexpr std::size_t num_velocities = {13};\n"
      "inline constexpr std::size_t num_states = {8};\n"
      "inline constexpr std::size_t num_parameters = {9};\n"
      "inline constexpr std::size_t num_inputs = {10};\n"
      "inline constexpr std::size_t num_outputs = {11};\n"
      "inline constexpr const char* method = \"{4}\";\n\n",
      version_string, source_name(e.source), e.model_name, e.title, e.method, e.degrees_of_freedom,
      e.degrees_of_freedom == 1 ? "" : "s", n, n + k, s.parameters.size(), s.inputs.size(), e.outputs.size(),
      header_summary(e, functions),
      k, std::string(uses_clamp || uses_magnitude || uses_atan_ratio ? "#include <complex>\n" : "") + (uses_constants ? "#include <limits>\n" : ""));
  out += fmt::format(
      "inline constexpr std::array<const char*, num_parameters> parameter_names{{{{{}}}}};\n"
      "inline constexpr std::array<const char*, num_coordinates> coordinate_names{{{{{}}}}};\n"
      "inline constexpr std::array<const char*, num_velocities> velocity_names{{{{{}}}}};\n"
      "/// What each velocity of the state is in terms of der(q) (the definitions of pseudo-velocities).\n"
      "inline constexpr std::array<const char*, num_velocities> velocity_definitions{{{{{}}}}};\n"
      "inline constexpr std::array<const char*, num_states> state_names{{{{{}}}}};\n"
      "inline constexpr std::array<const char*, num_inputs> input_names{{{{{}}}}};\n"
      "inline constexpr std::array<const char*, num_outputs> output_names{{{{{}}}}};\n\n"
      "inline constexpr std::array<double, num_parameters> default_parameters{{{{{}}}}};\n"
      "inline constexpr std::array<double, num_states> default_state{{{{{}}}}};\n"
      "inline constexpr std::array<double, num_inputs> default_inputs{{{{{}}}}};\n\n"
      "/// A coordinate is cyclic when neither M nor f depends on it (Hiller §3.8).\n"
      "inline constexpr std::array<bool, num_coordinates> is_cyclic{{{{{}}}}};\n"
      "/// An angle: a coordinate the equations take through sin, cos or tan of a whole multiple of it.\n"
      "/// Its size is one radian in any units of length and time (what the analyses' tolerances use).\n"
      "inline constexpr std::array<bool, num_coordinates> is_angle{{{{{}}}}};\n\n"
      "/// Ball and free joints: the coordinates w, x, y, z of each quaternion (R is that of q/|q|, and\n"
      "/// the motion keeps |q|: a zero eigenvalue of every linearization, left out of verdicts).\n"
      "inline constexpr std::size_t num_quaternions = {};\n"
      "inline constexpr std::array<std::size_t, 4 * num_quaternions> quaternion_coordinates{{{{{}}}}};\n\n"
      "/// T + V is conserved when the inputs are zero (no dissipation, no applied forces,\n"
      "/// scleronomic, T a quadratic form in the velocities): what an energy-drift check may rely on.\n"
      "inline constexpr bool conserves_energy_without_inputs = {};\n\n"
      "/// Hamilton's equations with H = T(p) + V(q): Störmer–Verlet in canonical variables is explicit.\n"
      "inline constexpr bool separable_hamiltonian = {};\n\n",
      quoted_list(s.parameter_names), quoted_list(s.coordinate_names), quoted_list(velocities), quoted_list(definitions),
      quoted_list(states),
      quoted_list(s.input_names), quoted_list(outputs), number_list(s.parameter_defaults), number_list(state),
      number_list(s.input_defaults), bool_list(cyclic_coordinates(e)), bool_list(angle_coordinates(e)),
      e.quaternions.size(), quaternion_list(e),
      e.conserves_energy_without_inputs ? "true" : "false",
      separable_hamiltonian(e) ? "true" : "false");
  out += fmt::format(
      "/// The parameters by name, with the model's defaults; values() gives them in\n"
      "/// parameter_names order, as the functions below take them.\n"
      "template <class Scalar>\nstruct Parameters {{\n{}"
      "  std::array<Scalar, num_parameters> values() const {{ return {{{{{}}}}}; }}\n}};\n\n",
      members, values);
  out += constraint_declarations(e);
  out += detail_functions(e, k, form != DynamicsForm::particle_tree, functions.find("detail::sin_cos(") != std::string::npos,
                          uses_constants,
                          uses_clamp, uses_magnitude, uses_atan_ratio);
  out += functions;
  out += fmt::format("}}  // namespace eomgen::models::{}\n", e.model_name);
  return out;
}

}  // namespace eomgen
