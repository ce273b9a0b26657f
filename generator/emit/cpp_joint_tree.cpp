#include "emit/cpp_joint_tree.hpp"

#include <fmt/format.h>

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

namespace {

// the body of detail::inverse_dynamics_gradient: a tangent sweep through τ's code, or with
// `closed_form` the bodies' part in closed form and a sweep through the applied part alone
std::string inverse_dynamics_gradient_body(const Equations& e, bool closed_form) {
  const Symbols& s = e.symbols;
  std::size_t n = e.num_velocities(), W = s.num_coordinates() + n;
  BodyWriter w(e);
  std::vector<ex> directions(s.coordinates.begin(), s.coordinates.end());
  directions.insert(directions.end(), s.velocities.begin(), s.velocities.end());
  const std::vector<ex>& swept = closed_form ? e.bodies_gradient->applied_inverse_dynamics : e.inverse_dynamics;
  TangentSweep sweep(w, directions);
  sweep.follow(w.write_intermediates_of(swept));
  CseBatch tau = w.reduced_batch(swept);
  sweep.follow(tau);
  std::vector<ex> entries;
  for (std::size_t i = 0; i < n; ++i)
    for (const ex& d : sweep.derivatives(tau.outputs[i])) entries.push_back(d);
  std::size_t nq = s.num_coordinates();
  const InverseDynamicsGradient* bodies = closed_form ? &e.bodies_gradient->closed_form : nullptr;
  for (std::size_t i = 0; i < n && bodies; ++i) {
    for (std::size_t j = 0; j < nq; ++j) entries[i * W + j] += bodies->coordinates(unsigned(i), unsigned(j));
    for (std::size_t j = 0; j < n; ++j) entries[i * W + nq + j] += bodies->velocities(unsigned(i), unsigned(j));
  }
  w.assign(entries, [](std::size_t k, const std::string& code) { return fmt::format("F[{}] = {};", k, code); });
  if (bodies && bodies->loops) call_tree_gradient_loops(w, *bodies->loops, nq, W);
  return without_unused_locals(w.finish(all_unused + std::string(" (void)ddq;")));
}

}  // namespace

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
  bool closed_form = e.bodies_gradient && (n > compared_up_to || loops);
  std::string body = inverse_dynamics_gradient_body(e, closed_form);
  if (e.bodies_gradient && !closed_form) {
    std::string closed = inverse_dynamics_gradient_body(e, true);
    auto operations = [&](const std::string& b) { return count_operations(function("", signature, b), "inverse_dynamics_gradient", n); };
    closed_form = operations(closed) < operations(body);
    if (closed_form) body = std::move(closed);
  }
  return tree_gradient_loops_function(e) + "namespace detail {\n\n" +
         function(fmt::format(fmt::runtime(loops
                                  ? "/// d tau/d(q, q') of the Newton-Euler inverse dynamics tau = M q'' - f, q'' held (the bodies'\n"
                                    "/// part by detail::hinge_tree_gradient's loops; a tangent sweep through the rest).\n"
                                    "/// ddq: {0}; F: {0}x{1}, row-major.\n"
                                  : closed_form
                                  ? "/// d tau/d(q, q') of the Newton-Euler inverse dynamics tau = M q'' - f, q'' held (the bodies'\n"
                                    "/// part in closed form, in world coordinates; a tangent sweep through the rest).\n"
                                    "/// ddq: {0}; F: {0}x{1}, row-major.\n"
                                  : "/// d tau/d(q, q') of the Newton-Euler inverse dynamics tau = M q'' - f, q'' held (a\n"
                                    "/// tangent sweep through the frames' recursion). ddq: {0}; F: {0}x{1}, row-major.\n"),
                              n, W),
                  signature, body) +
         "}  // namespace detail\n\n";
}

// a tree's M and f are long code, most of a 21-joint tree's header when mass_matrix, forcing and
// factored_accelerations each wrote them: written once, here, and those three call it
std::string mass_matrix_and_forcing_function(const Equations& e) {
  if (dynamics_form(e) != DynamicsForm::newton_euler) return "";
  std::size_t n = e.num_velocities(), upper = n * (n + 1) / 2;
  BodyWriter w(e);
  std::vector<ex> entries = upper_triangle(e.mass_matrix, n);
  entries.insert(entries.end(), e.forcing.begin(), e.forcing.end());
  std::vector<std::string> code = w.batch(entries);
  write_symmetric(w, std::vector<std::string>(code.begin(), code.begin() + long(upper)), n, "M");
  for (std::size_t i = 0; i < n; ++i) w.line(fmt::format("f[{}] = {};", i, code[upper + i]));
  return "namespace detail {\n\n" +
         function(fmt::format("/// M and f of M q'' = f together, for mass_matrix, forcing and factored_accelerations.\n"
                              "/// M: {0}x{0}, row-major; f: {0}.\n", n),
                  // inlined where it is called: a call passed M through memory, and rhs took 12-18 % longer
                  "#if defined(__GNUC__)\n__attribute__((always_inline))\n#endif\n"
                  "inline void mass_matrix_and_forcing(T t, const T* x, const input_t<T>* u, const T* p, T* M, T* f)",
                  w.finish(all_unused)) +
         "}  // namespace detail\n\n";
}

// q'' and the factors of M for jacobian_state of a tree, whose own code then is the sweep's call and
// the solves: rhs's code is not written a second time (it was most of a 21-joint tree's header)
std::string factored_accelerations_function(const Equations& e) {
  if (dynamics_form(e) != DynamicsForm::newton_euler) return "";
  std::size_t n = e.num_velocities();
  BodyWriter w(e);
  w.line(fmt::format("T M[{}];", n * n));
  w.line("detail::mass_matrix_and_forcing(t, x, u, p, M, ddq);");
  w.line("detail::ldlt_factor(M, L, D);");
  w.line("detail::ldlt_solve(L, D, ddq);");
  return "namespace detail {\n\n" +
         function(fmt::format("/// The accelerations M^-1 f into ddq and M = L^T D L (ldlt_factor) into L and D, as rhs computes them.\n"
                              "/// ddq: {0}; L: {0}x{0}, row-major; D: {0}.\n", n),
                  "void factored_accelerations(T t, const T* x, const input_t<T>* u, const T* p, T* ddq, T* L, T* D)",
                  w.finish(all_unused)) +
         "}  // namespace detail\n\n";
}

}  // namespace eomgen
