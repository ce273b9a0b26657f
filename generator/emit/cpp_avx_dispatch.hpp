/// @file A large straight-line function of the header, and the solve with M's factors for many
/// columns, compiled a second time for AVX, for double on x86-64, and chosen at run time where the
/// processor has AVX.
///
/// Why: a user's program compiled with the compiler's defaults (-O2, no -march) gets SSE2 code,
/// whose arithmetic overwrites one of its operands, so that about every seventh instruction is a
/// register copy and each takes about 7 bytes. The 7-joint arm's jacobian_state function is then
/// 71 KB of code, more than a first-level instruction cache of 32 or 64 KB, and it runs at the speed
/// its code arrives from the second level. AVX's VEX encoding of the same scalar operations takes
/// three operands: the same function is 57 KB, and ran 1.2-1.5 times as fast with a 32 KB cache
/// and 2.2 times with a 64 KB one (tests/benchmarks/rigid_body_trees.md). AVX has no fused
/// multiply-add, so both copies do the same operations in the same order and give the same
/// results to the last bit (tested). The price is compiling the function twice.
#pragma once

#include <cstddef>
#include <string>

namespace eomgen {

/// From this many operations (count_operations) on, a function's SSE2 code outgrows a 32 KB
/// instruction cache (about 12.6 bytes an operation in the arm's gradient).
constexpr long avx_dispatch_from_operations = 2500;

/// `function`, one `template <class T>` function as function() writes it, followed by, where
/// g++ or clang++ compile for x86-64 without AVX enabled (no -mavx, -march=native on a machine
/// with AVX defines __AVX__ and needs none) and EOMGEN_NO_AVX_DISPATCH is not defined, an AVX copy
/// of its double instance (NAME_avx) and the overload for double that calls it where the
/// processor has AVX, the double instance of the template where not.
std::string with_avx_dispatch(const std::string& function);

/// From this many coordinates on, M's solve for many columns gets an AVX copy (below it, the call
/// would cost more than the copy saves); in the copy, from 8 columns on.
constexpr std::size_t solve_rows_avx_from_coordinates = 4;

/// For ldlt_solve_rows<m, negated, T> (emit/cpp_ldlt), under the same condition: its AVX copy for
/// double and the overload for double, which partial ordering prefers to the template and which
/// takes the copy where the processor has AVX. The solve's column loops then run four lanes wide
/// (jacobian_state's 2n columns), with each column's operations unchanged.
std::string solve_rows_avx_dispatch();

}  // namespace eomgen
