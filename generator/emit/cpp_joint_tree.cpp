#include "emit/cpp_joint_tree.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "emit/cpp_avx_dispatch.hpp"
#include "emit/cpp_ldlt.hpp"
#include "emit/cpp_register_allocation.hpp"
#include "emit/operation_count.hpp"
#include "emit/tangent_sweep.hpp"
#include "emit/cpp_tree_gradient_loops.hpp"
#include "emit/dynamics_form.hpp"

namespace eomgen {

using GiNaC::ex;

void call_factored_accelerations(BodyWriter& w, std::size_t n) {
  w.line(fmt::format("T ddq[{}];", n));
  w.line(fmt::format("T L[{}];", n * n));
  w.line(fmt::format("T D[{}];", n));
  w.line("detail::factored_accelerations(t, x, u, p, ddq, L, D);");
}

std::string joint_tree_rhs_function(const Equations& e) {
  std::size_t n = e.symbols.num_coordinates(), k = e.num_velocities();
  bool pseudo = e.uses_pseudo_velocities();
  BodyWriter w(e);
  // q'' (s') and, for pseudo-velocities, q' = W s + w, in one batch
  std::vector<ex> outputs = e.joint_tree_accelerations()->accelerations;
  if (pseudo) outputs.insert(outputs.end(), e.coordinate_rates.begin(), e.coordinate_rates.end());
  auto values = w.batch(outputs);
  for (std::size_t i = 0; i < n; ++i) w.line(fmt::format("xdot[{}] = {};", i, pseudo ? values[k + i] : fmt::format("x[{}]", n + i)));
  for (std::size_t i = 0; i < k; ++i) w.line(fmt::format("xdot[{}] = {};", n + i, values[i]));
  return function(fmt::format("/// Explicit first-order form x' = [{}; {}''] with x = [q; {}], M {}'' = f solved by the\n"
                              "/// articulated-body algorithm over the joints (O(n), without forming M).\n"
                              "/// x, xdot: num_states = {}; u: num_inputs (may be null if none); p: num_parameters.\n",
                              pseudo ? "W s + w" : "q'", pseudo ? "s" : "q", pseudo ? "s" : "q'", pseudo ? "s" : "q", n + k),
                  "void rhs(T t, const T* x, const detail::input_t<T>* u, const T* p, T* xdot)", w.finish(all_unused));
}

bool rhs_takes_articulated_bodies(const Equations& e) {
  if (!e.joint_tree_accelerations()) return false;
  if (e.joint_tree_accelerations()->asked) return true;
  long articulated = count_operations(joint_tree_rhs_function(e), "rhs", 0);
  std::string ldlt = mass_matrix_factorization(e, e.num_velocities());
  long factored = mass_matrix_and_forcing_code(e).operations +
                  count_operations(ldlt, "ldlt_factor", 0) + count_operations(ldlt, "ldlt_solve", 0);
  return articulated < factored;
}

namespace {

// the state's variables, the directions of ∂τ/∂(q, q')
std::vector<ex> state_directions(const Symbols& s) {
  std::vector<ex> directions(s.coordinates.begin(), s.coordinates.end());
  directions.insert(directions.end(), s.velocities.begin(), s.velocities.end());
  return directions;
}

// ∂τ/∂(q, q') of `swept` (q'' held), n rows, by a tangent sweep that has followed the intermediates
// they use
std::vector<ex> swept_entries(BodyWriter& w, TangentSweep& sweep, const std::vector<ex>& swept, std::size_t n) {
  CseBatch tau = w.reduced_batch(swept);
  sweep.follow(tau);
  std::vector<ex> entries;
  for (std::size_t i = 0; i < n; ++i)
    for (const ex& d : sweep.derivatives(tau.outputs[i])) entries.push_back(d);
  return entries;
}

std::string written_into_F(std::size_t k, const std::string& code) { return fmt::format("F[{}] = {};", k, code); }

// the body of detail::inverse_dynamics_gradient: a tangent sweep through τ's code, or with
// `closed_form` the bodies' part in closed form and a sweep through the applied part alone
std::string inverse_dynamics_gradient_body(const Equations& e, bool closed_form) {
  const Symbols& s = e.symbols;
  std::size_t n = e.num_velocities(), W = s.num_coordinates() + n;
  BodyWriter w(e);
  std::vector<ex> directions = state_directions(s);
  const NewtonEulerRecursion& recursion = *e.newton_euler();
  const std::vector<ex>& swept = closed_form ? recursion.bodies_gradient->applied_inverse_dynamics : recursion.inverse_dynamics;
  TangentSweep sweep(w, directions);
  sweep.follow(w.write_intermediates_of(swept));
  std::vector<ex> entries = swept_entries(w, sweep, swept, n);
  std::size_t nq = s.num_coordinates();
  const InverseDynamicsGradient* bodies = closed_form ? recursion.bodies_gradient->expressions() : nullptr;
  for (std::size_t i = 0; i < n && bodies; ++i) {
    for (std::size_t j = 0; j < nq; ++j) entries[i * W + j] += bodies->coordinates(unsigned(i), unsigned(j));
    for (std::size_t j = 0; j < n; ++j) entries[i * W + nq + j] += bodies->velocities(unsigned(i), unsigned(j));
  }
  w.assign(entries, written_into_F);
  if (closed_form && recursion.bodies_gradient->loops()) call_tree_gradient_loops(w, e, nq, W);
  return without_unused_locals(w.finish(all_unused + std::string(" (void)ddq;")));
}

std::string in_detail(const std::string& functions) { return "namespace detail {\n\n" + functions + "}  // namespace detail\n\n"; }

// M_a and f_a of the applied part τ_a = M_a q'' − f_a (linear in q'')
struct AppliedMassMatrixAndForcing {
  GiNaC::matrix mass_matrix;
  std::vector<ex> forcing;
};
AppliedMassMatrixAndForcing applied_mass_matrix_and_forcing(BodyWriter& w, const std::vector<ex>& applied) {
  std::size_t n = applied.size();
  AppliedMassMatrixAndForcing a{GiNaC::matrix(unsigned(n), unsigned(n)), {}};
  GiNaC::exmap at_rest;
  for (const GiNaC::symbol& q : w.accelerations()) at_rest[q] = 0;
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < n; ++j) a.mass_matrix(unsigned(i), unsigned(j)) = applied[i].diff(w.accelerations()[j]).expand();
    a.forcing.push_back(-applied[i].subs(at_rest));
  }
  return a;
}

