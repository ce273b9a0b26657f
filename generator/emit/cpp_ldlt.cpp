#include "emit/cpp_ldlt.hpp"

#include <algorithm>
#include <utility>

#include <fmt/format.h>

#include "emit/cpp_avx_dispatch.hpp"

namespace eomgen {

namespace {

// jacobian_state solved its 2n columns one by one before: solved together, it runs 1.24 times as
// fast on a 21-joint tree, 1.12 on the 7-joint arm and the quadruped (g++ -O2, each header timed in
// both places of one process), with results within 4e-16 of the largest entry.
//
// `statement` for each column c of ldlt_solve_rows's B, by each_column (solve_rows_functions).
std::string over_columns(const std::string& indent, const std::string& statement) {
  return fmt::format("{}each_column<m>([&](std::size_t c) {{ {} }});\n", indent, statement);
}

// For ldlt_solve_rows: row `to` of B minus Σ L_k row k over `terms` (L's entry, k), in one pass
// over the columns. L's entries are read first: B might alias L, and would make the loop read them again.
std::string subtract_rows(std::size_t to, const std::vector<std::pair<std::string, std::size_t>>& terms) {
  if (terms.empty()) return "";
  std::string factors, sum;
  for (std::size_t t = 0; t < terms.size(); ++t) {
    factors += fmt::format("{}l{} = {}", t ? ", " : "", t, terms[t].first);
    sum += fmt::format(" - l{}*B[{}*m + c]", t, terms[t].second);
  }
  return fmt::format("  {{\n    const T {0};\n{1}  }}\n", factors,
                     over_columns("    ", fmt::format("B[{0}*m + c] = B[{0}*m + c]{1};", to, sum)));
}

std::string scale_rows(std::size_t n) {
  return fmt::format("  for (std::size_t i = 0; i < {}; ++i) {{\n    const T r = T(negated ? -1 : 1)/D[i];\n{}  }}\n", n,
                     over_columns("    ", "B[i*m + c] = B[i*m + c]*r;"));
}

using Terms = std::vector<std::pair<std::string, std::size_t>>;

// unrolled, the code grows as n³ and n² (the factor alone was 108 KB at n = 30); the loops were
// 18 % slower at n = 16 and as fast at n = 30 (the planar chain's rhs in the mass-matrix form,
// tests/benchmarks/rhs_benchmark.cpp)
constexpr std::size_t unrolled_up_to = 24;

LdltCode unrolled(std::size_t n) {
  LdltCode c;
  for (std::size_t j = 0; j < n; ++j) {
    std::string d = fmt::format("M[{}]", j * n + j);
    for (std::size_t k = 0; k < j; ++k) d += fmt::format(" - L[{0}]*L[{0}]*D[{1}]", j * n + k, k);
    c.factor += fmt::format("  D[{}] = {};\n", j, d);
    for (std::size_t i = j + 1; i < n; ++i) {
      std::string l = fmt::format("M[{}]", i * n + j);
      for (std::size_t k = 0; k < j; ++k) l += fmt::format(" - L[{}]*L[{}]*D[{}]", i * n + k, j * n + k, k);
      c.factor += fmt::format("  L[{}] = ({})/D[{}];\n", i * n + j, l, j);
    }
  }
  for (std::size_t i = 1; i < n; ++i) {
    std::string y = fmt::format("b[{}]", i);
    for (std::size_t k = 0; k < i; ++k) y += fmt::format(" - L[{}]*b[{}]", i * n + k, k);
    c.solve += fmt::format("  b[{}] = {};\n", i, y);
    Terms terms;
    for (std::size_t k = 0; k < i; ++k) terms.emplace_back(fmt::format("L[{}]", i * n + k), k);
    c.solve_rows += subtract_rows(i, terms);
  }
  c.solve_rows += scale_rows(n);
  for (std::size_t i = 0; i < n; ++i) c.solve += fmt::format("  b[{0}] = b[{0}]/D[{0}];\n", i);
  for (std::size_t i = n > 0 ? n - 1 : 0; i-- > 0;) {
    std::string x = fmt::format("b[{}]", i);
    for (std::size_t k = i + 1; k < n; ++k) x += fmt::format(" - L[{}]*b[{}]", k * n + i, k);
    c.solve += fmt::format("  b[{}] = {};\n", i, x);
    Terms terms;
    for (std::size_t k = i + 1; k < n; ++k) terms.emplace_back(fmt::format("L[{}]", k * n + i), k);
    c.solve_rows += subtract_rows(i, terms);
  }
  return c;
}

LdltCode loops(std::size_t n) {
  LdltCode c;
  c.unrolled = false;
  c.factor = fmt::format(
      "  for (std::size_t j = 0; j < {0}; ++j) {{\n"
      "    T d = M[j * {0} + j];\n"
      "    for (std::size_t k = 0; k < j; ++k) d = d - L[j * {0} + k] * L[j * {0} + k] * D[k];\n"
      "    D[j] = d;\n"
      "    for (std::size_t i = j + 1; i < {0}; ++i) {{\n"
      "      T l = M[i * {0} + j];\n"
      "      for (std::size_t k = 0; k < j; ++k) l = l - L[i * {0} + k] * L[j * {0} + k] * D[k];\n"
      "      L[i * {0} + j] = l / d;\n"
      "    }}\n"
      "  }}\n", n);
  c.solve = fmt::format(
      "  for (std::size_t i = 1; i < {0}; ++i)\n"
      "    for (std::size_t k = 0; k < i; ++k) b[i] = b[i] - L[i * {0} + k] * b[k];\n"
      "  for (std::size_t i = 0; i < {0}; ++i) b[i] = b[i] / D[i];\n"
      "  for (std::size_t i = {0} - 1; i-- > 0;)\n"
      "    for (std::size_t k = i + 1; k < {0}; ++k) b[i] = b[i] - L[k * {0} + i] * b[k];\n", n);
  const std::string subtract = over_columns("      ", "B[i*m + c] = B[i*m + c] - l*B[k*m + c];");
  c.solve_rows = fmt::format(
      "  for (std::size_t i = 1; i < {0}; ++i)\n"
      "    for (std::size_t k = 0; k < i; ++k) {{\n"
      "      const T l = L[i * {0} + k];\n"
      "{2}"
      "    }}\n"
      "{1}"
      "  for (std::size_t i = {0} - 1; i-- > 0;)\n"
      "    for (std::size_t k = i + 1; k < {0}; ++k) {{\n"
      "      const T l = L[k * {0} + i];\n"
      "{2}"
      "    }}\n", n, scale_rows(n), subtract);
  return c;
}

}  // namespace

// Written out at every size: the same operations in loops over a parent table, measured on trees
// of 18 to 85 coordinates (a quadruped, humanoids, chains, dm_control's dog, g++ -O2), factored
// 1.3-2.8x and solved for many columns 4.7-6.8x slower, and saved at most 20 s of g++ where the whole
// header takes minutes.
LdltCode tree_ldlt_code(const std::vector<int>& parent) {
  std::size_t n = parent.size();
  auto above = [&](std::size_t i) {
    std::vector<std::size_t> chain;
    for (int j = parent[i]; j >= 0; j = parent[std::size_t(j)]) chain.push_back(std::size_t(j));
    return chain;
  };
  LdltCode c;
  for (std::size_t k = 0; k < n; ++k) {
    c.factor += fmt::format("  D[{}] = M[{}];\n", k, k * n + k);
    for (std::size_t i : above(k)) c.factor += fmt::format("  L[{0}] = M[{0}];\n", k * n + i);
  }
  // for k from the leaves: a = M_ki / M_kk, M_ij −= a M_kj for j = i and above, M_ki = a
  for (std::size_t k = n; k-- > 0;)
    for (std::size_t i : above(k)) {
      std::string body = fmt::format("    const T a = L[{}]/D[{}];\n    D[{}] = D[{}] - a*L[{}];\n", k * n + i, k, i, i, k * n + i);
      for (std::size_t j : above(i)) body += fmt::format("    L[{0}] = L[{0}] - a*L[{1}];\n", i * n + j, k * n + j);
      c.factor += "  {\n" + body + fmt::format("    L[{}] = a;\n  }}\n", k * n + i);
    }
  std::vector<Terms> from_below(n);  // row i's terms: L_ki and each k that i's joint carries, from the leaves
  for (std::size_t k = n; k-- > 0;)
    for (std::size_t i : above(k)) {
      c.solve += fmt::format("  b[{0}] = b[{0}] - L[{1}]*b[{2}];\n", i, k * n + i, k);
      from_below[i].emplace_back(fmt::format("L[{}]", k * n + i), k);
    }
  for (std::size_t i = n; i-- > 0;) c.solve_rows += subtract_rows(i, from_below[i]);
  for (std::size_t i = 0; i < n; ++i) c.solve += fmt::format("  b[{0}] = b[{0}]/D[{0}];\n", i);
  c.solve_rows += scale_rows(n);
  for (std::size_t i = 0; i < n; ++i) {
    Terms terms;
    for (std::size_t j : above(i)) {
      c.solve += fmt::format("  b[{0}] = b[{0}] - L[{1}]*b[{2}];\n", i, i * n + j, j);
      terms.emplace_back(fmt::format("L[{}]", i * n + j), j);
    }
    c.solve_rows += subtract_rows(i, terms);
  }
  return c;
}

LdltCode ldlt_code(std::size_t n) { return n <= unrolled_up_to ? unrolled(n) : loops(n); }

namespace {

// e.coordinate_parents when every nonzero M_ij has one of i, j above the other; empty otherwise
std::vector<int> tree_of_mass_matrix(const Equations& e, std::size_t n) {
  const std::vector<int>& parent = e.coordinate_parents;
  if (parent.size() != n || e.mass_matrix.rows() != n) return {};
  std::vector<std::vector<bool>> related(n, std::vector<bool>(n, false));
  for (std::size_t i = 0; i < n; ++i)
    for (int j = int(i); j >= 0; j = parent[std::size_t(j)]) related[i][std::size_t(j)] = related[std::size_t(j)][i] = true;
  for (unsigned i = 0; i < n; ++i)
    for (unsigned j = 0; j < n; ++j)
      if (!related[i][j] && !e.mass_matrix(i, j).is_zero()) return {};
  return parent;
}

}  // namespace

// g++ -O2 vectorizes only a loop that needs no scalar remainder: 42 columns in one loop went two
// lanes wide even in AVX code, and as 40 and 2 the AVX copy (emit/cpp_avx_dispatch) runs the 40
// four wide: the 21-joint tree's solve 1.5 times as fast. Each column's operations are the same
// either way. each_column writes the two loops once: as two loops at every row the arm's header
// was 1.5 KB larger; as two passes of the whole solve (40 columns, then 2) the arm's solve took
// 100 ns instead of 80 (L's entries and D's reciprocals twice).
std::string solve_rows_functions(const LdltCode& code, std::size_t n) {
  return "/// column(c) for the m columns c, in two loops: over m / 4 * 4 of them, then the rest.\n"
         "template <std::size_t m, class Column>\n"
         "inline void each_column(Column column) {\n"
         "  for (std::size_t c = 0; c < m / 4 * 4; ++c) column(c);\n"
         "  for (std::size_t c = m / 4 * 4; c < m; ++c) column(c);\n"
         "}\n\n"
         "/// As ldlt_solve, for the m columns of B (" + std::to_string(n) + "xm, row-major) at once: each row's operations in\n"
         "/// a pass over its columns, which the compiler vectorizes, and D's reciprocals taken once;\n"
         "/// `negated` solves for -x (exactly: the reciprocals' sign carries through).\n"
         "template <std::size_t m, bool negated = false, class T>\n"
         "inline void ldlt_solve_rows(const T* L, const T* D, T* B) {\n  (void)L;\n" +
         code.solve_rows + "}\n\n" + (n < solve_rows_avx_from_coordinates ? std::string() : solve_rows_avx_dispatch());
}

std::string mass_matrix_factorization(const Equations& e, std::size_t n) {
  const char* functions =
      "template <class T>\ninline void ldlt_factor(const T* M, T* L, T* D) {{\n  (void)L;\n{1}}}\n\n"
      "/// Solves {2} x = b in place. b: {0}.\n"
      "template <class T>\ninline void ldlt_solve(const T* L, const T* D, T* b) {{\n  (void)L;\n{3}}}\n\n"
      "{4}";
  if (std::vector<int> tree = tree_of_mass_matrix(e, n); !tree.empty()) {
    LdltCode ldlt = tree_ldlt_code(tree);
    return fmt::format(
               "/// M = L^T D L for the symmetric positive definite {0}x{0} mass matrix of a tree, factored from\n"
               "/// the leaves (Featherstone's LTDL): L_ij is nonzero only for a coordinate j above i in the\n"
               "/// tree (or in the chain that joints following another's coordinate make), so nothing fills\n"
               "/// in beyond it. M, L: {0}x{0}, row-major (L unit lower triangular, only those entries\n"
               "/// written); D: {0}.\n", n) +
           fmt::format(fmt::runtime(functions), n, ldlt.factor, "L^T D L", ldlt.solve, solve_rows_functions(ldlt, n));
  }
  LdltCode ldlt = ldlt_code(n);
  return fmt::format("/// M = L D L^T for the symmetric positive definite {0}x{0} mass matrix{1}.\n"
                     "/// M, L: {0}x{0}, row-major (L unit lower triangular, only below the diagonal written); D: {0}.\n",
                     n, ldlt.unrolled ? ", unrolled" : "") +
         fmt::format(fmt::runtime(functions), n, ldlt.factor, "L D L^T", ldlt.solve, solve_rows_functions(ldlt, n));
}

std::vector<std::size_t> factor_entries(const Equations& e, std::size_t n) {
  std::vector<int> tree = tree_of_mass_matrix(e, n);
  std::vector<std::size_t> entries;
  for (std::size_t i = 0; i < n; ++i) {
    std::vector<std::size_t> columns;  // of row i: every j < i, or the coordinates above i in the tree
    if (tree.empty())
      for (std::size_t j = 0; j < i; ++j) columns.push_back(j);
    else
      for (int j = tree[i]; j >= 0; j = tree[std::size_t(j)]) columns.push_back(std::size_t(j));
    std::sort(columns.begin(), columns.end());
    for (std::size_t j : columns) entries.push_back(i * n + j);
  }
  return entries;
}

}  // namespace eomgen
