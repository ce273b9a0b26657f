#include "emit/cpp_articulated_jacobian.hpp"

#include <algorithm>
#include <functional>

#include <fmt/format.h>

#include "emit/cpp_articulated.hpp"
#include "emit/cpp_body_writer.hpp"
#include "emit/cpp_component_text.hpp"
#include "emit/cpp_jacobian_readers.hpp"
#include "kinematics/vector3.hpp"

namespace eomgen {

using GiNaC::ex;

namespace {

// A column of J's lower block, −∂q''/∂x = −M⁻¹ ∂τ/∂x, as a load on the coordinates' tree
// (TreeInverseDynamics::coordinate_order): a uniform field w on the particles the carrier `node` holds
// up (∂τ_j/∂x = m̄ S_j · w, derive/articulated_inverse_dynamics.hpp) and a generalized force on the
// node itself, both negated. The rest's columns of −M⁻¹ (a unit force at a node) are loads too.
struct Load {
  std::size_t node;
  Vector3 field{0, 0, 0};
  ex own_force;
  int column;  // of J's lower block; −1 − k for the k-th column of −M⁻¹
};

// an entry of ∂τ/∂x that no load carries: J[:, column] += (−M⁻¹)[:, inverse] · value
struct RestEntry {
  std::size_t column, inverse;
  ex value;
};

struct JacobianLayout {
  std::vector<std::size_t> coordinate;  // of each node, parents first
  std::vector<int> parent;              // node of the parent, −1: the ground
  std::vector<Load> loads;              // by node
  std::vector<std::size_t> first_load;  // loads of node m: first_load[m] … first_load[m + 1]
  std::size_t inverse_columns = 0;
  std::vector<RestEntry> rest;
  std::vector<unsigned> components;  // x, y, z where any vector of the tree is not zero
  bool chain = true;                 // node m hangs from m − 1
  std::vector<int> branching;        // nodes with two or more children
};

std::vector<unsigned> used_components(const TreeInverseDynamics& tree) {
  std::vector<unsigned> used;
  for (unsigned c = 0; c < 3; ++c) {
    bool any = false;
    for (const auto* set : {&tree.axes, &tree.acceleration_by_coordinate, &tree.acceleration_by_velocity})
      for (const Vector3& v : *set) any = any || !v[c].is_zero();
    if (any) used.push_back(c);
  }
  return used;
}

// the coordinates' tree in the order parents first: each node's coordinate and parent node
void coordinate_tree(const TreeInverseDynamics& tree, JacobianLayout& out, std::vector<std::size_t>& node_of) {
  std::size_t n = tree.axes.size();
  out.coordinate = tree.coordinate_order;
  node_of.assign(n, 0);
  for (std::size_t m = 0; m < n; ++m) node_of[out.coordinate[m]] = m;
  std::vector<int> children(n, 0);
  for (std::size_t m = 0; m < n; ++m) {
    int above = tree.coordinate_parent[out.coordinate[m]];
    out.parent.push_back(above < 0 ? -1 : int(node_of[std::size_t(above)]));
    out.chain = out.chain && out.parent.back() == int(m) - 1;
    if (above >= 0) ++children[std::size_t(out.parent.back())];
  }
  for (std::size_t m = 0; m < n; ++m)
    if (children[m] > 1) out.branching.push_back(int(m));
}

// Each coordinate's two columns load its joint's carrier, with the rest's entry in the carrier's row;
// any other entry of the rest needs the column of M⁻¹ of its row's node. A chain with any such column
// takes every node's, so that all nodes have as many loads (one loop over the rows then serves a
// node's columns together).
void loads_and_rest(const TreeInverseDynamics& tree, const std::vector<std::size_t>& node_of, JacobianLayout& out) {
  std::size_t n = tree.axes.size(), W = tree.gradient_rest.size() / n;
  std::vector<bool> carried(n * W, false);
  std::vector<Load>& loads = out.loads;
  for (std::size_t l = 0; l < n; ++l) {
    std::size_t r = tree.joint_carrier[l], row = r * W;
    loads.push_back({node_of[r], scaled(-1, tree.acceleration_by_coordinate[l]), -tree.gradient_rest[row + l], int(l)});
    loads.push_back({node_of[r], scaled(-1, tree.acceleration_by_velocity[l]), -tree.gradient_rest[row + n + l], int(n + l)});
    carried[row + l] = carried[row + n + l] = true;
  }
  std::vector<int> inverse_of(n, -1);
  auto inverse_column = [&](std::size_t a) {
    if (inverse_of[a] < 0) {
      inverse_of[a] = int(out.inverse_columns++);
      loads.push_back({node_of[a], {0, 0, 0}, ex(-1), -1 - inverse_of[a]});
    }
    return std::size_t(inverse_of[a]);
  };
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t x = 0; x < 2 * n; ++x) {
      const ex& value = tree.gradient_rest[a * W + x];
      if (!carried[a * W + x] && !value.is_zero()) out.rest.push_back({x, inverse_column(a), value});
    }
  for (std::size_t a = 0; out.chain && out.inverse_columns > 0 && a < n; ++a) inverse_column(a);
  std::stable_sort(loads.begin(), loads.end(), [](const Load& a, const Load& b) { return a.node < b.node; });
  for (std::size_t m = 0, k = 0; m <= n; ++m) {
    while (k < loads.size() && loads[k].node < m) ++k;
    out.first_load.push_back(k);
  }
}

JacobianLayout jacobian_layout(const Equations& e) {
  const TreeInverseDynamics& tree = e.articulated()->inverse_dynamics;
  JacobianLayout out;
  std::vector<std::size_t> node_of;
  coordinate_tree(tree, out, node_of);
  loads_and_rest(tree, node_of, out);
  out.components = used_components(tree);
  return out;
}

template <class Container>
std::string list(const Container& values) {
  std::string out;
  for (const auto& v : values) out += (out.empty() ? "" : ", ") + fmt::format("{}", v);
  return out;
}

// the symbolic values: each node's axis and mass, each load's field and own force, the rest's entries
void write_tree_values(BodyWriter& w, const Equations& e, const JacobianLayout& layout) {
  const TreeInverseDynamics& tree = e.articulated()->inverse_dynamics;
  std::size_t n = layout.coordinate.size(), C = layout.components.size(), L = layout.loads.size();
  std::vector<ex> values;
  std::vector<std::string> targets;
  for (std::size_t m = 0; m < n; ++m) {
    for (std::size_t c = 0; c < C; ++c)
      values.push_back(tree.axes[layout.coordinate[m]][layout.components[c]]), targets.push_back(fmt::format("axis[{}][{}]", m, c));
    values.push_back(tree.carried_masses[layout.coordinate[m]]), targets.push_back(fmt::format("carried[{}]", m));
  }
  for (std::size_t k = 0; k < L; ++k) {
    for (std::size_t c = 0; c < C; ++c)
      values.push_back(layout.loads[k].field[layout.components[c]]), targets.push_back(fmt::format("field[{}][{}]", k, c));
    values.push_back(layout.loads[k].own_force), targets.push_back(fmt::format("own_force[{}]", k));
  }
  for (std::size_t r = 0; r < layout.rest.size(); ++r)
    values.push_back(layout.rest[r].value), targets.push_back(fmt::format("rest_value[{}]", r));
  w.line(fmt::format("T axis[{0}][{1}], carried[{0}], field[{2}][{1}], own_force[{2}];", n, C, L));
  if (!layout.rest.empty()) w.line(fmt::format("T rest_value[{}];", layout.rest.size()));
  w.assign(values, targets);
}

// How the factors' text reads a node's quantities: a chain keeps each node's IA and Ω for the next
// one in local values, by their upper triangles (both symmetric); a tree adds them up in arrays.
class FactorText {
 public:
  FactorText(const ComponentText& k, bool chain) : k_(k), chain_(chain) {}
  // one statement per entry (a, b) with a ≤ b
  std::string upper(const std::function<std::string(std::size_t, std::size_t)>& statement, const std::string& indent) const {
    std::string out;
    for (std::size_t a = 0; a < k_.count(); ++a)
      for (std::size_t b = a; b < k_.count(); ++b) out += indent + statement(a, b) + "\n";
    return out;
  }
  static std::string mirrored(const std::string& array, std::size_t a, std::size_t b, const std::string& value) {
    return fmt::format("{0}[{1}][{2}] = {3};{4}", array, a, b, value, a == b ? "" : fmt::format(" {}[{}][{}] = {};", array, b, a, value));
  }
  std::string articulated(std::size_t a, std::size_t b) const { return chain_ ? symmetric("A", a, b) : fmt::format("articulated[m][{}][{}]", a, b); }
  std::string above(std::size_t a, std::size_t b) const { return chain_ ? symmetric("O", a, b) : fmt::format("above[{}][{}]", a, b); }
  bool chain() const { return chain_; }