// M_a and f_a into M (zeros before) and f
void assign_applied_mass_matrix_and_forcing(BodyWriter& w, const std::vector<ex>& applied) {
  std::size_t n = applied.size();
  AppliedMassMatrixAndForcing a = applied_mass_matrix_and_forcing(w, applied);
  std::vector<ex> values;
  std::vector<std::string> targets;
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < n; ++j)
      if (ex m = a.mass_matrix(unsigned(i), unsigned(j)); !m.is_zero()) values.push_back(m), targets.push_back(fmt::format("M[{}]", i * n + j));
    values.push_back(a.forcing[i]), targets.push_back(fmt::format("f[{}]", i));
  }
  w.assign(values, targets);
}

// whether τ_a's M_a is ∂τ_a/∂q'': q'' must not enter τ_a through a quantity of the recursion (τ_a's
// symbols gathered in one walk, not one walk per quantity)
bool applied_part_apart(const Equations& e) {
  const NewtonEulerRecursion& recursion = *e.newton_euler();
  GiNaC::exset in_applied;
  for (const ex& tau : recursion.bodies_gradient->applied_inverse_dynamics)
    for (auto it = tau.preorder_begin(); it != tau.preorder_end(); ++it)
      if (GiNaC::is_a<GiNaC::symbol>(*it)) in_applied.insert(*it);
  return std::none_of(recursion.acceleration_intermediates.begin(), recursion.acceleration_intermediates.end(),
                      [&](const Intermediate& i) { return in_applied.count(i.symbol) > 0; });
}

