/// @file The large straight-line gradients compiled by g++ with IRA's priority colouring.
///
/// Why: in a function of thousands of statements most values are spilled, and g++'s default
/// register allocator (Chow's priority colouring is the other; the default is Chaitin–Briggs)
/// then spends a third of the whole compile assigning stack slots. The seven-joint arm's rhs and
/// jacobian_state compiled at -O2 in 3.9 s on average against 3.4 s with priority colouring (six
/// alternating compiles each; "LRA hard reg assignment" 1.7 s against 0.8 s by -ftime-report), and
/// its jacobian_state ran at the same speed (1,024-1,049 ns against 1,029-1,046 over four
/// alternations on one core; 6 ball joints' 6.35-6.70 µs against 6.40-6.61 µs). The option changes
/// which register holds a value, never an operation: the results are the same to the last bit
/// (tested). Clang has no such option and takes the text without the pragma.
#pragma once

#include <string>

namespace eomgen {

/// `functions` between `#pragma GCC push_options` / `optimize("ira-algorithm=priority")` and
/// `pop_options`, seen by g++ only (not by clang++, which also defines __GNUC__): the options of
/// the command line (-O level, -ffast-math, -march) stay as they are.
std::string with_priority_register_allocation(const std::string& functions);

}  // namespace eomgen