 private:
  static std::string symmetric(const std::string& name, std::size_t a, std::size_t b) { return fmt::format("{}{}{}", name, std::min(a, b), std::max(a, b)); }
  const ComponentText& k_;
  bool chain_;
};

// The recursion's factors at this state (Featherstone's articulated masses, for particles), leaves
// first: IA, the pivot D = Sᵀ IA S (kept as 1/D), the gain V = IA S / D and the mass passed up
// IA − IA S Vᵀ
std::string inward_factors(const ComponentText& k, const FactorText& f, std::size_t n) {
  std::size_t C = k.count();
  std::string out = fmt::format("  T inverse_pivot[{0}], gain[{0}][{1}], passed[{0}][{1}][{1}];\n", n, C);
  if (f.chain()) {
    out += f.upper([](std::size_t a, std::size_t b) { return fmt::format("T I{}{} = T(0);", a, b); }, "  ");
  } else {
    out += fmt::format("  T articulated[{0}][{1}][{1}];\n  for (int m = 0; m < {0}; ++m) {{\n", n, C);
    out += k.each_pair([&](std::size_t a, std::size_t b) { return fmt::format("articulated[m][{}][{}] = {};", a, b, a == b ? "carried[m]" : "T(0)"); }, "    ");
    out += "  }\n";
  }
  out += fmt::format("  for (int m = {}; m >= 0; --m) {{\n", n - 1);
  if (f.chain()) out += f.upper([](std::size_t a, std::size_t b) { return fmt::format("const T A{0}{1} = I{0}{1}{2};", a, b, a == b ? " + carried[m]" : ""); }, "    ");
  out += k.each([&](std::size_t a) {
    return fmt::format("const T U{} = {};", a, k.sum([&](std::size_t b) { return fmt::format("{} * axis[m][{}]", f.articulated(a, b), b); }));
  }, "    ");
  out += "    inverse_pivot[m] = T(1) / " + k.sum([](std::size_t a) { return fmt::format("axis[m][{0}] * U{0}", a); }) + ";\n";
  out += k.each([](std::size_t a) { return fmt::format("gain[m][{0}] = U{0} * inverse_pivot[m];", a); }, "    ");
  if (f.chain())
    return out + f.upper([&](std::size_t a, std::size_t b) {
      return fmt::format("I{0}{1} = A{0}{1} - U{0} * gain[m][{1}]; ", a, b) + FactorText::mirrored("passed[m]", a, b, fmt::format("I{}{}", a, b));
    }, "    ") + "  }\n";
  out += k.each_pair([&](std::size_t a, std::size_t b) { return fmt::format("passed[m][{0}][{1}] = {2} - U{0} * gain[m][{1}];", a, b, f.articulated(a, b)); }, "    ");
  out += "    if (parent[m] >= 0) {\n";
  out += k.each_pair([&](std::size_t a, std::size_t b) {
    return fmt::format("articulated[parent[m]][{0}][{1}] = articulated[parent[m]][{0}][{1}] + passed[m][{0}][{1}];", a, b);
  }, "      ");
  return out + "    }\n  }\n";
}

// then from the root: Φ = I − S Vᵀ (the acceleration carried across the joint, its load held), the
// accelerance Ω = Φ Ω_parent Φᵀ + S Sᵀ / D (a bias p on the node's subtree gives a = −Ω p along the
// path to it) and the response e = Φ Ω_parent V − S / D (q'' = e · p at the node); accelerance is
// indexed by node + 1, [0] the ground's (zero)
std::string outward_factors(const ComponentText& k, const FactorText& f, std::size_t n) {
  std::size_t C = k.count();
  std::string out = fmt::format("  T across[{0}][{1}][{1}], accelerance[{2}][{1}][{1}], response[{0}][{1}];\n", n, C, n + 1);
  out += k.each_pair([](std::size_t a, std::size_t b) { return fmt::format("accelerance[0][{}][{}] = T(0);", a, b); }, "  ");
  if (f.chain()) out += f.upper([](std::size_t a, std::size_t b) { return fmt::format("T O{}{} = T(0);", a, b); }, "  ");
  out += fmt::format("  for (int m = 0; m < {}; ++m) {{\n", n);
  out += k.each_pair([](std::size_t a, std::size_t b) {
    return fmt::format("const T F{0}{1} = {2} - axis[m][{0}] * gain[m][{1}]; across[m][{0}][{1}] = F{0}{1};", a, b, a == b ? "T(1)" : "T(0)");
  }, "    ");
  if (!f.chain()) out += fmt::format("    const T (&above)[{0}][{0}] = accelerance[parent[m] + 1];\n", C);
  out += k.each([&](std::size_t a) {
    return fmt::format("const T OV{} = {};", a, k.sum([&](std::size_t b) { return fmt::format("{} * gain[m][{}]", f.above(a, b), b); }));
  }, "    ");
  out += k.each([&](std::size_t a) {
    return fmt::format("response[m][{0}] = {1} - axis[m][{0}] * inverse_pivot[m];", a, k.sum([&](std::size_t b) { return fmt::format("F{}{} * OV{}", a, b, b); }));
  }, "    ");
  out += k.each_pair([&](std::size_t a, std::size_t b) {
    return fmt::format("const T AO{}{} = {};", a, b, k.sum([&](std::size_t c) { return fmt::format("F{}{} * {}", a, c, f.above(c, b)); }));
  }, "    ");
  out += f.upper([&](std::size_t a, std::size_t b) {
    std::string value = fmt::format("{} + axis[m][{}] * (axis[m][{}] * inverse_pivot[m])",
                                    k.sum([&](std::size_t c) { return fmt::format("AO{}{} * F{}{}", a, c, b, c); }), a, b);
    if (!f.chain()) return FactorText::mirrored("accelerance[m + 1]", a, b, value);
    return fmt::format("O{}{} = {}; ", a, b, value) + FactorText::mirrored("accelerance[m + 1]", a, b, fmt::format("O{}{}", a, b));
  }, "    ");
  return out + "  }\n";
}

// each load's effect where it acts: the bias P = V ρ − IAᵃ w it passes to the node's parent, the
// node's own q'' (= ρ / D + V · (w − a_parent), a_parent = −Ω_parent P) and the acceleration
// relative to the field it leaves the node with, from which the subtree below moves as a free one
std::string load_effects(const ComponentText& k, std::size_t L) {
  std::size_t C = k.count();
  std::string out = fmt::format("  T bias_above[{0}][{1}], relative_below[{0}][{1}], own_response[{0}];\n", L, C);
  out += fmt::format("  for (int k = 0; k < {}; ++k) {{\n    const int r = load_node[k];\n", L);
  out += k.each([&](std::size_t a) {
    return fmt::format("const T P{0} = gain[r][{0}] * own_force[k] - {1};", a,
                       k.sum([&](std::size_t b) { return fmt::format("passed[r][{}][{}] * field[k][{}]", a, b, b); }));
  }, "    ");
  out += k.each([&](std::size_t a) {
    return fmt::format("const T ap{} = -{};", a, k.sum([&](std::size_t b) { return fmt::format("accelerance[parent[r] + 1][{}][{}] * P{}", a, b, b); }));
  }, "    ");
  out += "    const T own = own_force[k] * inverse_pivot[r] + " +
         k.sum([](std::size_t a) { return fmt::format("gain[r][{0}] * (field[k][{0}] - ap{0})", a); }) + ";\n";
  out += k.each([](std::size_t a) {
    return fmt::format("relative_below[k][{0}] = ap{0} - field[k][{0}] + axis[r][{0}] * own; bias_above[k][{0}] = P{0};", a);
  }, "    ");
  out += "    own_response[k] = own;\n  }\n";
  return out;
}

std::string tables(const JacobianLayout& layout, bool with_coordinates, bool with_first_load) {
  std::size_t n = layout.coordinate.size(), L = layout.loads.size();
  std::vector<int> node, column;
  for (const Load& l : layout.loads) node.push_back(int(l.node)), column.push_back(l.column);
  std::string out = fmt::format("static constexpr int parent[{}] = {{{}}};", n, list(layout.parent));
  if (with_coordinates) out += fmt::format("\n  static constexpr int coordinate[{}] = {{{}}};", n, list(layout.coordinate));
  if (with_first_load) out += fmt::format("\n  static constexpr int first_load[{}] = {{{}}};", n + 1, list(layout.first_load));
  out += fmt::format("\n  static constexpr int load_node[{}] = {{{}}};", L, list(node));
  out += fmt::format("\n  static constexpr int load_column[{}] = {{{}}};", L, list(column));
  if (!layout.chain) {
    std::vector<int> branching(n, 0);
    for (int m : layout.branching) branching[std::size_t(m)] = 1;
    out += fmt::format("\n  static constexpr bool branching[{}] = {{{}}};", n, list(branching));
  }
  return out;
}

std::string rest_product(const JacobianLayout& layout, std::size_t n) {
  if (layout.rest.empty()) return "";
  std::vector<std::size_t> column, inverse;
  for (const RestEntry& r : layout.rest) column.push_back(r.column), inverse.push_back(r.inverse);
  std::size_t R = layout.rest.size(), Y = layout.inverse_columns;
  return fmt::format("  static constexpr int rest_column[{0}] = {{{1}}};\n  static constexpr int rest_inverse[{0}] = {{{2}}};\n"
                     "  for (int r = 0; r < {0}; ++r)\n    for (int i = 0; i < {3}; ++i)\n"
                     "      J[({3} + i) * {4} + rest_column[r]] = J[({3} + i) * {4} + rest_column[r]] + inverse[i * {5} + rest_inverse[r]] * rest_value[r];\n",
                     R, list(column), list(inverse), n, 2 * n, Y);
}

}  // namespace