// the body of detail::tree_acceleration_gradient: the applied part's M and f (τ_a = M_a q'' − f_a,
// linear in q'') with the tables, the bodies' M and f from the loops' pass at q'' = 0, its solve,
// and the pass again at the accelerations for ∂τ/∂(q, q')
std::string tree_acceleration_gradient_body(const Equations& e) {
  const Symbols& s = e.symbols;
  std::size_t n = e.num_velocities(), nq = s.num_coordinates();
  const std::vector<ex>& applied = e.newton_euler()->bodies_gradient->applied_inverse_dynamics;
  BodyWriter w(e);
  TangentSweep sweep(w, state_directions(s));
  sweep.follow(w.write_intermediates_of(applied));
  w.line(fmt::format("T ddq[{}] = {{}};", n));  // the pass's first accelerations, M's and f's
  call_tree_tables(w, e);
  w.line(fmt::format("T M[{}] = {{}};", n * n));
  w.line(fmt::format("T f[{}];", n));
  assign_applied_mass_matrix_and_forcing(w, applied);
  // the pass adds the bodies' M and f, then the solve sets q'' = M^-1 f, the applied part's ∂τ and the
  // root joint's motion at them, and the pass adds the bodies' ∂τ
  w.line(fmt::format("tree_gradient_pass<true>(tree, ddq, {}, {}, F, {}, M, f, [&] {{", nq, nq + n, n));
  w.line("ldlt_factor(M, L, D);");
  w.line(fmt::format("for (std::size_t i = 0; i < {}; ++i) ddq[i] = f[i];", n));
  w.line("ldlt_solve(L, D, ddq);");
  w.fresh_subexpressions("cq");  // as in straight_tree_acceleration_gradient_body
  w.assign(swept_entries(w, sweep, applied, n), written_into_F);
  call_root_motion(w, e);
  w.line("});");
  return without_unused_locals(w.finish(all_unused));
}

// the body of detail::tree_acceleration_gradient in straight-line code, for a tree whose gradient is
// in closed form: M and f from the composite inertias and the forces at q'' = 0 that the gradient
// forms anyway (the applied part's added), their solve, and ∂τ/∂(q, q') at the solved q''. The
// intermediates that hold q'' are written after the solve, since M and f do not use them.
std::string straight_tree_acceleration_gradient_body(const Equations& e) {
  const Symbols& s = e.symbols;
  std::size_t n = e.num_velocities(), nq = s.num_coordinates(), W = nq + n;
  const BodiesGradient& bodies = *e.newton_euler()->bodies_gradient;
  const InverseDynamicsGradient& closed = *bodies.expressions();
  BodyWriter w(e);
  // M's and f's run in order of use too, though shorter than statement_order.cpp's cut: here it
  // holds the gradient's world-frame quantities, not only M's and f's (the 7-joint arm's 520
  // statements). Its AVX code 54.4 KB against 57.1, g++ -O2 of rhs and jacobian_state 5-10 %
  // faster (3.00-4.04 s against 3.10-4.39; the oblique tree 1.53-1.97 against 1.67-2.57), the
  // same speed (minima 0.82-1.05 µs against 0.85-0.93 in five alternations; the oblique tree's
  // 0.60-0.61 against 0.59-0.63)
  w.order_every_run();
  TangentSweep sweep(w, state_directions(s));
  sweep.follow(w.write_intermediates_of(bodies.applied_inverse_dynamics));
  AppliedMassMatrixAndForcing applied = applied_mass_matrix_and_forcing(w, bodies.applied_inverse_dynamics);
  std::vector<ex> mass_and_forcing;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i; j < n; ++j)
      mass_and_forcing.push_back(applied.mass_matrix(unsigned(i), unsigned(j)) + closed.mass_matrix(unsigned(i), unsigned(j)));
  for (std::size_t i = 0; i < n; ++i) mass_and_forcing.push_back(applied.forcing[i] - closed.bias[i]);
  std::vector<std::string> code = w.batch(mass_and_forcing);
  // only what ldlt_factor reads of M, and only the factor's entries copied out (not M's upper
  // half, a zeroed factor and all n² entries: the 7-joint arm's jacobian_state 3-4 % faster)
  w.line(fmt::format("T M[{}];", n * n));
  write_lower_triangle(w, std::vector<std::string>(code.begin(), code.end() - long(n)), n, "M");
  // the factors in local arrays, which g++ keeps in registers (through L and D, which might alias
  // each other, every step went through memory: the 7-joint arm's jacobian_state took 1.3-1.4 times
  // as long, g++ -O2 -march=native)
  w.line(fmt::format("T ddq[{}];", n));
  w.line("if (given_ddq) {");
  w.line(fmt::format("  for (std::size_t i = 0; i < {}; ++i) ddq[i] = given_ddq[i];", n));
  w.line("} else {");
  for (std::size_t i = 0; i < n; ++i) w.line(fmt::format("  ddq[{}] = {};", i, code[code.size() - n + i]));
  w.line(fmt::format("  T factor[{}];", n * n));
  w.line(fmt::format("  T pivots[{}];", n));
  w.line("  ldlt_factor(M, factor, pivots);");
  w.line("  ldlt_solve(factor, pivots, ddq);");
  for (std::size_t k : factor_entries(e, n)) w.line(fmt::format("  L[{0}] = factor[{0}];", k));
  w.line(fmt::format("  for (std::size_t i = 0; i < {}; ++i) D[i] = pivots[i];", n));
  w.line("}");
  // τ_a's code must not reuse M's and f's temporaries, which the sweep has not followed: their
  // tangents would count as zero (a gyroscopic torque's ∂τ/∂s lost its c's)
  w.fresh_subexpressions("cq");
  std::vector<ex> entries = swept_entries(w, sweep, bodies.applied_inverse_dynamics, n);
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < nq; ++j) entries[i * W + j] += closed.coordinates(unsigned(i), unsigned(j));
    for (std::size_t j = 0; j < n; ++j) entries[i * W + nq + j] += closed.velocities(unsigned(i), unsigned(j));
  }
  w.assign(entries, written_into_F);
  return without_unused_locals(w.finish(all_unused));
}

