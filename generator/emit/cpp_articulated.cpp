#include "emit/cpp_articulated.hpp"

#include <algorithm>
#include <functional>
#include <map>

#include <fmt/format.h>

#include "emit/cpp_body_writer.hpp"
#include "emit/cpp_expression.hpp"
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

// The tree's vectors as local arrays name[i][c] over the components c that are not zero in every
// vector (a planar tree: x and y), so that the loops below are the same code for every link.
class TreeArrays {
 public:
  TreeArrays(BodyWriter& w, const TreeInverseDynamics& tree, bool derivatives) : w_(w), tree_(tree) {
    for (unsigned c = 0; c < 3; ++c) {
      bool used = false;
      for (const std::vector<Vector3>* set : sets(derivatives))
        for (const Vector3& v : *set) used = used || !v[c].is_zero();
      if (used) components_.push_back(c);
    }
    std::size_t n = tree.axes.size();
    w.line(fmt::format("static constexpr int coupling[{}] = {{{}}};", n * n, integer_list(tree.coupling)));
    write("mass", tree.subtree_masses);
    write("axis", tree.axes);
    if (!derivatives) return;
    write("by_coordinate", tree.acceleration_by_coordinate);
    write("by_velocity", tree.acceleration_by_velocity);
  }

  // Σ_c a[i][c] b[k][c] as C++ text
  std::string dot(const std::string& a, const std::string& i, const std::string& b, const std::string& k) const {
    std::string out;
    for (std::size_t c = 0; c < components_.size(); ++c)
      out += fmt::format("{}{}[{}][{}] * {}[{}][{}]", c ? " + " : "", a, i, c, b, k, c);
    return out.empty() ? "T(0)" : "(" + out + ")";
  }

 private:
  std::vector<const std::vector<Vector3>*> sets(bool derivatives) const {
    if (!derivatives) return {&tree_.axes};
    return {&tree_.axes, &tree_.acceleration_by_coordinate, &tree_.acceleration_by_velocity};
  }

  static std::string integer_list(const std::vector<int>& values) {
    std::string out;
    for (int v : values) out += (out.empty() ? "" : ", ") + std::to_string(v);
    return out;
  }

  void write(const std::string& name, const std::vector<ex>& scalars) {
    w_.line(fmt::format("T {}[{}];", name, scalars.size()));
    w_.assign(scalars, [&](std::size_t k, const std::string& code) { return fmt::format("{}[{}] = {};", name, k, code); });
  }

  void write(const std::string& name, const std::vector<Vector3>& vectors) {
    std::size_t C = std::max<std::size_t>(1, components_.size());
    std::vector<ex> entries;
    for (const Vector3& v : vectors)
      for (unsigned c : components_) entries.push_back(v[c]);
    w_.line(fmt::format("T {}[{}][{}];", name, vectors.size(), C));
    w_.assign(entries, [&](std::size_t k, const std::string& code) {
      return fmt::format("{}[{}][{}] = {};", name, k / C, k % C, code);
    });
  }

  BodyWriter& w_;
  const TreeInverseDynamics& tree_;
  std::vector<unsigned> components_;
};

// the loop over the coupled pairs (j, l), k the particle whose subtree's mass couples them
std::string coupled_pairs_loop(std::size_t n, const std::string& zero, const std::string& coupled,
                               const std::string& mirror = "") {
  return fmt::format("for (std::size_t j = 0; j < {0}; ++j)\n"
                     "    for (std::size_t l = {3}; l < {0}; ++l) {{\n"
                     "      const int k = coupling[j * {0} + l];\n"
                     "      if (k < 0) {{\n        {1}\n      }} else {{\n        {2}\n      }}\n{4}"
                     "    }}",
                     n, zero, coupled, mirror.empty() ? "0" : "j", mirror.empty() ? "" : "      " + mirror + "\n");
}

}  // namespace

