#include "emit/cpp_articulated_jacobian.hpp"

#include <algorithm>
#include <functional>

#include <fmt/format.h>

#include "emit/cpp_articulated.hpp"
#include "emit/cpp_body_writer.hpp"
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
  const TreeInverseDynamics& tree = e.articulated_inverse_dynamics;
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

// C++ text of Σ_c term(c) over the tree's components
class Components {
 public:
  explicit Components(std::size_t count) : count_(count) {}
  std::size_t count() const { return count_; }
  std::string sum(const std::function<std::string(std::size_t)>& term) const {
    std::string out;
    for (std::size_t c = 0; c < count_; ++c) out += (c ? " + " : "") + term(c);
    return count_ > 1 ? "(" + out + ")" : out;
  }
  // one statement per component a, or per pair (a, b)
  std::string each(const std::function<std::string(std::size_t)>& statement, const std::string& indent) const {
    std::string out;
    for (std::size_t a = 0; a < count_; ++a) out += indent + statement(a) + "\n";
    return out;
  }
  std::string each_pair(const std::function<std::string(std::size_t, std::size_t)>& statement, const std::string& indent) const {
    return each([&](std::size_t a) {
      std::string row;
      for (std::size_t b = 0; b < count_; ++b) row += (b ? " " : "") + statement(a, b);
      return row;
    }, indent);
  }

 private:
  std::size_t count_;
};

// the symbolic values: each node's axis and mass, each load's field and own force, the rest's entries
void write_tree_values(BodyWriter& w, const Equations& e, const JacobianLayout& layout) {
  const TreeInverseDynamics& tree = e.articulated_inverse_dynamics;
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
  w.assign(values, [&](std::size_t k, const std::string& code) { return targets[k] + " = " + code + ";"; });
}