// The pass forms M and f in about the same time for any tree of a given size, the straight-line code
// in time with its operations. jacobian_state, g++ -O2, with the pass against factored_accelerations,
// by the operations of M and f per velocity: tests/crosscheck's 21-joint tree of oblique hinges
// (481) 7.5 µs against 9.1, its coupled hand (418) 3.25 against 3.50, its gantry hand (339) 3.46
// against 3.61; the quadruped (260) 8.0-8.1 against 7.8-7.9, example-robot-data's Romeo small
// (about 225) 12.1-12.5 against 11.8-12.0
constexpr long tree_pass_beyond_operations_per_velocity = 300;

}  // namespace

bool jacobian_takes_tree_pass(const Equations& e, long mass_matrix_and_forcing_operations) {
  return e.gradient_loops() && mass_matrix_and_forcing_operations > tree_pass_beyond_operations_per_velocity * long(e.num_velocities()) &&
         applied_part_apart(e);
}

namespace {

constexpr const char* tree_acceleration_gradient_signature =
    "void tree_acceleration_gradient(T t, const T* x, const input_t<T>* u, const T* p, T* L, T* D, T* F)";
constexpr const char* given_accelerations_signature =
    "void tree_acceleration_gradient(T t, const T* x, const input_t<T>* u, const T* p, const T* given_ddq, T* L, T* D, T* F)";

// A straight-line gradient of `operations` as the header writes it: from avx_dispatch_from_operations
// on with its AVX copy, and the two compiled by g++ with priority colouring (cpp_register_allocation)
std::string sized_for_its_operations(const std::string& gradient, long operations) {
  if (operations < avx_dispatch_from_operations) return gradient;
  return with_priority_register_allocation(with_avx_dispatch(gradient));
}

}  // namespace

std::string tree_acceleration_gradient_function(const Equations& e) {
  std::size_t n = e.num_velocities(), W = e.symbols.num_coordinates() + n;
  return in_detail(
      function(fmt::format("/// For jacobian_state: M = L^T D L (into L and D) and f from detail::tree_gradient_pass at\n"
                           "/// q'' = 0, q'' = M^-1 f, and d tau/d(q, q') at those q'' from the same pass (F: {0}x{1},\n"
                           "/// row-major), where factored_accelerations would form M and f a second time.\n",
                           n, W),
               tree_acceleration_gradient_signature, tree_acceleration_gradient_body(e)));
}

