/// @file A large straight-line function of the header, and the solve with M's factors for many
/// columns, compiled a second time for a wider instruction set, for double on x86-64, and chosen
/// at run time where the processor has it.
///
/// Why: a user's program compiled with the compiler's defaults (-O2, no -march) gets SSE2 code,
/// whose arithmetic overwrites one of its operands, so that about every seventh instruction is a
/// register copy and each takes about 7 bytes. The 7-joint arm's jacobian_state function is then
/// 71 KB of code, more than a first-level instruction cache of 32 or 64 KB, and it runs at the speed
/// its code arrives from the second level. AVX's VEX encoding of the same scalar operations takes
/// three operands: the same function is 57 KB, and ran 1.2-1.5 times as fast with a 32 KB cache
/// and 2.2 times with a 64 KB one (tests/benchmarks/rigid_body_trees.md).
///
/// The gradients' copy is for AVX2 with FMA (every x86-64 processor since 2013-2015), whose fused
/// multiply-adds the compiler forms by its default contraction: one rounding where there were two,
/// and the arm's jacobian_state a tenth faster again (2.9 rhs against 3.2,
/// tests/benchmarks/arm_jacobian_state.md). Its results therefore differ from the template's in
/// the last bits (within a few units of rounding of the largest result; tested), so that one program
/// gives one result on every processor with AVX2 and FMA and another on older ones;
/// -ffp-contract=off gives the template's bits again (tested), EOMGEN_NO_AVX_DISPATCH the template
/// everywhere. The solve's copy is for AVX alone, where the same operations in the same order give
/// the same results to the last bit (tested): its time is not in its arithmetic. The price is
/// compiling the function twice.
#pragma once

#include <cstddef>
#include <string>

namespace eomgen {

/// From this many operations (count_operations) on, a function's SSE2 code outgrows a 32 KB
/// instruction cache (about 12.6 bytes an operation in the arm's gradient).
constexpr long avx_dispatch_from_operations = 2500;

/// `function`, one `template <class T>` function as function() writes it, followed by, where
/// g++ or clang++ compile for x86-64 without AVX enabled (no -mavx, -march=native on a machine
/// with AVX defines __AVX__ and needs none) and EOMGEN_NO_AVX_DISPATCH is not defined, a copy
/// of its double instance for AVX2 and FMA (NAME_fma) and the overload for double that calls it
/// where the processor has both, the double instance of the template where not.
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
