#include "emit/cpp_jacobian_readers.hpp"

#include <functional>

#include <fmt/format.h>

namespace eomgen {

namespace {

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
std::string chain_entries(const ComponentText& k, std::size_t n, std::size_t inverse_columns) {
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
std::string tree_entries(const ComponentText& k, std::size_t n, std::size_t inverse_columns) {
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

}  // namespace

std::string reader_passes(const ComponentText& k, const ReaderShape& shape) {
  if (shape.chain && k.count() == 2) return planar_chain_entries(shape.nodes, shape.inverse_columns, shape.identity, shape.uniform_loads);
  if (shape.chain) return chain_entries(k, shape.nodes, shape.inverse_columns);
  return tree_entries(k, shape.nodes, shape.inverse_columns);
}

}  // namespace eomgen