// Chosen by operations, as the gradient's forms are: the 7-joint arm's function has 5,618 where
// factored_accelerations' M and f had 1,499 and the gradient 5,348, and its jacobian_state ran 1.15
// to 1.2 times as fast (g++ -O2 -march=native 0.62 µs against 0.73; -O2 1.56-1.71 against 1.81-1.84),
// measured_arm's 1.4 times, oblique_tree's 1.05-1.1 (tests/benchmarks/rigid_body_trees.md)
std::string closed_form_acceleration_gradient_functions(const Equations& e, long factored_operations, const std::string& gradient_function) {
  const NewtonEulerRecursion* recursion = e.newton_euler();
  // (a model with multipliers solves its own system in jacobian_state: M and f here would serve nothing)
  if (dynamics_form(e) != DynamicsForm::newton_euler || e.has_multipliers || !recursion->bodies_gradient || e.gradient_loops() ||
      !applied_part_apart(e))
    return "";
  std::size_t n = e.num_velocities(), W = e.symbols.num_coordinates() + n;
  std::string fused = function(fmt::format("/// d tau/d(q, q') of the Newton-Euler inverse dynamics tau = M q'' - f at the given q''\n"
                                           "/// (linearization), or, for jacobian_state with given_ddq null, at q'' = M^-1 f, with M =\n"
                                           "/// L^T D L into L and D: M and f from the composite inertias and forces at q'' = 0 of the\n"
                                           "/// bodies' part in closed form (in the world's axes or a link's, whichever takes fewer\n"
                                           "/// operations), a tangent sweep through the rest.\n"
                                           "/// given_ddq: {0} or null; F: {0}x{1}, row-major.\n",
                                           n, W),
                               given_accelerations_signature, straight_tree_acceleration_gradient_body(e));
  long ldlt = long(n * n * n / 6 + 3 * n * n);
  long apart = factored_operations + ldlt + count_operations(gradient_function, "inverse_dynamics_gradient", n);
  long operations = count_operations(fused, "tree_acceleration_gradient", n);
  if (operations >= apart) return "";
  fused = sized_for_its_operations(fused, operations);
  // inverse_dynamics_gradient (linearization's, at given q'') by the same code, not written twice
  std::string at_given = function(fmt::format("/// d tau/d(q, q') of the Newton-Euler inverse dynamics tau = M q'' - f, q'' held, by\n"
                                              "/// tree_acceleration_gradient at the given q''. ddq: {0}; F: {0}x{1}, row-major.\n",
                                              n, W),
                                  "void inverse_dynamics_gradient(T t, const T* x, const T* ddq, const input_t<T>* u, const T* p, T* F)",
                                  fmt::format("  T L[{}];\n  T D[{}];\n  tree_acceleration_gradient(t, x, u, p, ddq, L, D, F);\n", n * n, n));
  return in_detail(fused + at_given);
}

std::string newton_euler_gradient_function(const Equations& e) {
  if (dynamics_form(e) != DynamicsForm::newton_euler) return "";
  std::size_t n = e.num_velocities(), W = e.symbols.num_coordinates() + n;
  const char* signature = "void inverse_dynamics_gradient(T t, const T* x, const T* ddq, const input_t<T>* u, const T* p, T* F)";
  // the closed form costs about a thousand operations per link, the sweep a few hundred per pair
  // of a joint and one it carries: up to a dozen joints both are written and the one with fewer
  // operations kept (a 5-joint tree's sweep has 4,014 where the closed form has 4,824, and ran
  // 1.24 times as fast; a 7-joint arm's 10,695 against 6,678); beyond, the closed form, whose
  // share grows with the depth (a 21-joint tree: 44,773 against 25,942), without the sweep's
  // second of generating
  constexpr std::size_t compared_up_to = 12;
  bool loops = e.gradient_loops();
  bool bodies_apart = e.newton_euler()->bodies_gradient.has_value();
  bool closed_form = bodies_apart && (n > compared_up_to || loops);
  std::string body = inverse_dynamics_gradient_body(e, closed_form);
  if (bodies_apart && !closed_form) {
    std::string closed = inverse_dynamics_gradient_body(e, true);
    auto operations = [&](const std::string& b) { return count_operations(function("", signature, b), "inverse_dynamics_gradient", n); };
    closed_form = operations(closed) < operations(body);
    if (closed_form) body = std::move(closed);
  }
  std::string gradient =
         function(fmt::format(fmt::runtime(loops
                                  ? "/// d tau/d(q, q') of the Newton-Euler inverse dynamics tau = M q'' - f, q'' held (the bodies'\n"
                                    "/// part by detail::tree_bodies_gradient's loops; a tangent sweep through the rest).\n"
                                    "/// ddq: {0}; F: {0}x{1}, row-major.\n"
                                  : closed_form
                                  ? "/// d tau/d(q, q') of the Newton-Euler inverse dynamics tau = M q'' - f, q'' held (the bodies'\n"
                                    "/// part in closed form, in the world's axes or a link's; a tangent sweep through the rest).\n"
                                    "/// ddq: {0}; F: {0}x{1}, row-major.\n"
                                  : "/// d tau/d(q, q') of the Newton-Euler inverse dynamics tau = M q'' - f, q'' held (a\n"
                                    "/// tangent sweep through the frames' recursion). ddq: {0}; F: {0}x{1}, row-major.\n"),
                              n, W),
                  signature, body);
  if (!loops) gradient = sized_for_its_operations(gradient, count_operations(gradient, "inverse_dynamics_gradient", n));
  return in_detail(gradient);
}