// dq''/dx = −M⁻¹ ∂τ/∂x entry by entry: each column of ∂τ/∂x is a uniform field on a subtree plus a
// force at its top (derive/articulated_inverse_dynamics.hpp), whose response the recursion's factors
// give at each coordinate as a product of vectors carried along the tree: O(1) operations per entry
std::string articulated_jacobian_state_function(const Equations& e) {
  std::size_t n = e.symbols.num_coordinates(), N = 2 * n;
  JacobianLayout layout = jacobian_layout(e);
  ComponentText k(layout.components.size());
  BodyWriter w(e);
  w.line(fmt::format("T xdot[{}];", N));
  w.line("rhs(t, x, u, p, xdot);");
  w.line(fmt::format("const T* const ddq = xdot + {};", n));
  w.line("(void)ddq;");
  bool identity = true, planar_chain = layout.chain && k.count() == 2;
  for (std::size_t m = 0; m < n; ++m) identity = identity && layout.coordinate[m] == m;
  std::size_t uniform_loads = layout.loads.size() / n;
  for (std::size_t m = 0; m < n; ++m) uniform_loads = layout.first_load[m + 1] - layout.first_load[m] == uniform_loads ? uniform_loads : 0;
  w.line(tables(layout, !(planar_chain && identity), !(planar_chain && uniform_loads > 0)));
  write_tree_values(w, e, layout);
  // the upper block [0 I] first, as one stream of stores
  std::string body = fmt::format("  for (int i = 0; i < {}; ++i) J[i] = T(0);\n  for (int i = 0; i < {}; ++i) J[i * {} + {} + i] = T(1);\n",
                                 n * N, n, N, n);
  FactorText factor_text(k, layout.chain);
  body += inward_factors(k, factor_text, n) + outward_factors(k, factor_text, n) + load_effects(k, layout.loads.size());
  if (layout.inverse_columns > 0) body += fmt::format("  T inverse[{}];\n", n * layout.inverse_columns);
  body += reader_passes(k, {n, layout.inverse_columns, layout.chain, identity, uniform_loads});
  body += rest_product(layout, n);
  return articulated_inverse_dynamics_gradient_function(e) +
         function(fmt::format("/// Jacobian of the right-hand side, dx'/dx, analytic: the lower block -M^-1 d tau/dx\n"
                              "/// (tau = M q'' - f, q'' held, from rhs) entry by entry, each column a field and a force on\n"
                              "/// the particles' tree, carried to each coordinate by the articulated-body factors\n"
                              "/// (O(1) operations per entry, without M^-1). J: {0}x{0}, row-major.\n",
                              N),
                  "void jacobian_state(T t, const T* x, const detail::input_t<T>* u, const T* p, T* J)",
                  w.finish(all_unused) + body);
}

}  // namespace eomgen