// The recursion's factors at this state (Featherstone's articulated masses, for particles): IA, the
// pivot D = Sᵀ IA S (kept as 1/D), the gain V = IA S / D and the mass passed up IA − IA S Vᵀ, leaves
// first; then from the root Φ = I − S Vᵀ (the acceleration carried across the joint, its load held),
// the accelerance Ω = Φ Ω_parent Φᵀ + S Sᵀ / D (a bias p on the node's subtree gives a = −Ω p along
// the path to it) and the response e = Φ Ω_parent V − S / D (q'' = e · p at the node). A chain keeps
// each node's IA and Ω for the next one in local values, by their upper triangles (both symmetric);
// a tree adds them up in arrays.
std::string recursion_factors(const Components& k, std::size_t n, bool chain) {
  std::size_t C = k.count();
  auto sym = [](const std::string& name, std::size_t a, std::size_t b) { return fmt::format("{}{}{}", name, std::min(a, b), std::max(a, b)); };
  auto upper = [&](const std::function<std::string(std::size_t, std::size_t)>& statement, const std::string& indent) {
    std::string out;
    for (std::size_t a = 0; a < C; ++a)
      for (std::size_t b = a; b < C; ++b) out += indent + statement(a, b) + "\n";
    return out;
  };
  auto mirrored = [](const std::string& array, std::size_t a, std::size_t b, const std::string& value) {
    return fmt::format("{0}[{1}][{2}] = {3};{4}", array, a, b, value, a == b ? "" : fmt::format(" {}[{}][{}] = {};", array, b, a, value));
  };
  auto articulated = [&](std::size_t a, std::size_t b) { return chain ? sym("A", a, b) : fmt::format("articulated[m][{}][{}]", a, b); };
  auto above = [&](std::size_t a, std::size_t b) { return chain ? sym("O", a, b) : fmt::format("above[{}][{}]", a, b); };

  std::string out = fmt::format("  T inverse_pivot[{0}], gain[{0}][{1}], passed[{0}][{1}][{1}];\n", n, C);
  if (chain) {
    out += upper([](std::size_t a, std::size_t b) { return fmt::format("T I{}{} = T(0);", a, b); }, "  ");
  } else {
    out += fmt::format("  T articulated[{0}][{1}][{1}];\n  for (int m = 0; m < {0}; ++m) {{\n", n, C);
    out += k.each_pair([&](std::size_t a, std::size_t b) { return fmt::format("articulated[m][{}][{}] = {};", a, b, a == b ? "carried[m]" : "T(0)"); }, "    ");
    out += "  }\n";
  }
  out += fmt::format("  for (int m = {}; m >= 0; --m) {{\n", n - 1);
  if (chain) out += upper([](std::size_t a, std::size_t b) { return fmt::format("const T A{0}{1} = I{0}{1}{2};", a, b, a == b ? " + carried[m]" : ""); }, "    ");
  out += k.each([&](std::size_t a) {
    return fmt::format("const T U{} = {};", a, k.sum([&](std::size_t b) { return fmt::format("{} * axis[m][{}]", articulated(a, b), b); }));
  }, "    ");
  out += "    inverse_pivot[m] = T(1) / " + k.sum([](std::size_t a) { return fmt::format("axis[m][{0}] * U{0}", a); }) + ";\n";
  out += k.each([](std::size_t a) { return fmt::format("gain[m][{0}] = U{0} * inverse_pivot[m];", a); }, "    ");
  if (chain) {
    out += upper([&](std::size_t a, std::size_t b) {
      return fmt::format("I{0}{1} = A{0}{1} - U{0} * gain[m][{1}]; ", a, b) + mirrored("passed[m]", a, b, fmt::format("I{}{}", a, b));
    }, "    ");
  } else {
    out += k.each_pair([&](std::size_t a, std::size_t b) { return fmt::format("passed[m][{0}][{1}] = {2} - U{0} * gain[m][{1}];", a, b, articulated(a, b)); }, "    ");
    out += "    if (parent[m] >= 0) {\n";
    out += k.each_pair([&](std::size_t a, std::size_t b) {
      return fmt::format("articulated[parent[m]][{0}][{1}] = articulated[parent[m]][{0}][{1}] + passed[m][{0}][{1}];", a, b);
    }, "      ");
    out += "    }\n";
  }
  out += "  }\n";
  // accelerance is indexed by node + 1: [0] is the ground's, zero
  out += fmt::format("  T across[{0}][{1}][{1}], accelerance[{2}][{1}][{1}], response[{0}][{1}];\n", n, C, n + 1);
  out += k.each_pair([](std::size_t a, std::size_t b) { return fmt::format("accelerance[0][{}][{}] = T(0);", a, b); }, "  ");
  if (chain) out += upper([](std::size_t a, std::size_t b) { return fmt::format("T O{}{} = T(0);", a, b); }, "  ");
  out += fmt::format("  for (int m = 0; m < {}; ++m) {{\n", n);
  out += k.each_pair([](std::size_t a, std::size_t b) {
    return fmt::format("const T F{0}{1} = {2} - axis[m][{0}] * gain[m][{1}]; across[m][{0}][{1}] = F{0}{1};", a, b, a == b ? "T(1)" : "T(0)");
  }, "    ");
  if (!chain) out += fmt::format("    const T (&above)[{0}][{0}] = accelerance[parent[m] + 1];\n", C);
  out += k.each([&](std::size_t a) {
    return fmt::format("const T OV{} = {};", a, k.sum([&](std::size_t b) { return fmt::format("{} * gain[m][{}]", above(a, b), b); }));
  }, "    ");
  out += k.each([&](std::size_t a) {
    return fmt::format("response[m][{0}] = {1} - axis[m][{0}] * inverse_pivot[m];", a, k.sum([&](std::size_t b) { return fmt::format("F{}{} * OV{}", a, b, b); }));
  }, "    ");
  out += k.each_pair([&](std::size_t a, std::size_t b) {
    return fmt::format("const T AO{}{} = {};", a, b, k.sum([&](std::size_t c) { return fmt::format("F{}{} * {}", a, c, above(c, b)); }));
  }, "    ");
  out += upper([&](std::size_t a, std::size_t b) {
    std::string value = fmt::format("{} + axis[m][{}] * (axis[m][{}] * inverse_pivot[m])",
                                    k.sum([&](std::size_t c) { return fmt::format("AO{}{} * F{}{}", a, c, b, c); }), a, b);
    if (!chain) return mirrored("accelerance[m + 1]", a, b, value);
    return fmt::format("O{}{} = {}; ", a, b, value) + mirrored("accelerance[m + 1]", a, b, fmt::format("O{}{}", a, b));
  }, "    ");
  return out + "  }\n";
}

