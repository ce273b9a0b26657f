// The generated factorization and solves of the mass matrix (emit/cpp_ldlt): dense and unrolled,
// dense in loops, and a tree's from the leaves, each compiled and run on a random symmetric
// positive definite M of its shape (the tree's also with zeros on its chains that fill in);
// ldlt_solve and ldlt_solve_rows must solve M x = b to rounding, and ldlt_solve_rows<m, true>
// give exactly −x (jacobian_state's rows are ∂τ/∂x, solved negated).
#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "emit/cpp_ldlt.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

std::string functions(const std::string& name, const LdltCode& code, std::size_t n) {
  return fmt::format(
      "namespace {0} {{\n"
      "template <class T>\ninline void ldlt_factor(const T* M, T* L, T* D) {{\n  (void)L;\n{1}}}\n"
      "template <class T>\ninline void ldlt_solve(const T* L, const T* D, T* b) {{\n  (void)L;\n{2}}}\n"
      "{3}"
      "}}\n",
      name, code.factor, code.solve, solve_rows_functions(code, n));
}

// M random, symmetric and diagonally dominant (so positive definite), zero where `related` says (a
// tree's M is zero between coordinates on different branches). Both solves against M X = B, 7 columns.
const char* check = R"cpp(
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>
template <class Related, class Factor, class Solve, class SolveRows, class NegatedRows>
int check(const char* name, int n, Related related, Factor factor, Solve solve, SolveRows solve_rows,
          NegatedRows negated_rows) {
  constexpr int m = 7;
  std::mt19937 g(3);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<double> M(n * n, 0.0), L(n * n, 0.0), D(n), B(n * m), X, column(n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j <= i; ++j)
      if (related(i, j)) M[i * n + j] = M[j * n + i] = i == j ? n + 1.0 + u(g) : u(g);
  for (double& b : B) b = u(g);
  X = B;
  factor(M.data(), L.data(), D.data());
  solve_rows(L.data(), D.data(), X.data());
  std::vector<double> Y = B;
  negated_rows(L.data(), D.data(), Y.data());
  int unequal = 0;
  for (std::size_t k = 0; k < Y.size(); ++k) unequal += Y[k] != -X[k];
  double worst = 0, worst_columns = 0;
  for (int c = 0; c < m; ++c) {
    for (int i = 0; i < n; ++i) column[i] = B[i * m + c];
    solve(L.data(), D.data(), column.data());
    for (int i = 0; i < n; ++i) {
      double r = -B[i * m + c], rc = -B[i * m + c];
      for (int k = 0; k < n; ++k) r += M[i * n + k] * X[k * m + c], rc += M[i * n + k] * column[k];
      worst = std::fmax(worst, std::fabs(r));
      worst_columns = std::fmax(worst_columns, std::fabs(rc));
    }
  }
  std::printf("%s: |M X - B| %.3g by rows, %.3g by columns; %d negated entries not -X\n", name, worst, worst_columns, unequal);
  return worst < 1e-13 && worst_columns < 1e-13 && unequal == 0 ? 0 : 1;
}
int main() {
  const int parent[] = {PARENTS};
  auto in_tree = [&](int i, int j) {
    for (int k = i; k >= 0; k = parent[k]) if (k == j) return true;
    for (int k = j; k >= 0; k = parent[k]) if (k == i) return true;
    return false;
  };
  auto dense = [](int, int) { return true; };
  int failures = 0;
  failures += check("unrolled", 5, dense, unrolled::ldlt_factor<double>, unrolled::ldlt_solve<double>, unrolled::ldlt_solve_rows<7, false, double>,
                    unrolled::ldlt_solve_rows<7, true, double>);
  failures += check("loops", 30, dense, loops::ldlt_factor<double>, loops::ldlt_solve<double>, loops::ldlt_solve_rows<7, false, double>,
                    loops::ldlt_solve_rows<7, true, double>);
  failures += check("tree", TREE_SIZE, in_tree, tree::ldlt_factor<double>, tree::ldlt_solve<double>, tree::ldlt_solve_rows<7, false, double>,
                    tree::ldlt_solve_rows<7, true, double>);
  // zeros on the chains, which the factorization from the leaves fills in (the parents that
  // joints following another's coordinate or a numbering not parents first give)
  auto filled_in = [&](int i, int j) {
    const int zero[][2] = {{1, 0}, {2, 0}, {4, 2}, {7, 3}, {10, 5}, {12, 0}};
    for (const auto& z : zero)
      if ((i == z[0] && j == z[1]) || (i == z[1] && j == z[0])) return false;
    return in_tree(i, j);
  };
  failures += check("tree, filled in", TREE_SIZE, filled_in, tree::ldlt_factor<double>, tree::ldlt_solve<double>,
                    tree::ldlt_solve_rows<7, false, double>, tree::ldlt_solve_rows<7, true, double>);
  return failures;
}
)cpp";

TEST(MassMatrixFactorization, BothSolvesSolveDenseAndTreeMatrices) {
  // a floating base's six velocities in a chain, two legs of three hinges and an arm of two
  std::vector<int> parent = {-1, 0, 1, 2, 3, 4, 5, 6, 7, 5, 9, 10, 5, 12};
  std::string parents;
  for (int p : parent) parents += fmt::format("{}{}", parents.empty() ? "" : ", ", p);
  std::string dir = temporary_directory();
  {
    std::ofstream out(dir + "/check.cpp");
    out << "#include <cstddef>\n#define PARENTS " << parents << "\n#define TREE_SIZE " << parent.size() << "\n"
        << functions("unrolled", ldlt_code(5), 5) << functions("loops", ldlt_code(30), 30)
        << functions("tree", tree_ldlt_code(parent), parent.size()) << check;
  }
  EXPECT_EQ(run_command("cd '" + dir + "' && c++ -std=c++17 -O1 -Wall -Wextra -Werror check.cpp -o check && ./check"), 0);
  EXPECT_FALSE(ldlt_code(30).unrolled) << "the loops are checked";
  EXPECT_TRUE(ldlt_code(5).unrolled);
}

}  // namespace
}  // namespace eomgen::test
