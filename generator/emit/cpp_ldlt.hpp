/// @file The generated header's factorization of the mass matrix and its solve, detail::ldlt_factor
/// and detail::ldlt_solve: L D Lᵀ, unrolled for small matrices and loops for large ones, or, for a
/// tree's M, Lᵀ D L from the leaves without fill-in.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "derive/equations.hpp"

namespace eomgen {

struct LdltCode {
  std::string factor;  // body of ldlt_factor(const T* M, T* L, T* D)
  std::string solve;   // body of ldlt_solve(const T* L, const T* D, T* b)
  // body of ldlt_solve_rows<m, negated>(const T* L, const T* D, T* B): the same row operations on
  // the m columns of B at once, each by each_column
  std::string solve_rows;
  bool unrolled = true;
};

/// D_j = M_jj − Σ_{k<j} L_jk² D_k,  L_ij = (M_ij − Σ_{k<j} L_ik L_jk D_k) / D_j, then L D Lᵀ x = b
/// forward, scaled and backward, for an n×n row-major M.
LdltCode ldlt_code(std::size_t n);

/// For the M of a tree (Featherstone's LTDL, RBDA §6.5): with parent[i] < i the coordinate above
/// i (−1 at a root) and M_ij = 0 unless one of i, j is above the other, M = Lᵀ D L factored from
/// the leaves: L_ij ≠ 0 only for j above i, O(n·depth) operations where the dense factor takes
/// n³/6. Eliminating k changes only entries between coordinates above k, so whatever fills in
/// stays on the chains (zeros of M there are allowed). The same functions: ldlt_factor writes L
/// and D, ldlt_solve solves Lᵀ D L x = b (from the leaves up, scaled, then down).
LdltCode tree_ldlt_code(const std::vector<int>& parent);

/// each_column (a row's pass over B's m columns, as two loops: m / 4 * 4 of them and the rest) and
/// ldlt_solve_rows with `code`'s solve_rows, documented, for an n×n M; from
/// solve_rows_avx_from_coordinates on also its AVX copy (emit/cpp_avx_dispatch).
std::string solve_rows_functions(const LdltCode& code, std::size_t n);

/// The two functions, documented, for the n×n M of `e`: the tree's factorization when
/// e.coordinate_parents gives one and M's zeros are still those of the tree (no transformation has
/// filled them in), L D Lᵀ otherwise.
std::string mass_matrix_factorization(const Equations& e, std::size_t n);

/// The entries of L (row-major indices into n×n) that mass_matrix_factorization's ldlt_factor
/// writes for `e`, in increasing order: those of the tree's chains, or all below the diagonal.
std::vector<std::size_t> factor_entries(const Equations& e, std::size_t n);

}  // namespace eomgen