namespace {

// The time of M and f by the loops, in operations of straight-line code (about 0.25 ns each, g++
// -O2): each link of the tables (a fixed one too) about 95 ns, each pair of a joint and one at or
// above it 3.4 ns (per pair of their columns), each root joint 570 ns, fit to the loops' times on
// chains of 9 and 16 oblique hinges and checked on the others below. M and f alone, loops against
// straight-line code (links, pairs, straight-line operations): chains of 9, 10, 12 and 16 oblique
// hinges 0.92, 0.88, 0.77 and 0.68 (9, 45, 4,332 to 16, 136, 10,528); the 21-joint tree 0.87 (21,
// 90, 10,105); hinge_chain 0.96 (20, 210, 12,019); the 21-joint tree below a free torso 0.85 (22,
// 90, 13,098) and beside a free body 1.10 (22, 90, 10,391); floating_snake 1.17 (17, 136, 10,310);
// the quadruped 1.55 (13, 24, 4,687); chains of 9, 12 and 16 rods on hinges along their axes 5.1,
// 1.75 and 1.49 (1,787 to 4,614 operations); example-robot-data's Talos (45 links for 32
// velocities, 15,221) 1.37 and TIAGo Pro (34 for 23, 14,129) 1.08, where per velocity the counts
// had looked like the 21-joint tree's. A link of several columns (a ball joint) about 190
// operations more per column beyond its first: a ragdoll of seven ball joints and four hinges below
// a free root (tests/crosscheck/mjcf/ball_ragdoll.xml without its wrists and right ankle, 31
// velocities) took 3.40 µs for rhs by the loops against 2.58 by straight-line code of 8,000
// operations, the loops' M and f thus about 8,000 + 0.82 µs / 0.25 ns = 11,280 where links and
// pairs alone count 8,596: 2,684 more for its 14 columns beyond its links' first.
long looped_mass_matrix_and_forcing_operations(const TreeLinkTables& links) {
  long pairs = 0, more_columns = 0;
  for (std::size_t k = 0; k < links.parent.size(); ++k) {
    more_columns += long(std::max<std::size_t>(links.velocity[k].size(), 1) - 1);
    for (int j = int(k); j >= 0; j = links.parent[std::size_t(j)])
      pairs += long(links.velocity[k].size() * links.velocity[std::size_t(j)].size());
  }
  return 380 * long(links.parent.size()) + 190 * more_columns + 14 * pairs + 2300 * long(links.roots.size());
}

// detail::mass_matrix_and_forcing's declaration, inlined where it is called: a call passed M
// through memory, and rhs took 12-18 % longer
constexpr const char* mass_matrix_and_forcing_signature =
    "#if defined(__GNUC__)\n__attribute__((always_inline))\n#endif\n"
    "inline void mass_matrix_and_forcing(T t, const T* x, const input_t<T>* u, const T* p, T* M, T* f)";

std::string straight_line_mass_matrix_and_forcing(const Equations& e) {
  std::size_t n = e.num_velocities(), upper = n * (n + 1) / 2;
  BodyWriter w(e);
  std::vector<ex> entries = upper_triangle(e.mass_matrix, n);
  entries.insert(entries.end(), e.forcing.begin(), e.forcing.end());
  std::vector<std::string> code = w.batch(entries);
  write_symmetric(w, std::vector<std::string>(code.begin(), code.begin() + long(upper)), n, "M");
  for (std::size_t i = 0; i < n; ++i) w.line(fmt::format("f[{}] = {};", i, code[upper + i]));
  return in_detail(function(fmt::format("/// M and f of M q'' = f together, for mass_matrix, forcing and factored_accelerations.\n"
                                        "/// M: {0}x{0}, row-major; f: {0}.\n", n),
                            mass_matrix_and_forcing_signature, w.finish(all_unused)));
}

// the applied part's M and f, then the bodies' from the loops' world pass at q'' = 0
std::string looped_mass_matrix_and_forcing(const Equations& e) {
  std::size_t n = e.num_velocities();
  BodyWriter w(e);
  w.line(fmt::format("for (std::size_t i = 0; i < {}; ++i) M[i] = T(0);", n * n));
  assign_applied_mass_matrix_and_forcing(w, e.newton_euler()->bodies_gradient->applied_inverse_dynamics);
  call_tree_mass_matrix_and_forcing(w, e);
  return in_detail(function(fmt::format("/// M and f of M q'' = f together, for mass_matrix, forcing and factored_accelerations: the\n"
                                        "/// bodies' part by detail::tree_loops_mass_matrix_and_forcing's loops over the links.\n"
                                        "/// M: {0}x{0}, row-major; f: {0}.\n", n),
                            mass_matrix_and_forcing_signature, without_unused_locals(w.finish(all_unused))));
}

}  // namespace