// ∂τ/∂(q, q', u), τ = M(q) q'' − f(q, q', u) with q'' held: the coupled terms m̄ S_j · ∂d''/∂x in a
// loop, then the rest (derive/articulated_inverse_dynamics.hpp) where it is not zero
std::string articulated_inverse_dynamics_gradient_function(const Equations& e) {
  const TreeInverseDynamics& tree = e.articulated()->inverse_dynamics;
  std::size_t n = e.symbols.num_coordinates(), W = forcing_variables(e.symbols).size();
  BodyWriter w(e);
  TreeArrays arrays(w, tree, true);
  w.line(coupled_pairs_loop(n, fmt::format("F[j * {0} + l] = T(0);\n        F[j * {0} + {1} + l] = T(0);", W, n),
                            fmt::format("F[j * {0} + l] = mass[k] * {2};\n        F[j * {0} + {1} + l] = mass[k] * {3};", W, n,
                                        arrays.dot("axis", "j", "by_coordinate", "l"), arrays.dot("axis", "j", "by_velocity", "l"))));
  std::vector<ex> rest;
  std::vector<std::size_t> at;
  for (std::size_t k = 0; k < tree.gradient_rest.size(); ++k)
    if (k % W >= 2 * n || !tree.gradient_rest[k].is_zero()) rest.push_back(tree.gradient_rest[k]), at.push_back(k);
  w.assign(rest, [&](std::size_t k, const std::string& code) {
    std::size_t i = at[k];
    return i % W >= 2 * n ? fmt::format("F[{}] = {};", i, code) : fmt::format("F[{0}] = F[{0}] + ({1});", i, code);
  });
  return "namespace detail {\n\n" +
         function(fmt::format("/// d tau/d(q, q', u) of the inverse dynamics tau = M(q) q'' - f, q'' held: m S_j . dd''/dx over\n"
                              "/// the particles' tree, and the rest. ddq: {0}; F: {0}x{1}, row-major.\n", n, W),
                  "void inverse_dynamics_gradient(T t, const T* x, const T* ddq, const input_t<T>* u, const T* p, T* F)",
                  w.finish(all_unused + std::string(" (void)ddq;"))) +
         "}  // namespace detail\n\n";
}

std::string articulated_rhs_function(const Equations& e) {
  std::size_t n = e.symbols.num_coordinates();
  BodyWriter w(e);
  auto ddq = w.batch(e.articulated()->accelerations);
  for (std::size_t i = 0; i < n; ++i) w.line(fmt::format("xdot[{}] = x[{}];", i, n + i));
  for (std::size_t i = 0; i < n; ++i) w.line(fmt::format("xdot[{}] = {};", n + i, ddq[i]));
  return function(fmt::format("/// Explicit first-order form x' = [q'; q''] with x = [q; q'], q'' = M^-1 f by the\n"
                              "/// articulated-body recursion of the particles' tree (O(n), without forming M).\n"
                              "/// x, xdot: num_states = {}; u: num_inputs (may be null if none); p: num_parameters.\n",
                              2 * n),
                  "void rhs(T t, const T* x, const detail::input_t<T>* u, const T* p, T* xdot)", w.finish(all_unused));
}

// M_jl = m̄ S_j · S_l (derive/articulated_inverse_dynamics.hpp): O(n) code for the n² entries
std::string articulated_mass_matrix_function(const Equations& e) {
  std::size_t n = e.symbols.num_coordinates();
  BodyWriter w(e);
  TreeArrays arrays(w, e.articulated()->inverse_dynamics, false);
  // the upper triangle, mirrored: M is symmetric, and the coupling with it
  w.line(coupled_pairs_loop(n, fmt::format("M[j * {} + l] = T(0);", n),
                            fmt::format("M[j * {} + l] = mass[k] * {};", n, arrays.dot("axis", "j", "axis", "l")),
                            fmt::format("M[l * {0} + j] = M[j * {0} + l];", n)));
  return function(fmt::format("/// Mass matrix M(q) of M q'' = f, symmetric positive definite: M_jl = m S_j . S_l over the\n"
                              "/// particles' tree (S_j = dr/dq_j, m the mass below the deeper of the two joints).\n"
                              "/// x: num_states; p: num_parameters; M: {0}x{0}, row-major.\n", n),
                  "void mass_matrix(T t, const T* x, const T* p, T* M)", w.finish("(void)t; (void)x; (void)p;"));
}