// each load's effect where it acts: the bias P = V ρ − IAᵃ w it passes to the node's parent, the
// node's own q'' (= ρ / D + V · (w − a_parent), a_parent = −Ω_parent P) and the acceleration
// relative to the field it leaves the node with, from which the subtree below moves as a free one
std::string load_effects(const Components& k, std::size_t L) {
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

// where load k writes: J's lower block, or (the rest's loads) the local columns of −M⁻¹
std::string destination(std::size_t n, std::size_t inverse_columns, const std::string& indent, const std::string& suffix = "") {
  if (inverse_columns == 0)
    return fmt::format("{0}T* const out{1} = J + {2} + load_column[k{1}];\n{0}const int stride{1} = {3};\n", indent, suffix, 2 * n * n, 2 * n);
  return fmt::format("{0}T* const out{1} = load_column[k{1}] >= 0 ? J + {2} + load_column[k{1}] : inverse + (-1 - load_column[k{1}]);\n"
                     "{0}const int stride{1} = load_column[k{1}] >= 0 ? {3} : {4};\n",
                     indent, suffix, 2 * n * n, 2 * n, inverse_columns);
}

// A chain: the entries above each loaded node m read d(j, m − 1) · P, with d(m, m) = e_m and
// d(j, m) = Φ_m d(j, m − 1); those below it s(j, m) · (a − w), with s(j, j − 1) = −V_j and
// s(j, m − 1) = Φ_mᵀ s(j, m). Each step advances the readers of all rows at once (independent
// products, where one row at a time would wait on each one's latency).
std::string chain_entries(const Components& k, std::size_t n, std::size_t inverse_columns) {
  std::size_t C = k.count();
  auto constants = [&](const std::string& name, const std::string& source) {
    std::string out = "const T";
    for (std::size_t a = 0; a < C; ++a) out += fmt::format("{} {}{} = {}[{}]", a ? "," : "", name, a, source, a);
    return out + ";";
  };
  auto across = [&](bool transposed) {
    std::string out = "const T";
    for (std::size_t a = 0; a < C; ++a)
      for (std::size_t b = 0; b < C; ++b) out += fmt::format("{} A{}{} = across[m][{}][{}]", a || b ? "," : "", a, b, transposed ? b : a, transposed ? a : b);
    return out + ";";
  };
  auto advance = [&](const std::string& range) {
    std::string out = fmt::format("      for (int j = {}) {{\n", range);
    std::string load = "        const T";
    for (std::size_t a = 0; a < C; ++a) load += fmt::format("{} d{} = reader[{}][j]", a ? "," : "", a, a);
    out += load + ";\n";
    out += k.each([&](std::size_t a) {
      return fmt::format("reader[{}][j] = {};", a, k.sum([&](std::size_t b) { return fmt::format("A{}{} * d{}", a, b, b); }));
    }, "        ");
    return out + "      }\n";
  };
  std::string out = fmt::format("  {{\n    T reader[{}][{}] = {{}};\n    for (int m = 0; m < {}; ++m) {{\n", C, n, n);
  out += "      for (int k = first_load[m]; k < first_load[m + 1]; ++k) {\n" + destination(n, inverse_columns, "        ");
  out += "        out[coordinate[m] * stride] = own_response[k];\n        " + constants("P", "bias_above[k]") + "\n";
  out += "        for (int j = 0; j < m; ++j) out[coordinate[j] * stride] = " +
         k.sum([](std::size_t a) { return fmt::format("reader[{0}][j] * P{0}", a); }) + ";\n      }\n";
  out += "      " + across(false) + "\n" + advance("0; j < m; ++j");
  out += k.each([](std::size_t a) { return fmt::format("reader[{0}][m] = response[m][{0}];", a); }, "      ");
  out += fmt::format("    }}\n  }}\n  {{\n    T reader[{}][{}] = {{}};\n    for (int m = {}; m >= 0; --m) {{\n", C, n, n - 1);
  out += fmt::format("      if (m + 1 < {}) {{\n", n);
  out += k.each([](std::size_t a) { return fmt::format("reader[{0}][m + 1] = -gain[m + 1][{0}];", a); }, "        ");
  out += "      }\n      for (int k = first_load[m]; k < first_load[m + 1]; ++k) {\n" + destination(n, inverse_columns, "        ");
  out += "        " + constants("G", "relative_below[k]") + "\n";
  out += fmt::format("        for (int j = m + 1; j < {}; ++j) out[coordinate[j] * stride] = ", n) +
         k.sum([](std::size_t a) { return fmt::format("reader[{0}][j] * G{0}", a); }) + ";\n      }\n";
  out += "      " + across(true) + "\n" + advance(fmt::format("m + 1; j < {}; ++j", n));
  return out + "    }\n  }\n";
}

// The planar chain's two passes with the same number of loads at every node: one loop over the rows
// per step writes all the node's columns and advances the row's number once.
std::string fused_planar_passes(std::size_t n, std::size_t inverse_columns, bool identity, std::size_t loads) {
  auto row = [&](const std::string& j) { return identity ? j : "coordinate[" + j + "]"; };
  auto each = [&](const std::function<std::string(const std::string&)>& text) {
    std::string out;
    for (std::size_t i = 0; i < loads; ++i) out += text(std::to_string(i));
    return out;
  };
  auto targets = [&](const std::string& indent) {
    return each([&](const std::string& i) {
      return fmt::format("{}const int k{} = {} * m + {};\n", indent, i, loads, i) + destination(n, inverse_columns, indent, i);
    });
  };
  std::string out = fmt::format("  {{\n    T delta[{0}] = {{}};\n    for (int m = 0; m < {0}; ++m) {{\n", n);
  out += targets("      ");
  out += each([&](const std::string& i) { return fmt::format("      out{0}[{1} * stride{0}] = own_response[k{0}];\n", i, row("m")); });
  out += "      if (m == 0) continue;\n";
  out += each([&](const std::string& i) {
    return fmt::format("      out{0}[{1} * stride{0}] = response[m - 1][0] * bias_above[k{0}][0] + response[m - 1][1] * bias_above[k{0}][1];\n"
                       "      const T through{0} = image[m - 1][0] * bias_above[k{0}][0] + image[m - 1][1] * bias_above[k{0}][1];\n",
                       i, row("(m - 1)"));
  });
  out += "      for (int j = 0; j < m - 1; ++j) {\n        const T d = delta[j];\n";
  out += each([&](const std::string& i) { return fmt::format("        out{0}[{1} * stride{0}] = d * through{0};\n", i, row("j")); });
  out += "        delta[j] = d * carry[m];\n      }\n"
         "      delta[m - 1] = normal[m][0] * response[m - 1][0] + normal[m][1] * response[m - 1][1];\n    }\n  }\n";
  out += fmt::format("  {{\n    T sigma[{0}] = {{}};\n    for (int m = {1}; m >= 0; --m) {{\n", n, n - 2);
  out += targets("      ");
  out += each([&](const std::string& i) {
    return fmt::format("      out{0}[{1} * stride{0}] = -(gain[m + 1][0] * relative_below[k{0}][0] + gain[m + 1][1] * relative_below[k{0}][1]);\n"
                       "      const T through{0} = normal[m + 1][0] * relative_below[k{0}][0] + normal[m + 1][1] * relative_below[k{0}][1];\n",
                       i, row("(m + 1)"));
  });
  out += fmt::format("      for (int j = m + 2; j < {}; ++j) {{\n        const T s = sigma[j];\n", n);
  out += each([&](const std::string& i) { return fmt::format("        out{0}[{1} * stride{0}] = s * through{0};\n", i, row("j")); });
  out += "        sigma[j] = s * carry[m + 1];\n      }\n"
         "      sigma[m + 1] = -(image[m][0] * gain[m + 1][0] + image[m][1] * gain[m + 1][1]);\n    }\n  }\n";
  return out;
}

// A planar chain: Φ = I − S Vᵀ annihilates S, so in the plane it has rank 1, Φ_m = image_m normal_mᵀ
// with normal_m ⟂ S_m; a product of them is image · Π carry · normalᵀ, carry_m = normal_m · image_m−1.
// The readers d(j, m) and s(j, m) of a chain are then one number per row, δ_j and σ_j, and each step
// multiplies them by one carry: a multiplication per entry and one per row and step.
std::string planar_chain_entries(std::size_t n, std::size_t inverse_columns, bool identity, std::size_t uniform_loads) {
  auto row = [&](const std::string& j) { return identity ? j : "coordinate[" + j + "]"; };
  std::string dest = "        const int k0 = k;\n" + destination(n, inverse_columns, "        ", "0") +
                     "        T* const out = out0;\n        const int stride = stride0;\n";
  std::string out = fmt::format("  T normal[{0}][2], image[{0}][2], carry[{0}];\n  for (int m = 0; m < {0}; ++m) {{\n", n);
  out += "    normal[m][0] = -axis[m][1];\n    normal[m][1] = axis[m][0];\n"
         "    const T inverse_square = T(1) / (normal[m][0] * normal[m][0] + normal[m][1] * normal[m][1]);\n"
         "    image[m][0] = (across[m][0][0] * normal[m][0] + across[m][0][1] * normal[m][1]) * inverse_square;\n"
         "    image[m][1] = (across[m][1][0] * normal[m][0] + across[m][1][1] * normal[m][1]) * inverse_square;\n"
         "    carry[m] = m > 0 ? normal[m][0] * image[m - 1][0] + normal[m][1] * image[m - 1][1] : T(0);\n  }\n";
  if (uniform_loads > 0) return out + fused_planar_passes(n, inverse_columns, identity, uniform_loads);
  // rows j < m − 1 above node m: d(j, m − 1) = image_{m−1} δ_j; row m − 1 reads e_{m−1} itself
  out += fmt::format("  {{\n    T delta[{0}] = {{}};\n    for (int m = 0; m < {0}; ++m) {{\n", n);
  out += "      for (int k = first_load[m]; k < first_load[m + 1]; ++k) {\n" + dest;
  out += fmt::format("        out[{} * stride] = own_response[k];\n", row("m"));
  out += "        if (m > 0) {\n";
  out += fmt::format("          out[{} * stride] = response[m - 1][0] * bias_above[k][0] + response[m - 1][1] * bias_above[k][1];\n", row("(m - 1)"));
  out += "          const T through = image[m - 1][0] * bias_above[k][0] + image[m - 1][1] * bias_above[k][1];\n";
  out += fmt::format("          for (int j = 0; j < m - 1; ++j) out[{} * stride] = delta[j] * through;\n", row("j"));
  out += "        }\n      }\n      if (m > 0) {\n        for (int j = 0; j < m - 1; ++j) delta[j] = delta[j] * carry[m];\n"
         "        delta[m - 1] = normal[m][0] * response[m - 1][0] + normal[m][1] * response[m - 1][1];\n      }\n    }\n  }\n";
  // rows j > m + 1 below node m: s(j, m) = normal_{m+1} σ_j; row m + 1 reads −V_{m+1} itself
  out += fmt::format("  {{\n    T sigma[{0}] = {{}};\n    for (int m = {1}; m >= 0; --m) {{\n      if (m + 1 == {0}) continue;\n", n, n - 1);
  out += "      for (int k = first_load[m]; k < first_load[m + 1]; ++k) {\n" + dest;
  out += "        const T G0 = relative_below[k][0], G1 = relative_below[k][1];\n";
  out += fmt::format("        out[{} * stride] = -(gain[m + 1][0] * G0 + gain[m + 1][1] * G1);\n", row("(m + 1)"));
  out += "        const T through = normal[m + 1][0] * G0 + normal[m + 1][1] * G1;\n";
  out += fmt::format("        for (int j = m + 2; j < {}; ++j) out[{} * stride] = sigma[j] * through;\n      }}\n", n, row("j"));
  out += fmt::format("      for (int j = m + 2; j < {}; ++j) sigma[j] = sigma[j] * carry[m + 1];\n", n);
  out += "      sigma[m + 1] = -(image[m][0] * gain[m + 1][0] + image[m][1] * gain[m + 1][1]);\n    }\n  }\n";
  return out;
}

// Any tree, one row j at a time: up its ancestors m with s(j, m) (entries s · (a − w)); at each
// ancestor with other branches d(j, m) = −Ω_m s(j, m); then over every other node m, parents first,
// d(j, m) = Φ_m d(j, parent), the entries of m's loads d(j, parent) · P.
std::string tree_entries(const Components& k, std::size_t n, std::size_t inverse_columns) {
  std::size_t C = k.count();
  std::string out = fmt::format("  for (int j = 0; j < {0}; ++j) {{\n    bool above[{0}] = {{}};\n    T reader[{1}][{2}] = {{}};\n", n, n + 1, C);
  out += k.each([](std::size_t a) { return fmt::format("T s{0} = -gain[j][{0}];", a); }, "    ");
  out += "    for (int m = parent[j]; m >= 0; m = parent[m]) {\n      above[m] = true;\n";
  out += "      for (int k = first_load[m]; k < first_load[m + 1]; ++k) {\n" + destination(n, inverse_columns, "        ");
  out += "        out[coordinate[j] * stride] = " + k.sum([](std::size_t a) { return fmt::format("s{0} * relative_below[k][{0}]", a); }) + ";\n      }\n";
  out += "      if (branching[m]) {\n";
  out += k.each([&](std::size_t a) {
    return fmt::format("reader[m + 1][{}] = -{};", a, k.sum([&](std::size_t b) { return fmt::format("accelerance[m + 1][{}][{}] * s{}", a, b, b); }));
  }, "        ");
  out += "      }\n";
  out += k.each([&](std::size_t a) {
    return fmt::format("const T t{} = {};", a, k.sum([&](std::size_t b) { return fmt::format("across[m][{}][{}] * s{}", b, a, b); }));
  }, "      ");
  out += k.each([](std::size_t a) { return fmt::format("s{0} = t{0};", a); }, "      ");
  out += "    }\n    for (int k = first_load[j]; k < first_load[j + 1]; ++k) {\n" + destination(n, inverse_columns, "      ");
  out += "      out[coordinate[j] * stride] = own_response[k];\n    }\n";
  out += k.each([](std::size_t a) { return fmt::format("reader[j + 1][{0}] = response[j][{0}];", a); }, "    ");
  out += fmt::format("    for (int m = 0; m < {}; ++m) {{\n      if (m == j || above[m]) continue;\n", n);
  out += fmt::format("      const T (&d)[{}] = reader[parent[m] + 1];\n", C);
  out += "      for (int k = first_load[m]; k < first_load[m + 1]; ++k) {\n" + destination(n, inverse_columns, "        ");
  out += "        out[coordinate[j] * stride] = " + k.sum([](std::size_t a) { return fmt::format("d[{0}] * bias_above[k][{0}]", a); }) + ";\n      }\n";
  out += k.each([&](std::size_t a) {
    return fmt::format("reader[m + 1][{}] = {};", a, k.sum([&](std::size_t b) { return fmt::format("across[m][{}][{}] * d[{}]", a, b, b); }));
  }, "      ");
  return out + "    }\n  }\n";
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
  Components k(layout.components.size());
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
  body += recursion_factors(k, n, layout.chain) + load_effects(k, layout.loads.size());
  if (layout.inverse_columns > 0) body += fmt::format("  T inverse[{}];\n", n * layout.inverse_columns);
  if (planar_chain) body += planar_chain_entries(n, layout.inverse_columns, identity, uniform_loads);
  else body += layout.chain ? chain_entries(k, n, layout.inverse_columns) : tree_entries(k, n, layout.inverse_columns);
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