// a tree's M and f are long code, most of a 21-joint tree's header when mass_matrix, forcing and
// factored_accelerations each wrote them: written once, here, and those three call it
MassMatrixAndForcing mass_matrix_and_forcing_code(const Equations& e) {
  if (dynamics_form(e) != DynamicsForm::newton_euler) return {};
  MassMatrixAndForcing code;
  code.function = straight_line_mass_matrix_and_forcing(e);
  code.straight_line_operations = count_operations(code.function, "mass_matrix_and_forcing", 0);
  code.operations = code.straight_line_operations;
  if (!e.gradient_loops() || !applied_part_apart(e)) return code;
  long looped = looped_mass_matrix_and_forcing_operations(*e.gradient_loops());
  code.operations = std::min(looped, code.straight_line_operations);
  // where rhs takes the articulated-body algorithm and jacobian_state the tree's pass, M and f serve
  // mass_matrix, forcing, jacobian_input and linearization alone: the loops then, for the header's
  // size (TIAGo's straight-line M and f were 680 KB of its 2 MB)
  bool rhs_and_jacobian_without = e.joint_tree_accelerations() && jacobian_takes_tree_pass(e, code.straight_line_operations);
  if (looped < code.straight_line_operations || rhs_and_jacobian_without) {
    code.function = looped_mass_matrix_and_forcing(e);
    code.by_loops = true;
  }
  return code;
}

// q'' and the factors of M for jacobian_state of a tree, whose own code then is the sweep's call and
// the solves: rhs's code is not written a second time (it was most of a 21-joint tree's header).
std::string factored_accelerations_function(const Equations& e) {
  if (dynamics_form(e) != DynamicsForm::newton_euler) return "";
  std::size_t n = e.num_velocities();
  BodyWriter w(e);
  w.line(fmt::format("T M[{}];", n * n));
  w.line("detail::mass_matrix_and_forcing(t, x, u, p, M, ddq);");
  w.line("detail::ldlt_factor(M, L, D);");
  w.line("detail::ldlt_solve(L, D, ddq);");
  // For double, flattened: ldlt_factor and ldlt_solve, which other functions call too, were left
  // as calls, and M, L and D went through memory between them (rhs, g++ -O2, one process: the
  // 7-joint arm 240 → 209 ns, the quadruped 1.29 → 0.93 µs, the 21-joint tree 1.96 → 1.91 µs, the
  // oblique tree unchanged). Not the template: for a user's automatic-differentiation T, flatten
  // would inline every operation's own code into M's thousands.
  const char* for_double =
      "#if defined(__GNUC__)\n"
      "/// factored_accelerations for double, with the factorization and the solve inlined.\n"
      "__attribute__((flatten)) inline void factored_accelerations(double t, const double* x, const double* u, const double* p, "
      "double* ddq, double* L, double* D) {\n"
      "  factored_accelerations<double>(t, x, u, p, ddq, L, D);\n"
      "}\n"
      "#endif\n\n";
  return "namespace detail {\n\n" +
         function(fmt::format("/// The accelerations M^-1 f into ddq and M = L^T D L (ldlt_factor) into L and D, as rhs computes them.\n"
                              "/// ddq: {0}; L: {0}x{0}, row-major; D: {0}.\n", n),
                  "void factored_accelerations(T t, const T* x, const input_t<T>* u, const T* p, T* ddq, T* L, T* D)",
                  w.finish(all_unused)) +
         for_double + "}  // namespace detail\n\n";
}

}  // namespace eomgen