namespace {

// M⁻¹ b by the recursion for symbolic b (TreeInverseDynamics::forces): the quantities that depend on
// b, in the order the recursion defines them, and the symbols they use that do not (S, U, D⁻¹, W: q alone)
struct SolveOfForces {
  std::vector<const Intermediate*> with_forces;
  std::vector<ex> factors;
};

SolveOfForces solve_of_forces(const Equations& e) {
  const TreeInverseDynamics& tree = e.articulated()->inverse_dynamics;
  GiNaC::exset dependent(tree.forces.begin(), tree.forces.end());
  std::vector<const Intermediate*> all;
  for (const Intermediate& i : e.articulated()->intermediates) {
    GiNaC::exset in;
    collect_symbols(i.definition, in);
    if (std::none_of(in.begin(), in.end(), [&](const ex& x) { return dependent.count(x) > 0; })) continue;
    dependent.insert(i.symbol);
    all.push_back(&i);
  }
  // only what the accelerations use (the leaves' accelerations a are never needed)
  GiNaC::exset used;
  for (const ex& a : tree.accelerations_of_forces) collect_symbols(a, used);
  SolveOfForces solve;
  for (auto i = all.rbegin(); i != all.rend(); ++i)
    if (used.count((*i)->symbol)) {
      collect_symbols((*i)->definition, used);
      solve.with_forces.push_back(*i);
    }
  std::reverse(solve.with_forces.begin(), solve.with_forces.end());
  for (const ex& x : used)
    if (!dependent.count(x)) solve.factors.push_back(x);
  return solve;
}

// Columns solved in one block: each column's recursion is one chain of dependent operations, so
// the block writes every step for all its columns at once (short loops the compiler vectorizes)
// instead of running the chains one after another. An even size near 16: no odd remainder to
// vectorize, and the block's quantities stay within the first-level cache.
std::size_t column_block(std::size_t count) {
  std::size_t blocks = (count + 15) / 16, size = (count + blocks - 1) / blocks;
  return std::min(count, size + size % 2);
}

// The solve's steps in groups of twelve, each group one loop over the block's columns (one loop per
// step took twice as long to compile and ran slower): a quantity used only in its own group is a
// local of the loop's body, any other an array over the block.
struct BlockLayout {
  static constexpr std::size_t group_size = 12;
  std::map<ex, std::size_t, GiNaC::ex_is_less> step_index;
  GiNaC::exset arrays;
};

BlockLayout block_layout(const SolveOfForces& solve, const std::vector<ex>& outputs) {
  const std::vector<const Intermediate*>& steps = solve.with_forces;
  BlockLayout layout;
  std::map<ex, std::size_t, GiNaC::ex_is_less> last_group;
  auto note_uses = [&](const ex& x, std::size_t group) {
    GiNaC::exset used;
    collect_symbols(x, used);
    for (const ex& u : used) last_group[u] = std::max(last_group[u], group);
  };
  for (std::size_t k = 0; k < steps.size(); ++k) {
    layout.step_index[steps[k]->symbol] = k;
    note_uses(steps[k]->definition, k / BlockLayout::group_size);
  }
  for (const ex& a : outputs) note_uses(a, steps.size());
  for (std::size_t k = 0; k < steps.size(); ++k)
    if (last_group[steps[k]->symbol] > k / BlockLayout::group_size) layout.arrays.insert(steps[k]->symbol);
  return layout;
}

// the solve's steps for one block of B columns, BlockLayout::group_size steps to a loop over the columns
void write_block_steps(BodyWriter& w, const std::vector<const Intermediate*>& steps, const BlockLayout& layout, std::size_t B,
                       const std::function<std::string(const ex&)>& print) {
  for (std::size_t start = 0; start < steps.size(); start += BlockLayout::group_size) {
    std::size_t end = std::min(steps.size(), start + BlockLayout::group_size);
    for (std::size_t k = start; k < end; ++k)
      if (layout.arrays.count(steps[k]->symbol)) w.line(fmt::format("  T {}[{}];", steps[k]->cpp_name, B));
    w.line(fmt::format("  for (std::size_t k = 0; k < {}; ++k) {{", B));
    for (std::size_t k = start; k < end; ++k)
      w.line(fmt::format(layout.arrays.count(steps[k]->symbol) ? "    {}[k] = {};" : "    const T {} = {};",
                         steps[k]->cpp_name, print(steps[k]->definition)));
    w.line("  }");
  }
}

// target[row(i) + c] = −(M⁻¹ F[:, first + c])_i for the columns c < count of F (n × W, row-major), M⁻¹
// by the recursion (O(n) per column) with its factors S, U, D⁻¹, W computed once, before the loop
// over the blocks of columns; the recursion's own statements, free of common subexpressions already
void write_solved_columns(BodyWriter& w, const Equations& e, std::size_t W, std::size_t first, std::size_t count,
                          const std::string& target, const std::function<std::size_t(std::size_t)>& row) {
  const TreeInverseDynamics& tree = e.articulated()->inverse_dynamics;
  SolveOfForces solve = solve_of_forces(e);
  w.batch(solve.factors);
  const std::vector<const Intermediate*>& steps = solve.with_forces;
  BlockLayout layout = block_layout(solve, tree.accelerations_of_forces);
  std::map<ex, std::size_t, GiNaC::ex_is_less> force_row;
  for (std::size_t i = 0; i < tree.forces.size(); ++i) force_row[tree.forces[i]] = i;
  auto print = [&](const ex& x) -> std::string {
    return cpp_expression(x, [&](const GiNaC::symbol& s) {
      if (auto f = force_row.find(s); f != force_row.end()) return fmt::format("F[{} + c + k]", f->second * W + first);
      auto step = layout.step_index.find(s);
      if (step == layout.step_index.end()) return w.name_of(s);
      return steps[step->second]->cpp_name + (layout.arrays.count(s) ? "[k]" : "");
    }, [&](const ex& call) { return w.batched_trig(call); });
  };
  std::size_t B = column_block(count);
  w.line(fmt::format("for (std::size_t block = 0; block < {}; block += {}) {{", count, B));
  // the last block ends at the last column, repeating some when B does not divide the count
  if (count % B == 0) w.line("  const std::size_t c = block;");
  else w.line(fmt::format("  const std::size_t c = block < {0} ? block : {0};", count - B));
  write_block_steps(w, steps, layout, B, print);
  w.line(fmt::format("  for (std::size_t k = 0; k < {}; ++k) {{", B));
  for (std::size_t i = 0; i < tree.accelerations_of_forces.size(); ++i)
    w.line(fmt::format("    {}[{} + c + k] = {};", target, row(i), print(-tree.accelerations_of_forces[i])));
  w.line("  }");
  w.line("}");
}

}  // namespace

