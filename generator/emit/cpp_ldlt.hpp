/// @file The generated header's L D Lᵀ factorization of the mass matrix and its solve, as the
/// statements of two functions: unrolled for small matrices, loops for large ones.
#pragma once

#include <cstddef>
#include <string>

namespace eomgen {

struct LdltCode {
  std::string factor;  // body of ldlt_factor(const T* M, T* L, T* D)
  std::string solve;   // body of ldlt_solve(const T* L, const T* D, T* b)
  bool unrolled = true;
};

/// D_j = M_jj − Σ_{k<j} L_jk² D_k,  L_ij = (M_ij − Σ_{k<j} L_ik L_jk D_k) / D_j, then L D Lᵀ x = b
/// forward, scaled and backward, for an n×n row-major M.
LdltCode ldlt_code(std::size_t n);

}  // namespace eomgen