// dq''/du = −M⁻¹ ∂τ/∂u = M⁻¹ ∂f/∂u: only the input columns of ∂τ/∂(q, q', u), which the coupled
// terms m̄ S_j · ∂d''/∂x do not reach (O(n m) entries, not the whole O(n²) gradient)
std::string articulated_jacobian_input_function(const Equations& e) {
  const Symbols& s = e.symbols;
  std::size_t n = s.num_coordinates(), m = s.inputs.size(), W = 2 * n + m;
  BodyWriter w(e);
  if (m > 0) {
    GiNaC::lst at_rest;  // ∂τ/∂u = −∂f/∂u does not depend on q''
    for (const GiNaC::symbol& a : e.acceleration_symbols()) at_rest.append(a == 0);
    std::vector<ex> by_input;
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t c = 0; c < m; ++c) by_input.push_back(e.articulated()->inverse_dynamics.gradient_rest[i * W + 2 * n + c].subs(at_rest));
    w.batch(solve_of_forces(e).factors);  // first, so that F shares their sines and cosines
    w.line(fmt::format("T F[{}];", n * m));
    w.assign(by_input, [](std::size_t k, const std::string& code) { return fmt::format("F[{}] = {};", k, code); });
    w.line(fmt::format("for (std::size_t i = 0; i < {}; ++i) B[i] = T(0);", n * m));
    write_solved_columns(w, e, m, 0, m, "B", [&](std::size_t i) { return (n + i) * m; });
  }
  return function(fmt::format("/// Input Jacobian dx'/du: zero upper block, M^-1 df/du below (M^-1 by the articulated-body\n"
                              "/// recursion). B: {}x{}, row-major (nothing is written when the model has no inputs).\n", 2 * n, m),
                  "void jacobian_input(T t, const T* x, const detail::input_t<T>* u, const T* p, T* B)",
                  w.finish(all_unused + std::string(" (void)B;")));
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
